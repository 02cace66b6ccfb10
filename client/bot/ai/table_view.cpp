// Pocket targets derived from the table geometry, and loading a table for the AI.
#include "client/bot/ai/table_view.h"

#include <algorithm>
#include <limits>

namespace pool::bot {
namespace {

bool isJaw(const table::NoseSegment& nose) {
  return nose.name.rfind("jaw_", 0) == 0;
}

// The two rail-nose end points nearest a hole: the jaw points of its pocket.
std::pair<Vec2, Vec2> jawPoints(const table::TableGeometry& geometry, const Vec2& hole) {
  std::vector<Vec2> ends;
  for (const auto& nose : geometry.noses) {
    if (isJaw(nose)) continue;
    ends.push_back(nose.a);
    ends.push_back(nose.b);
  }
  std::sort(ends.begin(), ends.end(), [&](const Vec2& p, const Vec2& q) {
    return (p - hole).squaredNorm() < (q - hole).squaredNorm();
  });
  if (ends.size() < 2) return {hole, hole};
  return {ends[0], ends[1]};
}

PocketTarget targetFor(const table::TableGeometry& geometry, const table::PocketHole& hole) {
  PocketTarget target;
  target.name = hole.name;
  target.hole = hole.centre;
  const auto [a, b] = jawPoints(geometry, hole.centre);
  target.mouth = (a + b) / 2;
  const Vec2 out = hole.centre - target.mouth;
  target.outward = out.norm() > 1e-9 ? Vec2(out.normalized()) : Vec2(hole.centre.normalized());
  target.corner = hole.name.find("corner") != std::string::npos;
  return target;
}

}  // namespace

TableView makeTableView(table::TableSpec spec, table::TableGeometry geometry) {
  TableView view;
  view.context = rules::tableContext(spec, geometry);
  for (const auto& hole : geometry.holes) view.pockets.push_back(targetFor(geometry, hole));
  view.spec = std::move(spec);
  view.geometry = std::move(geometry);
  return view;
}

Result<TableView> loadTableView(const std::string& name) {
  auto spec = table::loadTableSpec(name);
  if (!spec) return Result<TableView>::fail("table " + name + ": " + spec.error());
  auto geometry = table::loadTableGeometry(*spec);
  if (!geometry) return Result<TableView>::fail("table " + name + ": " + geometry.error());
  return Result<TableView>::ok(makeTableView(std::move(*spec), std::move(*geometry)));
}

int pocketIndex(const TableView& view, const std::string& name) {
  for (std::size_t i = 0; i < view.pockets.size(); ++i) {
    if (view.pockets[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace pool::bot
