// Contact times as the earliest closing of a polynomial gap: quartics for spheres and points,
// quadratics for nose lines.
#include "physics/predict.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace pool::physics {

namespace {

using Poly3 = std::array<double, 3>;  // c0 + c1 t + c2 t²

Poly3 along(const Kinematics& k, const Vec2& dir, const Vec2& origin) {
  return {(k.p.head<2>() - origin).dot(dir), k.v.head<2>().dot(dir), 0.5 * k.a.head<2>().dot(dir)};
}

Quartic square(const Poly3& s) {
  return {s[0] * s[0], 2 * s[0] * s[1], s[1] * s[1] + 2 * s[0] * s[2], 2 * s[1] * s[2],
          s[2] * s[2]};
}

Quartic add(const Quartic& x, const Quartic& y) {
  return {x[0] + y[0], x[1] + y[1], x[2] + y[2], x[3] + y[3], x[4] + y[4]};
}

/// |d(t)|² − r² for d(t) = dp + dv t + da t²/2 (any dimension through the dot products).
template <class V>
Quartic gapSquared(const V& dp, const V& dv, const V& da, double r) {
  return {dp.squaredNorm() - r * r, 2.0 * dp.dot(dv), dv.squaredNorm() + dp.dot(da), dv.dot(da),
          0.25 * da.squaredNorm()};
}

/// How far a motion can get in `horizon` seconds (a bound for cheap rejection).
double reach(const Vec3& v, const Vec3& a, double horizon) {
  return horizon * (v.norm() + 0.5 * horizon * a.norm());
}

double lineGapTime(const Poly3& s, double offset, double horizon) {
  return earliestClosing({s[0] - offset, s[1], s[2], 0.0, 0.0}, horizon);
}

bool withinSegment(const Kinematics& k, const TableFeatures::Nose& n, double t) {
  const double q = (k.at(t).head<2>() - n.a).dot(n.dir);
  return q >= 0.0 && q <= n.length;
}

}  // namespace

double pairContactTime(const Kinematics& a, const Kinematics& b, double radius, double horizon) {
  const Vec3 dp = b.p - a.p;
  const Vec3 dv = b.v - a.v;
  const Vec3 da = b.a - a.a;
  if (dp.norm() - 2.0 * radius > reach(dv, da, horizon)) return kNever;
  return earliestClosing(gapSquared(dp, dv, da, 2.0 * radius), horizon);
}

TableFeatures TableFeatures::from(const table::TableGeometry& g) {
  TableFeatures f;
  f.half_length = 0.5 * g.length;
  f.half_width = 0.5 * g.width;
  // Points are the segment ends; a point shared by a rail and a jaw is the jaw's.
  std::map<std::pair<long long, long long>, size_t> seen;
  auto addPoint = [&](const Vec2& c, const std::string& name) {
    const auto key = std::make_pair(std::llround(c.x() * 1e7), std::llround(c.y() * 1e7));
    auto it = seen.find(key);
    if (it == seen.end()) {
      seen.emplace(key, f.points.size());
      f.points.push_back({c, name});
    } else if (name.rfind("jaw_", 0) == 0) {
      f.points[it->second].name = name;
    }
  };
  for (const auto& s : g.noses) {
    const Vec2 d = s.b - s.a;
    f.noses.push_back({s.a, d.normalized(), s.normal.normalized(), d.norm(), s.name});
    addPoint(s.a, s.name);
    addPoint(s.b, s.name);
  }
  for (const auto& h : g.holes) f.holes.push_back({h.centre, h.radius, h.name});
  return f;
}

TableHit nextTableHit(const Kinematics& k, bool airborne, const TableFeatures& f, double radius,
                      double nose_height, double horizon) {
  TableHit best;
  const double lift = nose_height - radius;  // nose above the centre of a ball on the slate
  const double dh = std::sqrt(std::max(0.0, radius * radius - lift * lift));
  const double r = reach(k.v, k.a, horizon);
  const double near = airborne ? radius : dh;  // horizontal distance at contact, at most
  auto consider = [&](double t, FeatureKind kind, size_t i) {
    if (t < best.t) best = {t, kind, static_cast<int>(i)};
  };
  const Vec2 p2 = k.p.head<2>();

  for (size_t i = 0; i < f.noses.size(); ++i) {
    const auto& n = f.noses[i];
    const Poly3 s = along(k, n.normal, n.a);
    if (s[0] - near > r) continue;
    if (!airborne) {
      const double t = lineGapTime(s, dh, std::min(horizon, best.t));
      if (t < best.t && withinSegment(k, n, t)) consider(t, FeatureKind::Nose, i);
      continue;
    }
    // Airborne: the distance to the nose line in 3-D, and the line over the nose.
    const Poly3 w{k.p.z() - nose_height, k.v.z(), 0.5 * k.a.z()};
    const Quartic gap = add(square(s), square(w));
    const double t = earliestClosing({gap[0] - radius * radius, gap[1], gap[2], gap[3], gap[4]},
                                     std::min(horizon, best.t));
    if (t < best.t && withinSegment(k, n, t) && (k.at(t).head<2>() - n.a).dot(n.normal) > 0) {
      consider(t, FeatureKind::Nose, i);
    }
    const double over = lineGapTime(s, 0.0, std::min(horizon, best.t));
    if (over < best.t && withinSegment(k, n, over)) consider(over, FeatureKind::OverNose, i);
  }

  for (size_t i = 0; i < f.points.size(); ++i) {
    const Vec2 d = p2 - f.points[i].c;
    if (d.norm() - near > r) continue;
    double t;
    if (!airborne) {
      t = earliestClosing(gapSquared(d, Vec2(k.v.head<2>()), Vec2(k.a.head<2>()), dh),
                          std::min(horizon, best.t));
    } else {
      const Vec3 c(f.points[i].c.x(), f.points[i].c.y(), nose_height);
      t = earliestClosing(gapSquared(Vec3(k.p - c), k.v, k.a, radius), std::min(horizon, best.t));
    }
    consider(t, FeatureKind::Point, i);
  }

  // A centre passing over a hole's edge drops, airborne or not: the pocket world (ODE on the
  // mesh: liner, rail, fascia) takes it from there.
  for (size_t i = 0; i < f.holes.size(); ++i) {
    const Vec2 d = p2 - f.holes[i].c;
    if (d.norm() - f.holes[i].radius > r) continue;
    const double t =
        earliestClosing(gapSquared(d, Vec2(k.v.head<2>()), Vec2(k.a.head<2>()), f.holes[i].radius),
                        std::min(horizon, best.t));
    consider(t, FeatureKind::Hole, i);
  }
  return best;
}

Vec3 contactNormal(const Vec3& p, const TableFeatures& f, FeatureKind kind, int index,
                   double nose_height) {
  Vec2 c;
  if (kind == FeatureKind::Nose) {
    const auto& n = f.noses[static_cast<size_t>(index)];
    c = n.a + n.dir * (p.head<2>() - n.a).dot(n.dir);
  } else {
    c = f.points[static_cast<size_t>(index)].c;
  }
  return (p - Vec3(c.x(), c.y(), nose_height)).normalized();
}

}  // namespace pool::physics
