// What the rules know of the table, and the pocket names.
#include "rules/table_context.h"

#include <algorithm>

namespace pool::rules {

TableContext tableContext(const table::TableSpec& spec) {
  TableContext context;
  context.spec = spec;
  context.spots = table::spotsFor(spec);
  context.ball_radius = spec.params.ball_radius;
  context.snooker = table::snookerSpotsFor(spec);
  return context;
}

TableContext tableContext(const table::TableSpec& spec, const table::TableGeometry& geometry) {
  TableContext context = tableContext(spec);
  context.holes = geometry.holes;
  return context;
}

const std::vector<std::string_view>& pocketNames() {
  static const std::vector<std::string_view> names = {"head_left_corner", "left_side",
                                                      "foot_left_corner", "head_right_corner",
                                                      "right_side",       "foot_right_corner"};
  return names;
}

bool isPocketName(std::string_view name) {
  const auto& names = pocketNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace pool::rules
