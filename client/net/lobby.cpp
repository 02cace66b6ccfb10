// Lobby bookkeeping and match selection.
#include "client/net/lobby.h"

#include <algorithm>
#include <charconv>

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

void Lobby::update(LobbyEntry entry) {
  std::string key = entry.match;
  entries_[key] = std::move(entry);
}

void Lobby::remove(const std::string& match) {
  entries_.erase(match);
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

std::optional<std::string> Lobby::firstInPlay() const {
  for (const LobbyEntry* e : entries()) {
    if (inPlay(e->phase)) return e->match;
  }
  return std::nullopt;
}

}  // namespace pool::client
