// A practice-table command (lay out balls, re-rack, undo, shoot again, coefficients) in domain
// terms, its signed form in the one envelope (tag Practice), and the checks of its fields.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/check.h"
#include "core/result.h"
#include "physics/ball.h"
#include "protocol/envelope.h"
#include "protocol/key_pair.h"
#include "table/physics_params.h"

namespace pool::protocol {

/// What a practice command asks of its table.
enum class PracticeAction : std::uint8_t {
  Layout,   ///< the balls on the table are exactly `balls` (every other ball off it)
  Rack,     ///< a fresh rack of game number `rack` (its table's), or 0: clear the table
  Undo,     ///< the table as it was before the last shot, bit for bit
  Again,    ///< the table before the last shot, and that shot played again with its parameters
  Physics,  ///< the table's coefficients become `coefficients` (kPracticeCoefficients' order)
};

const char* toString(PracticeAction action);  ///< "layout", "rack", "undo", "again", "physics"

/// One ball of a layout: an id 0–21 (the table's game may allow fewer) and a spot on the slate
/// (m, table frame).
struct BallSpot {
  int id = 0;
  double x = 0.0;
  double y = 0.0;
};

/// The coefficients a practice table may change, by their scenario names (SIM-CONTRACT.md).
inline constexpr std::array<std::string_view, 7> kPracticeCoefficients = {
    "u_s", "u_r", "spin_decel", "e_b", "e_c", "u_c", "e_slate"};
using PracticeCoefficients = std::array<double, kPracticeCoefficients.size()>;

/// `params`' values of kPracticeCoefficients, in order.
PracticeCoefficients coefficientsOf(const table::PhysicsParams& params);
/// `base` with `values` set, each checked by table::setParam and the whole by table::validate;
/// fails with "<name>: <reason>" and nothing changed.
Result<table::PhysicsParams> withCoefficients(const table::PhysicsParams& base,
                                              const PracticeCoefficients& values);

/// The most balls of a layout: a snooker set's 22 (ids 0 to physics::kMaxBallId).
inline constexpr std::size_t kPracticeMaxBalls = physics::kMaxBallId + 1;
/// The ball slots every practice command's encoding carries (a pool set's 16); a layout of more
/// balls (snooker's) adds one slot for each ball past them.
inline constexpr std::size_t kPracticeFixedSlots = 16;

/// The most layouts a table keeps to undo.
inline constexpr std::size_t kPracticeUndoDepth = 64;

/// One practice command (the PracticeCommand topic). Numbered from the seat's one sequence,
/// shared with its shot commands.
struct PracticeRequest {
  std::string match;
  int seat = 0;
  std::uint64_t seat_token = 0;
  std::uint32_t seq = 0;
  PracticeAction action = PracticeAction::Undo;
  std::vector<BallSpot> balls;  ///< Layout: at most kPracticeMaxBalls, each id once
  int rack = 0;  ///< Rack: a game's number (8, 9, 10, 3, 22: rules::gameOfNumber), or 0 (clear)
  PracticeCoefficients coefficients{};  ///< Physics
  std::vector<std::uint8_t> signature;  ///< 64 bytes by the seat's key
};

/// Bytes of one ball slot of a practice command's encoding: id u8, x f64, y f64.
inline constexpr std::size_t kPracticeSlotBytes = 1 + 8 + 8;
/// Bytes of a practice command's encoding with at most kPracticeFixedSlots balls (every pool
/// command); each ball past them adds kPracticeSlotBytes.
inline constexpr std::size_t kSignedPracticeBytes = kEnvelopeHeaderBytes + 1 + 1 + 1 +
                                                    kPracticeFixedSlots * kPracticeSlotBytes +
                                                    kPracticeCoefficients.size() * 8;

/// The signed bytes: the envelope header (tag Practice), then action u8 | rack u8 | ball count u8
/// | 16 × (id u8, x f64, y f64), unused ones zero | the balls past the 16th (a snooker layout's),
/// (id u8, x f64, y f64) each, none for 16 or fewer | the coefficients f64 each (zero unless
/// Physics). At most kPracticeMaxBalls balls are encoded. A command of 16 balls or fewer encodes
/// as it did before snooker's layouts.
std::vector<std::uint8_t> signedBytes(const PracticeRequest& request);
void signPractice(PracticeRequest& request, const KeyPair& key);
SignatureCheck verifyPractice(const PracticeRequest& request,
                              std::span<const std::uint8_t> public_key);

/// Passes `request`'s fields when they are well formed on their own (at most kPracticeMaxBalls
/// balls, ids 0–21 once each, finite spots within ±half_length × ±half_width, a rack of 0 or a
/// game's number, finite coefficients); refuses them with "<field>: <reason>". Whether a spot is
/// legal on the table, and a ball or rack of its game, is the server's.
Check<> checkPracticeFields(const PracticeRequest& request, double half_length, double half_width);

}  // namespace pool::protocol
