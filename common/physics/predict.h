// Time of impact between balls moving with constant acceleration, and against the table's features.
#pragma once

#include <string>
#include <vector>

#include "physics/ball.h"
#include "physics/polynomial.h"
#include "table/table_geometry.h"

namespace pool::physics {

/// Motion with constant acceleration: p + v·t + a·t²/2.
struct Kinematics {
  Vec3 p = Vec3::Zero();
  Vec3 v = Vec3::Zero();
  Vec3 a = Vec3::Zero();
  Vec3 at(double t) const { return p + t * (v + 0.5 * t * a); }
};

/// Earliest time in [0, horizon] at which two balls of radius r come into contact while
/// approaching; kNever if none.
double pairContactTime(const Kinematics& a, const Kinematics& b, double radius, double horizon);

/// What a ball can hit on the table.
enum class FeatureKind : std::uint8_t { Nose, Point, Hole, OverNose };

/// The table's features in the form the predictor uses (from TableGeometry).
struct TableFeatures {
  struct Nose {
    Vec2 a, dir, normal;
    double length;
    std::string name;
  };
  struct Point {
    Vec2 c;
    std::string name;
  };
  struct Hole {
    Vec2 c;
    double radius;
    std::string name;
  };
  std::vector<Nose> noses;
  std::vector<Point> points;  ///< ends of the nose segments (jaw points), each once
  std::vector<Hole> holes;
  double half_length = 0.0, half_width = 0.0;

  static TableFeatures from(const table::TableGeometry& geometry);
};

/// A predicted contact with the table.
struct TableHit {
  double t = kNever;
  FeatureKind kind = FeatureKind::Nose;
  int index = -1;
};

/// The ball's next contact with a cushion nose, a jaw point, a pocket hole (its centre passing
/// over the hole's edge, on the slate or in the air) or, when airborne, the line over a cushion
/// nose, within [0, horizon].
/// `nose_height` is the cushion nose above the slate.
TableHit nextTableHit(const Kinematics& k, bool airborne, const TableFeatures& f, double radius,
                      double nose_height, double horizon);

/// Unit normal (from the contact point to the ball's centre) of a ball at `p` touching nose
/// `index` or point `index` (kind Nose or Point) at height nose_height.
Vec3 contactNormal(const Vec3& p, const TableFeatures& f, FeatureKind kind, int index,
                   double nose_height);

}  // namespace pool::physics
