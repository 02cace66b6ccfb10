// Spots, 8-, 9- and 10-ball racks (deterministic shuffles, frozen or hand-racked), snooker's rack
// and re-spotting on the long string.
#include "table/rack.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/split_mix64.h"
#include "table/snooker_spots.h"

namespace pool::table {
namespace {

using Vec2 = Eigen::Vector2d;

/// Fisher–Yates with our own PRNG (std::shuffle's results differ between standard libraries).
void shuffle(std::vector<int>& v, SplitMix64& rng) {
  for (std::size_t i = v.size(); i > 1; --i) {
    const auto j = static_cast<std::size_t>(rng.below(i));
    std::swap(v[i - 1], v[j]);
  }
}

/// Rack positions row by row from `apex`; row k holds sizes[k] balls, listed from −y (right) to
/// +y (left).
std::vector<Vec2> rackSlots(const Vec2& apex, double ball_radius, double gap,
                            const std::vector<int>& sizes) {
  const double pitch = 2.0 * ball_radius + gap;
  const double row_step = pitch * std::sqrt(3.0) / 2.0;
  std::vector<Vec2> slots;
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const int n = sizes[k];
    for (int j = 0; j < n; ++j) {
      const double y = (j - (n - 1) / 2.0) * pitch;
      slots.push_back(apex + Vec2(static_cast<double>(k) * row_step, y));
    }
  }
  return slots;
}

/// Fills every slot not yet taken with `rest`, in slot order.
std::vector<BallPlacement> place(const std::vector<Vec2>& slots, std::vector<int> ids_by_slot,
                                 const std::vector<int>& rest) {
  std::size_t next = 0;
  for (int& id : ids_by_slot) {
    if (id == 0) id = rest[next++];
  }
  std::vector<BallPlacement> out;
  for (std::size_t i = 0; i < slots.size(); ++i)
    out.push_back(BallPlacement{ids_by_slot[i], slots[i]});
  return out;
}

std::vector<BallPlacement> eightBall(const TableSpec& spec, double ball_radius, std::uint64_t seed,
                                     double gap) {
  const auto slots = rackSlots(spotsFor(spec).foot_spot, ball_radius, gap, {1, 2, 3, 4, 5});
  constexpr std::size_t kCentre = 4, kBackRight = 10, kBackLeft = 14;
  SplitMix64 rng(seed);
  const bool solid_left = rng.below(2) == 0;
  const int solid = 1 + static_cast<int>(rng.below(7));
  const int stripe = 9 + static_cast<int>(rng.below(7));
  std::vector<int> ids(slots.size(), 0);
  ids[kCentre] = 8;
  ids[kBackLeft] = solid_left ? solid : stripe;
  ids[kBackRight] = solid_left ? stripe : solid;
  std::vector<int> rest;
  for (int id = 1; id <= 15; ++id) {
    if (id != 8 && id != solid && id != stripe) rest.push_back(id);
  }
  shuffle(rest, rng);
  return place(slots, ids, rest);
}

std::vector<BallPlacement> nineBall(const TableSpec& spec, double ball_radius, std::uint64_t seed,
                                    double gap) {
  const auto slots = rackSlots(spotsFor(spec).foot_spot, ball_radius, gap, {1, 2, 3, 2, 1});
  constexpr std::size_t kApex = 0, kCentre = 4;
  SplitMix64 rng(seed);
  std::vector<int> ids(slots.size(), 0);
  ids[kApex] = 1;
  ids[kCentre] = 9;
  std::vector<int> rest{2, 3, 4, 5, 6, 7, 8};
  shuffle(rest, rng);
  return place(slots, ids, rest);
}

std::vector<BallPlacement> tenBall(const TableSpec& spec, double ball_radius, std::uint64_t seed,
                                   double gap) {
  const auto slots = rackSlots(spotsFor(spec).foot_spot, ball_radius, gap, {1, 2, 3, 4});
  constexpr std::size_t kApex = 0, kCentre = 4;
  SplitMix64 rng(seed);
  std::vector<int> ids(slots.size(), 0);
  ids[kApex] = 1;
  ids[kCentre] = 10;
  std::vector<int> rest{2, 3, 4, 5, 6, 7, 8, 9};
  shuffle(rest, rng);
  return place(slots, ids, rest);
}

/// Points on the long string (y = 0) just clear of each ball that blocks it: behind (+x) or in
/// front.
std::vector<double> clearPoints(double ball_radius, const std::vector<Vec2>& occupied,
                                bool behind) {
  constexpr double kClearance = 5e-5;  // m: a re-spotted ball sits just clear of its neighbour
  const double d = 2.0 * ball_radius + kClearance;
  std::vector<double> xs;
  for (const Vec2& c : occupied) {
    if (std::abs(c.y()) >= d) continue;
    const double half = std::sqrt(d * d - c.y() * c.y());
    xs.push_back(behind ? c.x() + half : c.x() - half);
  }
  return xs;
}

}  // namespace

bool isFree(const Vec2& p, double ball_radius, const std::vector<Vec2>& occupied) {
  return std::all_of(occupied.begin(), occupied.end(),
                     [&](const Vec2& c) { return (c - p).norm() >= 2.0 * ball_radius; });
}

Spots spotsFor(const TableSpec& spec) {
  Spots s;
  s.head_spot = Vec2(-spec.length / 4.0, 0.0);
  s.foot_spot = Vec2(spec.length / 4.0, 0.0);
  s.centre_spot = Vec2(0.0, 0.0);
  s.head_string_x = -spec.length / 4.0;
  return s;
}

