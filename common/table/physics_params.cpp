// Coefficient names, range checks and consistency checks for PhysicsParams.
#include "table/physics_params.h"

#include <array>
#include <cmath>
#include <cstdio>

namespace pool::table {
namespace {

/// An interval of allowed values, each end open or closed.
struct Range {
  double lo = 0.0;
  double hi = 0.0;
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double v) const {
    if (!std::isfinite(v)) return false;
    const bool above = lo_open ? v > lo : v >= lo;
    const bool below = hi_open ? v < hi : v <= hi;
    return above && below;
  }
};

/// One named coefficient; `member` is null for u_b (an optional).
struct ParamInfo {
  std::string_view name;
  double PhysicsParams::*member;
  Range range;
};

constexpr Range kOpenTo(double hi) {
  return Range{0.0, hi, true, false};
}
constexpr Range kClosed(double lo, double hi) {
  return Range{lo, hi, false, false};
}

const std::array<ParamInfo, 14>& paramTable() {
  static const std::array<ParamInfo, 14> table{{
      {"u_s", &PhysicsParams::u_s, kOpenTo(2.0)},
      // Zero rolling resistance or spin decay would let a ball roll or spin for ever.
      {"u_r", &PhysicsParams::u_r, kOpenTo(1.0)},
      {"spin_decel", &PhysicsParams::spin_decel, kOpenTo(1000.0)},
      {"e_b", &PhysicsParams::e_b, kClosed(0.0, 1.0)},
      {"u_b", nullptr, kClosed(0.0, 1.0)},
      {"e_c", &PhysicsParams::e_c, kClosed(0.0, 1.0)},
      {"u_c", &PhysicsParams::u_c, kClosed(0.0, 1.0)},
      {"e_slate", &PhysicsParams::e_slate, kClosed(0.0, 1.0)},
      {"cushion_height", &PhysicsParams::cushion_height, kOpenTo(1.0)},
      {"ball_mass", &PhysicsParams::ball_mass, kOpenTo(10.0)},
      {"ball_radius", &PhysicsParams::ball_radius, kOpenTo(1.0)},
      {"cue_mass", &PhysicsParams::cue_mass, kOpenTo(10.0)},
      {"cue_end_mass", &PhysicsParams::cue_end_mass, kOpenTo(10.0)},
      {"miscue_limit", &PhysicsParams::miscue_limit, kOpenTo(1.0)},
  }};
  return table;
}

const ParamInfo* findParam(std::string_view name) {
  for (const ParamInfo& info : paramTable()) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

std::string formatBound(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string rangeReason(const Range& r) {
  return "must be a finite number in " + std::string(r.lo_open ? "(" : "[") + formatBound(r.lo) +
         ", " + formatBound(r.hi) + (r.hi_open ? ")" : "]");
}

}  // namespace

const std::vector<std::string_view>& paramNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> out;
    for (const ParamInfo& info : paramTable()) out.push_back(info.name);
    return out;
  }();
  return names;
}

Check<> setParam(PhysicsParams& params, std::string_view name, double value) {
  const ParamInfo* info = findParam(name);
  if (info == nullptr) return Check<>::refuse("unknown_parameter", "unknown parameter");
  if (!info->range.contains(value))
    return Check<>::refuse("out_of_range", rangeReason(info->range));
  if (info->member == nullptr) {
    params.u_b = value;
  } else {
    params.*(info->member) = value;
  }
  return Check<>::pass();
}

Check<> validate(const PhysicsParams& params) {
  for (const ParamInfo& info : paramTable()) {
    std::optional<double> value =
        info.member ? std::optional<double>(params.*(info.member)) : params.u_b;
    if (value && !info.range.contains(*value)) {
      return Check<>::refuse("out_of_range",
                             std::string(info.name) + ": " + rangeReason(info.range));
    }
  }
  if (!(params.cushion_height > params.ball_radius &&
        params.cushion_height < 2.0 * params.ball_radius)) {
    return Check<>::refuse("bad_cushion_height",
                           "cushion_height: must be above ball_radius and below 2 * ball_radius");
  }
  if (params.cue_end_mass > params.cue_mass)
    return Check<>::refuse("bad_cue_end_mass", "cue_end_mass: must not exceed cue_mass");
  return Check<>::pass();
}

}  // namespace pool::table
