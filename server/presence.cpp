// Presence: each answered client tied to the writer of its requests, bounded per writer.
#include "server/presence.h"

#include <algorithm>
#include <unordered_set>

namespace pool::server {

std::vector<Presence::Gone> Presence::answered(const std::string& client, std::uint64_t writer,
                                               const std::string& sender, bool seated) {
  auto [it, added] = clients_.try_emplace(client);
  Client& c = it->second;
  // A stranger writing under a seated client's id moves nothing: her presence is her seat's writer.
  if (!added && c.tied && c.writer != writer && !seated) return {};
  if (added || c.writer != writer) {
    if (!added) {
      if (auto old = writers_.find(c.writer); old != writers_.end()) --old->second.count;
    }
    c.writer = writer;
    Writer& w = writers_[writer];
    w.order.push_back(client);
    ++w.count;
    fresh_ = true;
    if (w.order.size() > 4 * kClientsPerWriter) compact(writer, w);
  }
  c.sender = sender;
  if (seated) c.tied = true;
  return trim(writer);
}

std::vector<Presence::Gone> Presence::trim(std::uint64_t writer) {
  std::vector<Gone> out;
  Writer& w = writers_[writer];
  for (auto i = w.order.begin(); w.count > kClientsPerWriter && i != w.order.end();) {
    const auto c = clients_.find(*i);
    if (c == clients_.end() || c->second.writer != writer) {
      i = w.order.erase(i);  // moved on or let go already
    } else if (c->second.tied) {
      ++i;  // a seat's client stays
    } else {
      out.push_back(Gone{c->first, c->second.sender});
      clients_.erase(c);
      --w.count;
      i = w.order.erase(i);
    }
  }
  return out;
}

void Presence::compact(std::uint64_t writer, Writer& w) {
  std::unordered_set<std::string> seen;
  std::deque<std::string> kept;
  for (auto& id : w.order) {
    const auto c = clients_.find(id);
    if (c != clients_.end() && c->second.writer == writer && seen.insert(id).second) {
      kept.push_back(std::move(id));
    }
  }
  w.order = std::move(kept);
}

void Presence::untieUnless(const std::function<bool(const std::string&)>& holds_seat) {
  for (auto& [id, c] : clients_) {
    if (c.tied && !holds_seat(id)) c.tied = false;
  }
}

std::vector<Presence::Gone> Presence::sweep(const std::vector<std::uint64_t>& alive) {
  fresh_ = false;
  std::vector<Gone> out;
  for (auto w = writers_.begin(); w != writers_.end();) {
    if (std::binary_search(alive.begin(), alive.end(), w->first)) {
      ++w;
      continue;
    }
    for (const auto& id : w->second.order) {
      const auto c = clients_.find(id);
      if (c == clients_.end() || c->second.writer != w->first) continue;
      out.push_back(Gone{c->first, c->second.sender});
      clients_.erase(c);
    }
    w = writers_.erase(w);
  }
  return out;
}

}  // namespace pool::server
