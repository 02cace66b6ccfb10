// A practice table's own commands: lay out, re-rack or clear, undo, play the last shot again,
// change the coefficients; each checked like a shot command and refused with nothing changed.
#include <algorithm>
#include <string>

#include "rules/practice.h"
#include "server/match/command_check.h"
#include "server/match/match.h"

namespace pool::server {

namespace {

Rejection refuse(Reject reason, std::string text) {
  return {reason, std::move(text)};
}

void sortById(std::vector<physics::Ball>& balls) {
  std::sort(balls.begin(), balls.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
}

// Whether games `a` and `b` are played on the same table (the pool games share the server's).
bool sameTable(rules::Game a, rules::Game b) {
  return rules::tableOf(a, {}) == rules::tableOf(b, {});
}

// What a practice table of `game` racks, e.g. "this is a pool table; it racks 8, 9, 10 or 0
// (clear)", "this is a snooker table; it racks 22 (snooker) or 0 (clear)".
std::string racksAt(rules::Game game) {
  std::string numbers;
  int count = 0;
  for (const rules::GameInfo& g : rules::allGames()) {
    if (!sameTable(g.game, game)) continue;
    numbers += (numbers.empty() ? "" : ", ") + std::to_string(g.number);
    ++count;
  }
  if (count == 1) numbers += std::string(" (") + rules::toString(game) + ")";
  const std::string table = rules::isPool(game) ? "pool" : rules::toString(game);
  return "this is a " + table + " table; it racks " + numbers + " or 0 (clear)";
}

}  // namespace

void Match::startPractice() {
  game_ = rules::practiceState();
  balls_ = layout(layouts_++, settings_.game);
  rack_ = 1;
  started_ = true;
  last_verdict_ = "practice: " + std::string(rules::toString(settings_.game)) + " rack";
  touch();
}

void Match::rememberStep(std::optional<protocol::ShotRequest> command,
                         std::optional<ShotPlan> plan) {
  history_.push_back(PracticeStep{balls_, game_, std::move(command), std::move(plan)});
  if (history_.size() > protocol::kPracticeUndoDepth) history_.erase(history_.begin());
}

CommandAnswer Match::handlePractice(const protocol::PracticeRequest& command, double now) {
  CommandAnswer answer;
  answer.seat = command.seat;
  answer.seq = command.seq;
  answer.shot_number = shot_number_;
  auto found = checkHolder(
      *this, {command.seat, command.seat_token, command.seq, !command.signature.empty()},
      [&](const Seat& seat) {
        return protocol::verifyPractice(command, seat.public_key) ==
               protocol::SignatureCheck::Valid;
      });
  if (!found) {
    answer.rejection = {found.code(), found.error()};
    return answer;
  }
  // The seat's own command: its number is used up from here on, whatever follows.
  seats_[static_cast<std::size_t>(command.seat)].last_seq = command.seq;
  if (closed_) {
    answer.rejection = refuse(Reject::MatchOver, "the match is closed");
    return answer;
  }
  if (!practice()) {
    answer.rejection = refuse(Reject::NotPractice, "this is not a practice table");
    return answer;
  }
  if (flight_) {
    answer.rejection =
        refuse(Reject::BallsMoving, "shot " + std::to_string(shotInMotion()) + " is still moving");
    return answer;
  }
  if (command.action == protocol::PracticeAction::Again) {
    if (history_.empty() || !history_.back().command) {
      answer.rejection = refuse(Reject::BadPractice, "again: the last change was not a shot");
      return answer;
    }
    PracticeStep last = std::move(history_.back());
    history_.pop_back();
    balls_ = last.balls;
    game_ = last.game;
    protocol::ShotRequest again = *last.command;
    again.seat = command.seat;
    again.seat_token = command.seat_token;
    again.seq = command.seq;
    again.signature.clear();
    touch();
    answer = runPlan(again, *last.plan, now);
    if (!answer.accepted()) {
      // Not expected (the same shot ran before): the table stays as it was before that shot.
      history_.push_back(std::move(last));
    }
    answer.record.reset();  // practice shots are not stored
    return answer;
  }
  Rejection change = practiceChange(command);
  if (!change.accepted()) {
    answer.rejection = std::move(change);
    return answer;
  }
  touch();
  rules::Verdict verdict;
  verdict.turn_continues = true;
  verdict.next = game_;
  verdict.next_shooter = command.seat;
  verdict.ball_in_hand = game_.ball_in_hand;
  answer.done = ShotReport{command.seat, command.seq, shot_number_, {}, verdict, last_verdict_};
  return answer;
}

Rejection Match::practiceChange(const protocol::PracticeRequest& command) {
  const auto& context = table().context;
  switch (command.action) {
    case protocol::PracticeAction::Layout: {
      const bool has_cue = std::any_of(command.balls.begin(), command.balls.end(),
                                       [](const auto& b) { return b.id == physics::kCueBall; });
      if (!has_cue) return refuse(Reject::BadPractice, "layout: the cue ball must be on the table");
      std::vector<table::BallPlacement> moves;
      for (const auto& b : command.balls) moves.push_back({b.id, Eigen::Vector2d(b.x, b.y)});
      auto placed = rules::placeBalls({}, moves, context, settings_.game);
      if (!placed) return refuse(Reject::BadPractice, "layout: " + placed.error());
      rememberStep({}, {});
      balls_ = std::move(*placed);
      sortById(balls_);
      last_verdict_ = "practice: " + std::to_string(balls_.size()) + " balls laid out";
      break;
    }
    case protocol::PracticeAction::Rack: {
      const auto game = rules::gameOfNumber(command.rack);
      if (command.rack != 0 && !game) {
        return refuse(Reject::BadPractice, "rack: " + std::to_string(command.rack) +
                                               " is no game's number; " + racksAt(settings_.game));
      }
      // Only a game of this table: another game's rack would need another table.
      if (game && !sameTable(*game, settings_.game))
        return refuse(Reject::BadPractice, "rack: " + racksAt(settings_.game));
      rememberStep({}, {});
      balls_ = layout(layouts_++, game.value_or(settings_.game));
      if (game) {
        settings_.game = *game;
        last_verdict_ = "practice: " + std::string(rules::toString(*game)) + " rack";
      } else {
        std::erase_if(balls_, [](const auto& b) { return b.id != physics::kCueBall; });
        last_verdict_ = "practice: the table cleared";
      }
      break;
    }
    case protocol::PracticeAction::Undo: {
      if (history_.empty()) return refuse(Reject::BadPractice, "undo: nothing to undo");
      balls_ = history_.back().balls;
      game_ = history_.back().game;
      history_.pop_back();
      last_verdict_ = "practice: undone";
      break;
    }
    case protocol::PracticeAction::Physics: {
      auto params = protocol::withCoefficients(table().spec.params, command.coefficients);
      if (!params) return refuse(Reject::BadPractice, "physics: " + params.error());
      // This table's own kit and world; every other table keeps the server's.
      auto kit = std::make_shared<game::LoadedTable>(table());
      if (!standard_coefficients_)
        standard_coefficients_ = protocol::coefficientsOf(kit->spec.params);
      kit->spec.params = *params;
      runner_ = std::make_shared<ShotRunner>(std::move(kit));
      custom_physics_ = command.coefficients != *standard_coefficients_;
      last_verdict_ = custom_physics_ ? "practice: coefficients changed (not a standard table)"
                                      : "practice: the standard coefficients";
      break;
    }
    case protocol::PracticeAction::Again:
      break;  // handled by handlePractice
  }
  game_.ball_in_hand = rules::BallInHand::Anywhere;
  return Rejection::none();
}

}  // namespace pool::server
