// The baulk line, the D and the colours' spots of a snooker table.
#include "table/snooker_spots.h"

namespace pool::table {

std::optional<SnookerSpots> snookerSpotsFor(const TableSpec& spec) {
  if (!spec.snooker_marks) return std::nullopt;
  const SnookerMarks& m = *spec.snooker_marks;
  SnookerSpots s;
  s.baulk_x = -spec.length / 2.0 + m.baulk_line;
  s.d_radius = m.d_radius;
  s.brown = {s.baulk_x, 0.0};
  s.yellow = {s.baulk_x, -m.d_radius};
  s.green = {s.baulk_x, m.d_radius};
  s.blue = {0.0, 0.0};
  s.pink = {spec.length / 4.0, 0.0};
  s.black = {spec.length / 2.0 - m.black_spot, 0.0};
  return s;
}

bool inTheD(const SnookerSpots& spots, const Eigen::Vector2d& pos) {
  return pos.x() <= spots.baulk_x && (pos - spots.brown).norm() <= spots.d_radius;
}

}  // namespace pool::table
