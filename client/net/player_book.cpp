// A bounded book of the players' records a client received.
#include "client/net/player_book.h"

#include <algorithm>

namespace pool::client {

void PlayerBook::update(protocol::PlayerStats stats) {
  Key key{stats.server, stats.key, rules::gameNumber(stats.game)};
  records_[key] = Kept{std::move(stats), ++received_};
  if (records_.size() <= kMaxPlayerRecords) return;
  const auto oldest = std::min_element(records_.begin(), records_.end(), [](auto& a, auto& b) {
    return a.second.order < b.second.order;
  });
  records_.erase(oldest);
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
