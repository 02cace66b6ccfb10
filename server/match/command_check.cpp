// The ordered checks of a shot command, each a small function that refuses or passes.
#include "server/match/command_check.h"

#include <algorithm>
#include <string>

#include "protocol/command_signature.h"
#include "rules/eight_ball.h"
#include "rules/placement.h"
#include "server/match/match.h"

namespace pool::server {

namespace {

using Check = RejectCheck;

Check refuse(Reject reason, std::string text) {
  return Check::refuse(reason, std::move(text));
}

std::string seatName(int seat) {
  return "seat " + std::to_string(seat);
}

Check checkValues(const Match& match, const protocol::ShotRequest& c) {
  if (!protocol::optionShoots(c.option)) return Check::pass();
  if (auto ok = physics::validateShot(c.cue, match.table().spec.params); !ok) {
    return refuse(Reject::Malformed, ok.error());
  }
  if (c.called_ball && (*c.called_ball < 1 || *c.called_ball > physics::kMaxBallId)) {
    return refuse(Reject::Malformed, "called_ball: must be 1-21");
  }
  return Check::pass();
}

Check checkTurn(const Match& match, const protocol::ShotRequest& c) {
  const MatchPhase phase = match.phase();
  if (phase == MatchPhase::Over || phase == MatchPhase::Closed) {
    return refuse(Reject::MatchOver, std::string("the match is ") + toString(phase));
  }
  if (phase == MatchPhase::Lobby) {
    return refuse(Reject::NotYourTurn, "the match has not started");
  }
  // At a practice table either seated player may shoot at any time.
  if (!match.practice() && match.game().shooter != c.seat) {
    return refuse(Reject::NotYourTurn, seatName(match.game().shooter) + " is to shoot");
  }
  if (match.inMotion()) {
    return refuse(Reject::BallsMoving,
                  "shot " + std::to_string(match.shotInMotion()) + " is still moving");
  }
  return Check::pass();
}

// Applies a pending choice to the plan's copies; refuses a missing or unoffered one.
Check checkOption(const Match& match, const protocol::ShotRequest& c, ShotPlan& plan) {
  const auto& offered = match.game().options;
  const auto choice = protocol::choiceOf(c.option);
  if (!choice) {
    if (offered.empty()) return Check::pass();
    return refuse(Reject::OptionRequired, "choose first: " + rules::describe(match.game()));
  }
  if (std::find(offered.begin(), offered.end(), *choice) == offered.end()) {
    return refuse(Reject::OptionNotOffered,
                  std::string("option ") + protocol::toString(c.option) + " is not offered");
  }
  auto verdict = rules::applyChoiceFor(match.rules(), match.game(), *choice, match.balls(),
                                       match.table().context);
  if (!verdict) return refuse(Reject::OptionNotOffered, verdict.error());
  plan.state = verdict->next;
  for (const auto& respot : verdict->respots) {
    for (auto& b : plan.before) {
      if (b.id != respot.id) continue;
      b = physics::Ball{};
      b.id = respot.id;
      b.pos = physics::Vec3(respot.pos.x(), respot.pos.y(), match.table().context.ball_radius);
    }
  }
  plan.shoots = protocol::optionShoots(c.option);
  plan.choice = std::move(*verdict);
  return Check::pass();
}

physics::Ball* cueBallOf(std::vector<physics::Ball>& balls) {
  auto it = std::find_if(balls.begin(), balls.end(),
                         [](const physics::Ball& b) { return b.id == physics::kCueBall; });
  return it == balls.end() ? nullptr : &*it;
}

// Places the cue ball in hand on the plan's table, or refuses the placement.
Check checkPlacement(const Match& match, const protocol::ShotRequest& c, ShotPlan& plan) {
  physics::Ball* cue = cueBallOf(plan.before);
  if (!cue) return refuse(Reject::IllegalPlacement, "no cue ball in this match");
  const rules::BallInHand in_hand = plan.state.ball_in_hand;
  const auto& table = match.table().context;
  if (!c.cue_ball_at) {
    if (in_hand == rules::BallInHand::None) return Check::pass();
    if (!physics::onTable(cue->state)) {
      return refuse(Reject::IllegalPlacement, "the cue ball is in hand: place it");
    }
  }
  const Eigen::Vector2d at = c.cue_ball_at.value_or(Eigen::Vector2d(cue->pos.head<2>()));
  const auto check = rules::checkCueBallPlacement(in_hand, at, plan.before, table);
  if (!check.ok()) return refuse(Reject::IllegalPlacement, "cue ball: " + check.error());
  *cue = physics::Ball{};
  cue->pos = physics::Vec3(at.x(), at.y(), table.ball_radius);
  return Check::pass();
}

Check checkCall(const Match& match, const protocol::ShotRequest& c, ShotPlan& plan) {
  plan.intent.ball = c.called_ball;
  plan.intent.pocket = c.called_pocket;
  plan.intent.safety = c.safety;
  auto ok = rules::checkIntentFor(match.rules(), plan.state, plan.intent, plan.before);
  if (!ok) return refuse(Reject::BadCall, ok.error());
  return Check::pass();
}

}  // namespace

RejectCheck checkHolder(const Match& match, const HolderFields& c,
                        const std::function<bool(const Seat&)>& signed_by) {
  if (c.seat != 0 && c.seat != 1) return refuse(Reject::WrongSeat, "seat: must be 0 or 1");
  const Seat& seat = match.seats()[static_cast<std::size_t>(c.seat)];
  if (!seat.taken()) return refuse(Reject::WrongSeat, seatName(c.seat) + " is free");
  if (seat.token != c.token) {
    return refuse(Reject::BadToken, "the token is not " + seatName(c.seat) + "'s");
  }
  if (!c.has_signature) {
    return refuse(Reject::Unsigned, "signature: commands must be signed");
  }
  if (c.seq <= seat.last_seq) {
    return refuse(Reject::StaleSequence, "seq " + std::to_string(c.seq) +
                                             " is not above the last used " +
                                             std::to_string(seat.last_seq));
  }
  if (!signed_by(seat)) {
    return refuse(Reject::BadSignature, "signature: not " + seatName(c.seat) + "'s key");
  }
  return Check::pass();
}

CheckedCommand checkCommand(const Match& match, const protocol::ShotRequest& command) {
  CheckedCommand out;
  out.plan.state = match.game();
  out.plan.before = match.balls();
  Check found = checkValues(match, command);
  if (found) {
    found = checkHolder(match,
                        {command.seat, command.seat_token, command.seq, !command.signature.empty()},
                        [&](const Seat& seat) {
                          return protocol::verifyCommand(command, seat.public_key) ==
                                 protocol::SignatureCheck::Valid;
                        });
  }
  out.signature_valid = found.ok();
  if (found) found = checkTurn(match, command);
  if (found) found = checkOption(match, command, out.plan);
  if (found && out.plan.shoots) found = checkPlacement(match, command, out.plan);
  // Practice rules ignore calls and safeties.
  if (found && out.plan.shoots && !match.practice()) found = checkCall(match, command, out.plan);
  if (!found) out.rejection = {found.code(), found.error()};
  return out;
}

}  // namespace pool::server
