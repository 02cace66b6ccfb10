// A player's shot command as the server and players reason about it, free of DDS types.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "physics/cue_strike.h"
#include "rules/game_state.h"

namespace pool::protocol {

/// The answer to a choice the rules offered before a shot (mirrors rules::Choice, plus None).
enum class ShotOption : std::uint8_t {
  None,              ///< no pending choice: an ordinary shot
  PlayOn,            ///< accept the table as it lies and shoot
  BallInHand,        ///< take the cue ball in hand behind the head string, and shoot
  RespotEight,       ///< re-spot the 8 pocketed on the break, and shoot
  ReBreak,           ///< re-rack, the chooser breaks; the command carries no shot
  OpponentReBreaks,  ///< re-rack, the other player breaks; the command carries no shot
  PushOut,           ///< 9-/10-ball: play this shot as a push-out
  PassBack,          ///< 9-/10-ball, snooker: the player who just shot shoots again; no shot
  FreeBall,          ///< snooker: play a free ball, and shoot
  Replace,           ///< snooker: the balls back as before the miss, the offender plays; no shot
};

const char* toString(ShotOption option);

/// True for the options that answer with a shot (None, PlayOn, BallInHand, RespotEight, PushOut).
bool optionShoots(ShotOption option);

/// The rules' choice as the option that answers it (the one mapping between the two enums).
ShotOption optionOf(rules::Choice choice);

/// The rules' choice an option names; none for ShotOption::None.
std::optional<rules::Choice> choiceOf(ShotOption option);

/// One shot command (the ShotCommand topic) in domain types. Angles in radians, SI units, table
/// frame.
struct ShotRequest {
  std::string match;                           ///< match id
  int seat = 0;                                ///< 0 or 1
  std::uint64_t seat_token = 0;                ///< from the JoinReply that gave the seat
  std::uint32_t seq = 0;                       ///< per seat, strictly increasing
  physics::CueShot cue;                        ///< yaw, tip offset, elevation (rad), speed (m/s)
  std::optional<int> called_ball;              ///< 1–21 (a pool game: 1–15); with called_pocket
  std::string called_pocket;                   ///< pocket name (SIM-CONTRACT.md); empty: none
  bool safety = false;                         ///< a declared safety
  std::optional<Eigen::Vector2d> cue_ball_at;  ///< ball in hand: place the cue ball here, m
  ShotOption option = ShotOption::None;
  std::vector<std::uint8_t> signature;  ///< empty until commands are signed (at most 64 bytes)
};

}  // namespace pool::protocol
