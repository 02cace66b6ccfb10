// Lobby bookkeeping within its bounds, and match selection.
#include "client/net/lobby.h"

#include <algorithm>
#include <charconv>
#include <utility>

namespace pool::client {
namespace {

unsigned long long localNumber(const std::string& id) {
  const auto dash = id.rfind('-');
  const std::size_t from = dash == std::string::npos ? id.size() : dash + 1;
  unsigned long long n = 0;
  const auto [ptr, ec] = std::from_chars(id.data() + from, id.data() + id.size(), n);
  return ec == std::errc() && ptr == id.data() + id.size() ? n : 0;
}

}  // namespace

bool matchOrder(const std::string& a, const std::string& b) {
  const auto na = localNumber(a), nb = localNumber(b);
  return na != nb ? na < nb : a < b;
}

LobbyUpdate Lobby::update(LobbyEntry entry) {
  const auto it = entries_.find(entry.match);
  if (it != entries_.end() && it->second.server == entry.server) {
    it->second = std::move(entry);
    return {true, {}};
  }
  if (it != entries_.end()) remove(entry.match);  // the same match under another server id
  const auto server = servers_.find(entry.server);
  const std::size_t held = server == servers_.end() ? 0 : server->second.matches.size();
  if (held >= bounds_.per_server) {
    ++refused_;
    return {};
  }
  LobbyUpdate done{true, {}};
  if (entries_.size() >= bounds_.kept) {
    const auto most = heaviest();
    if (most == servers_.end() || most->second.matches.size() < held + 2) {
      ++refused_;
      return {};
    }
    done.gave_way = *most->second.matches.rbegin();
    remove(done.gave_way);
  }
  auto [kept, fresh] = servers_.try_emplace(entry.server);
  if (fresh) kept->second.seen = next_seen_++;
  kept->second.matches.insert(entry.match);
  std::string key = entry.match;
  entries_[key] = std::move(entry);
  return done;
}

void Lobby::remove(const std::string& match) {
  const auto it = entries_.find(match);
  if (it == entries_.end()) return;
  const auto server = servers_.find(it->second.server);
  if (server != servers_.end()) {
    server->second.matches.erase(match);
    if (server->second.matches.empty()) servers_.erase(server);
  }
  entries_.erase(it);
}

const LobbyEntry* Lobby::find(const std::string& match) const {
  const auto it = entries_.find(match);
  return it == entries_.end() ? nullptr : &it->second;
}

std::vector<const LobbyEntry*> Lobby::entries() const {
  std::vector<const LobbyEntry*> out;
  for (const auto& [id, entry] : entries_) out.push_back(&entry);
  std::sort(out.begin(), out.end(), [](const LobbyEntry* a, const LobbyEntry* b) {
    return matchOrder(a->match, b->match);
  });
  return out;
}

std::optional<std::string> Lobby::lowestWithFreeSeat() const {
  for (const LobbyEntry* e : entries()) {
    const bool open = e->phase != MatchPhase::Over && e->phase != MatchPhase::Closed;
    if (open && e->seats_taken < 2) return e->match;
  }
  return std::nullopt;
}

std::map<std::string, Lobby::Server>::iterator Lobby::heaviest() {
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

std::optional<std::string> Lobby::firstInPlay() const {
  for (const LobbyEntry* e : entries()) {
    if (inPlay(e->phase)) return e->match;
  }
  return std::nullopt;
}

}  // namespace pool::client
