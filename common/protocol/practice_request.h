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
#include "protocol/envelope.h"
#include "protocol/key_pair.h"
#include "table/physics_params.h"

namespace pool::protocol {

/// What a practice command asks of its table.
enum class PracticeAction : std::uint8_t {
  Layout,   ///< the balls on the table are exactly `balls` (every other ball off it)
  Rack,     ///< a fresh rack of `rack` (8, 9 or 10), or 0: clear the table (the cue ball alone)
  Undo,     ///< the table as it was before the last shot, bit for bit
  Again,    ///< the table before the last shot, and that shot played again with its parameters
  Physics,  ///< the table's coefficients become `coefficients` (kPracticeCoefficients' order)
};

const char* toString(PracticeAction action);  ///< "layout", "rack", "undo", "again", "physics"

/// One ball of a layout: an id 0–15 and a spot on the slate (m, table frame).
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
  std::vector<BallSpot> balls;          ///< Layout: at most 16, each id once
  int rack = 0;                         ///< Rack: 8, 9, 10, or 0 (clear)
  PracticeCoefficients coefficients{};  ///< Physics
  std::vector<std::uint8_t> signature;  ///< 64 bytes by the seat's key
};

/// Bytes of a practice command's encoding (fixed).
inline constexpr std::size_t kSignedPracticeBytes =
    kEnvelopeHeaderBytes + 1 + 1 + 1 + 16 * (1 + 8 + 8) + kPracticeCoefficients.size() * 8;

/// The signed bytes: the envelope header (tag Practice), then action u8 | rack u8 | ball count u8
/// | 16 × (id u8, x f64, y f64), unused ones zero | the coefficients f64 each (zero unless
/// Physics).
std::vector<std::uint8_t> signedBytes(const PracticeRequest& request);
void signPractice(PracticeRequest& request, const KeyPair& key);
SignatureCheck verifyPractice(const PracticeRequest& request,
                              std::span<const std::uint8_t> public_key);

/// Passes `request`'s fields when they are well formed on their own (ids 0–15 once each, finite
/// spots within ±half_length × ±half_width, a rack of 0/8/9/10, finite coefficients); refuses
/// them with "<field>: <reason>". Whether a spot is legal on the table is the server's.
Check<> checkPracticeFields(const PracticeRequest& request, double half_length, double half_width);

}  // namespace pool::protocol
