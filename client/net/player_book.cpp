// A bounded book of the players' records a client received.
#include "client/net/player_book.h"

#include <algorithm>

namespace pool::client {

void PlayerBook::update(protocol::PlayerStats stats) {
  const std::string server = stats.server;
  Key key{server, stats.key, rules::gameNumber(stats.game)};
  records_[key] = Kept{std::move(stats), ++received_};
  const auto older = [](auto& a, auto& b) { return a.second.order < b.second.order; };
  // The oldest of this server's records past its share; the oldest of all past the whole.
  const auto first = records_.lower_bound(Key{server, {}, 0});
  auto last = first;
  std::size_t of_server = 0;
  while (last != records_.end() && std::get<0>(last->first) == server) {
    ++last;
    ++of_server;
  }
  if (of_server > kMaxPlayerRecordsPerServer) {
    records_.erase(std::min_element(first, last, older));
  } else if (records_.size() > kMaxPlayerRecords) {
    records_.erase(std::min_element(records_.begin(), records_.end(), older));
  }
}

std::vector<const protocol::PlayerStats*> PlayerBook::fairShare(std::size_t limit) const {
  std::map<std::string, std::vector<const protocol::PlayerStats*>> by_server;
  for (const auto* s : records()) by_server[s->server].push_back(s);
  std::vector<const protocol::PlayerStats*> out;
  for (std::size_t round = 0; out.size() < limit; ++round) {
    bool any = false;
    for (const auto& [server, list] : by_server) {
      if (round >= list.size() || out.size() >= limit) continue;
      out.push_back(list[round]);
      any = true;
    }
    if (!any) break;
  }
  return out;
}

std::vector<const protocol::PlayerStats*> PlayerBook::records() const {
  std::vector<const protocol::PlayerStats*> out;
  for (const auto& [key, kept] : records_) out.push_back(&kept.stats);
  std::sort(out.begin(), out.end(), [](const auto* a, const auto* b) {
    if (a->rating != b->rating) return a->rating > b->rating;
    return a->name < b->name;
  });
  return out;
}

std::vector<const protocol::PlayerStats*> PlayerBook::named(const std::string& name) const {
  std::vector<const protocol::PlayerStats*> out;
  for (const auto* s : records()) {
    if (s->name == name) out.push_back(s);
  }
  return out;
}

}  // namespace pool::client