std::optional<RackType> rackTypeFromString(std::string_view name) {
  if (name == "8ball") return RackType::EightBall;
  if (name == "9ball") return RackType::NineBall;
  if (name == "10ball") return RackType::TenBall;
  if (name == "three_cushion") return RackType::ThreeCushion;
  if (name == "snooker") return RackType::Snooker;
  return std::nullopt;
}

std::vector<BallPlacement> rackBalls(RackType type, const TableSpec& spec, double ball_radius,
                                     std::uint64_t seed, double gap) {
  switch (type) {
    case RackType::EightBall:
      return eightBall(spec, ball_radius, seed, gap);
    case RackType::NineBall:
      return nineBall(spec, ball_radius, seed, gap);
    case RackType::TenBall:
      return tenBall(spec, ball_radius, seed, gap);
    case RackType::ThreeCushion:
      return caromOpening(spec, seed);
    case RackType::Snooker:
      return snookerRack(spec, ball_radius, gap);
  }
  return {};
}

std::optional<RackGenerator> rackGeneratorOf(std::int64_t value) {
  if (value == static_cast<int>(RackGenerator::Frozen)) return RackGenerator::Frozen;
  if (value == static_cast<int>(RackGenerator::Hand)) return RackGenerator::Hand;
  return std::nullopt;
}

std::vector<BallPlacement> caromOpening(const TableSpec& spec, std::uint64_t seed) {
  const Spots spots = spotsFor(spec);
  SplitMix64 rng(seed);
  const double side = rng.below(2) == 0 ? 1.0 : -1.0;
  return {{0, spots.head_spot + Vec2(0.0, side * kCaromBreakOffset)},
          {1, spots.head_spot},
          {2, spots.foot_spot}};
}

std::vector<BallPlacement> snookerRack(const TableSpec& spec, double ball_radius, double gap) {
  const auto spots = snookerSpotsFor(spec);
  if (!spots) return {};
  const Vec2 apex = spots->pink + Vec2(2.0 * ball_radius + kSnookerApexGap, 0.0);
  const auto slots = rackSlots(apex, ball_radius, gap, {1, 2, 3, 4, 5});
  std::vector<BallPlacement> out;
  out.push_back({0, {spots->baulk_x, (spots->brown.y() + spots->yellow.y()) / 2.0}});
  for (std::size_t i = 0; i < slots.size(); ++i) out.push_back({static_cast<int>(i) + 1, slots[i]});
  for (int colour = kSnookerYellow; colour <= kSnookerBlack; ++colour)
    out.push_back({colour, *snookerSpotOf(spec, colour)});
  return out;
}

std::optional<Vec2> snookerSpotOf(const TableSpec& spec, int colour) {
  const auto spots = snookerSpotsFor(spec);
  if (!spots) return std::nullopt;
  switch (colour) {
    case kSnookerYellow:
      return spots->yellow;
    case kSnookerGreen:
      return spots->green;
    case kSnookerBrown:
      return spots->brown;
    case kSnookerBlue:
      return spots->blue;
    case kSnookerPink:
      return spots->pink;
    case kSnookerBlack:
      return spots->black;
    default:
      return std::nullopt;
  }
}

std::vector<BallPlacement> rackFor(RackType type, const TableSpec& spec, double ball_radius,
                                   std::uint64_t seed, RackGenerator generator) {
  if (generator == RackGenerator::Frozen || type == RackType::ThreeCushion)
    return rackBalls(type, spec, ball_radius, seed);
  auto balls = rackBalls(type, spec, ball_radius, seed, 2.0 * kRackStray);
  // Its own stream, so that the order of the balls stays the one a Frozen rack of the seed has.
  SplitMix64 rng(splitMix64(seed ^ 0x68616e647261636bULL));
  constexpr double kTwoPi = 6.283185307179586;
  for (BallPlacement& b : balls) {
    // Snooker's colours sit on their spots and its cue ball waits in the D: only the reds stray.
    if (type == RackType::Snooker && (b.id == 0 || b.id > kSnookerReds)) continue;
    const double r = kRackStray * std::sqrt(rng.uniform());  // uniform over the disc
    const double a = kTwoPi * rng.uniform();
    b.pos += Vec2(r * std::cos(a), r * std::sin(a));
  }
  return balls;
}

Vec2 respotPosition(const TableSpec& spec, double ball_radius, const std::vector<Vec2>& occupied) {
  const Vec2 foot = spotsFor(spec).foot_spot;
  if (isFree(foot, ball_radius, occupied)) return foot;
  std::vector<double> behind = clearPoints(ball_radius, occupied, true);
  std::sort(behind.begin(), behind.end());
  for (double x : behind) {
    if (x >= foot.x() && x <= spec.length / 2.0 - ball_radius &&
        isFree({x, 0.0}, ball_radius, occupied))
      return {x, 0.0};
  }
  std::vector<double> ahead = clearPoints(ball_radius, occupied, false);
  std::sort(ahead.begin(), ahead.end(), std::greater<>());
  for (double x : ahead) {
    if (x <= foot.x() && x >= -spec.length / 2.0 + ball_radius &&
        isFree({x, 0.0}, ball_radius, occupied))
      return {x, 0.0};
  }
  return foot;  // the whole long string is taken: nothing better exists
}

}  // namespace pool::table
