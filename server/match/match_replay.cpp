// Replaying: seats, rematches between racks, the stored commands re-addressed to the replay match.
#include "server/match/match_replay.h"

#include "protocol/command_signature.h"

#include "server/match/shot_runner.h"

namespace pool::server {

namespace {

/// The same table, ball for ball, bit for bit.
bool sameBalls(const std::vector<physics::Ball>& a, const std::vector<physics::Ball>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].id != b[i].id || a[i].pos != b[i].pos || a[i].state != b[i].state) return false;
  }
  return true;
}

bool sameEvents(const physics::EventLog& a, const physics::EventLog& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].t != b[i].t || a[i].type != b[i].type || a[i].ball_a != b[i].ball_a ||
        a[i].ball_b != b[i].ball_b || a[i].where != b[i].where || a[i].pos != b[i].pos) {
      return false;
    }
  }
  return true;
}

}  // namespace

MatchReplay::MatchReplay(const MatchSnapshot& stored, std::vector<ShotRecord> commands,
                         Match& target, std::array<std::uint64_t, 2> tokens, double pause)
    : commands_(std::move(commands)),
      target_(target),
      tokens_(tokens),
      keys_{protocol::generateKeyPair(), protocol::generateKeyPair()},
      pause_(pause) {
  // The replay's clock does not run: stored expiries are replayed where they happened.
  protocol::MatchSettings settings = stored.settings;
  settings.shot_clock = 0.0;
  for (int s = 0; s < 2; ++s) {
    const auto i = static_cast<std::size_t>(s);
    std::string player = stored.seats[i].player;
    if (player.empty()) player = "seat " + std::to_string(s);
    target_.takeSeat(s, player, "replay-" + std::to_string(s), tokens_[i], keys_[i].publicKey(),
                     settings);
  }
}

protocol::SeatRequest MatchReplay::signedRematch(int seat) {
  const auto i = static_cast<std::size_t>(seat);
  protocol::SeatRequest r;
  r.client = "replay-" + std::to_string(seat);
  r.match = target_.id();
  r.action = protocol::JoinAction::Rematch;
  r.seat = seat;
  r.token = tokens_[i];
  r.seq = ++seqs_[i];
  protocol::signSeatRequest(r, keys_[i]);
  return r;
}

std::optional<CommandAnswer> MatchReplay::step(double now) {
  if (next_ >= commands_.size() || target_.inMotion()) {
    idle_since_.reset();
    return std::nullopt;
  }
  if (!idle_since_) idle_since_ = now;
  if (now - *idle_since_ < pause_) return std::nullopt;
  idle_since_.reset();
  // A stored match that went on to another rack: both players asked for it.
  if (target_.phase() == MatchPhase::Over) {
    for (int s = 0; s < 2; ++s) target_.seatRequest(signedRematch(s));
  }
  const ShotRecord& stored = commands_[next_++];
  // A shot clock expiry (no player's command): the clock runs out again at the same point.
  if (!stored.shoots && stored.command.seq == 0) {
    auto expired = target_.runOutClock();
    if (!expired || !expired->accepted()) {
      differences_.push_back("command " + std::to_string(next_) + ": the clock expiry after shot " +
                             std::to_string(stored.shot_number) + " cannot be replayed");
      return expired;
    }
    ++replayed_;
    return expired;
  }
  protocol::ShotRequest command = stored.command;
  command.match = target_.id();
  command.seat_token = tokens_[static_cast<std::size_t>(command.seat)];
  // The replay's own numbering: stored numbers may not leave room for its rematch requests.
  command.seq = ++seqs_[static_cast<std::size_t>(command.seat)];
  protocol::signCommand(command, keys_[static_cast<std::size_t>(command.seat)]);
  CommandAnswer answer = target_.handleShot(command, now);
  check(stored, answer);
  return answer;
}

void MatchReplay::check(const ShotRecord& stored, const CommandAnswer& answer) {
  const std::string which =
      "command " + std::to_string(next_) + " (shot " + std::to_string(stored.shot_number) + ")";
  if (!answer.accepted() || !answer.record) {
    differences_.push_back(which + " refused: " + answer.rejection.text);
    return;
  }
  ++replayed_;
  if (!sameBalls(answer.record->before, stored.before)) {
    differences_.push_back(which + ": another table at the strike");
  } else if (!sameEvents(answer.record->events, stored.events)) {
    differences_.push_back(which + ": the physics told another story (" +
                           std::to_string(answer.record->events.size()) + " events, stored " +
                           std::to_string(stored.events.size()) + ")");
  }
}

}  // namespace pool::server
