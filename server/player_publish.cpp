// Publishing the players' records: statistics from the store with the rating beside them.
#include "server/player_publish.h"

#include <algorithm>
#include <cmath>

#include "server/store/rating_book.h"
#include "server/store/stat_book.h"

namespace pool::server {

std::string PlayerPublisher::publish(store::MatchStore& store, protocol::PlayerStats stats) {
  const rating::Rating r = store::ratingOf(store.database(), stats.key, stats.game);
  stats.server = server_;
  stats.rating = static_cast<int>(std::lround(r.rating));
  stats.rating_deviation = static_cast<int>(std::lround(r.deviation));
  const std::pair<std::vector<std::uint8_t>, int> id{stats.key, rules::gameNumber(stats.game)};
  std::erase(order_, id);
  order_.push_back(id);
  if (order_.size() > kMaxPublishedPlayers) {
    protocol::PlayerStats gone;
    gone.server = server_;
    gone.key = order_.front().first;
    gone.game = rules::gameOfNumber(order_.front().second).value_or(rules::Game::EightBall);
    transport_.withdraw(gone);
    order_.pop_front();
  }
  return transport_.publish(stats);
}

std::vector<std::string> PlayerPublisher::publishSeats(store::MatchStore& store,
                                                       const Match& match) {
  std::vector<std::string> errors;
  const auto& seats = match.seats();
  // Only a counted match changes records (stat_book.h's countsForStats): two different keys.
  if (match.practice() || seats[0].public_key.empty() || seats[1].public_key.empty() ||
      seats[0].public_key == seats[1].public_key) {
    return errors;
  }
  for (const Seat& seat : seats) {
    auto stats = store::statsOf(store.database(), seat.public_key, match.settings().game);
    if (!stats) continue;
    if (auto error = publish(store, std::move(*stats)); !error.empty()) errors.push_back(error);
  }
  return errors;
}

std::vector<std::string> PlayerPublisher::publishRecent(store::MatchStore& store,
                                                        std::size_t limit) {
  std::vector<std::string> errors;
  auto recent = store::recentStats(store.database(), std::min(limit, kMaxPublishedPlayers));
  // Oldest first, so the most recent are the last withdrawn.
  std::reverse(recent.begin(), recent.end());
  for (auto& stats : recent) {
    if (auto error = publish(store, std::move(stats)); !error.empty()) errors.push_back(error);
  }
  return errors;
}

}  // namespace pool::server
