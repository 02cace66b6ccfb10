// The gateway's lobby with its bounds per server id and in total, largest first.
#include "client/web/bounded_lobby.h"

#include <algorithm>
#include <tuple>
#include <utility>

#include "client/net/lobby.h"
#include "client/web/web_json.h"

namespace pool::web {

bool BoundedLobby::MatchLess::operator()(const std::string& a, const std::string& b) const {
  return client::matchOrder(a, b);
}

bool BoundedLobby::update(const client::LobbyEntry& entry) {
  const auto it = entries_.find(entry.match);
  if (it != entries_.end() && it->second.entry.server == entry.server) {
    it->second = Kept{entry, lobbyEntryJson(entry)};
    return true;
  }
  if (it != entries_.end()) remove(entry.match);  // the same match under another server id
  const auto server = servers_.find(entry.server);
  const std::size_t held = server == servers_.end() ? 0 : server->second.matches.size();
  if (held >= limits_.per_server) {
    ++refused_;
    return false;
  }
  if (entries_.size() >= limits_.kept) {
    const auto most = heaviest();
    if (most == servers_.end() || most->second.matches.size() < held + 2) {
      ++refused_;
      return false;
    }
    remove(*most->second.matches.rbegin());
  }
  add(entry);
  return true;
}

void BoundedLobby::add(const client::LobbyEntry& entry) {
  auto [server, fresh] = servers_.try_emplace(entry.server);
  if (fresh) server->second.seen = next_seen_++;
  server->second.matches.insert(entry.match);
  entries_[entry.match] = Kept{entry, lobbyEntryJson(entry)};
}

void BoundedLobby::remove(const std::string& match) {
  const auto it = entries_.find(match);
  if (it == entries_.end()) return;
  const auto server = servers_.find(it->second.entry.server);
  if (server != servers_.end()) {
    server->second.matches.erase(match);
    if (server->second.matches.empty()) servers_.erase(server);
  }
  entries_.erase(it);
}

const client::LobbyEntry* BoundedLobby::find(const std::string& match) const {
  const auto it = entries_.find(match);
  return it == entries_.end() ? nullptr : &it->second.entry;
}

std::map<std::string, BoundedLobby::Server>::iterator BoundedLobby::heaviest() {
  auto most = servers_.end();
  for (auto it = servers_.begin(); it != servers_.end(); ++it) {
    if (most == servers_.end() ||
        std::make_pair(it->second.matches.size(), it->second.seen) >
            std::make_pair(most->second.matches.size(), most->second.seen)) {
      most = it;
    }
  }
  return most;
}

std::string BoundedLobby::message() const {
  // How many entries each server id keeps in the message: its lowest-numbered ones.
  struct Share {
    const Server* server;
    std::vector<const Kept*> kept;  ///< lowest-numbered first
  };
  std::map<std::string, Share> shares;
  std::size_t count = 0;
  std::size_t bytes = lobbyJson({}).size();
  for (const auto& [id, server] : servers_) {
    Share& share = shares[id];
    share.server = &server;
    for (const std::string& match : server.matches) {
      const Kept& kept = entries_.at(match);
      share.kept.push_back(&kept);
      bytes += kept.json.size() + 1;
      ++count;
    }
  }
  // Largest first: (entries kept, seen) ordered, the last one gives up its highest-numbered.
  std::set<std::tuple<std::size_t, std::uint64_t, std::string>> order;
  for (const auto& [id, share] : shares) order.emplace(share.kept.size(), share.server->seen, id);
  while ((count > limits_.served || bytes > limits_.served_bytes) && !order.empty()) {
    const auto largest = std::prev(order.end());
    const std::string id = std::get<2>(*largest);
    order.erase(largest);
    Share& share = shares.at(id);
    bytes -= share.kept.back()->json.size() + 1;
    --count;
    share.kept.pop_back();
    if (!share.kept.empty()) order.emplace(share.kept.size(), share.server->seen, id);
  }
  std::vector<const Kept*> served;
  for (const auto& [id, share] : shares)
    served.insert(served.end(), share.kept.begin(), share.kept.end());
  std::sort(served.begin(), served.end(), [](const Kept* a, const Kept* b) {
    return client::matchOrder(a->entry.match, b->entry.match);
  });
  std::vector<const std::string*> texts;
  texts.reserve(served.size());
  for (const Kept* kept : served) texts.push_back(&kept->json);
  return lobbyJson(texts);
}

}  // namespace pool::web
