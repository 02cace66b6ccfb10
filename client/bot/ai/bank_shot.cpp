// One-cushion bank lines by the mirror image of the pocket.
#include "client/bot/ai/bank_shot.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pool::bot {
namespace {

// A bounce this close (m, along the cushion) to a pocket's opening is taken as the pocket's jaw.
constexpr double kJawClearance = 0.12;
// A pocket within this distance (m) of a cushion's line lies on that cushion.
constexpr double kOnCushion = 0.15;
// Widest angle between the banked ball's path and the pocket's axis that still drops, rad.
constexpr double kBankApproach = 1.0;

// One cushion's line for a ball's centre: coordinate `axis` (0: x, 1: y) equal to `at`.
struct CushionLine {
  int axis;
  double at;
};

}  // namespace

std::vector<PotLine> bankLines(const Vec2& cue, const std::vector<physics::Ball>& balls,
                               const std::vector<int>& legal, const TableView& view,
                               std::span<const double> shifts) {
  const double r = view.radius();
  const double hx = view.halfLength() - r, hy = view.halfWidth() - r;
  const std::array<CushionLine, 4> cushions{{{0, hx}, {0, -hx}, {1, hy}, {1, -hy}}};
  std::vector<PotLine> lines;
  for (int id : legal) {
    const auto object = ballAt(balls, id);
    if (!object) continue;
    for (int p = 0; p < static_cast<int>(view.pockets.size()); ++p) {
      const PocketTarget& pocket = view.pockets[static_cast<std::size_t>(p)];
      for (const CushionLine& c : cushions) {
        const int a = c.axis, o = 1 - c.axis;
        if (std::abs(pocket.mouth[a] - c.at) < kOnCushion) continue;
        Vec2 mirrored = pocket.mouth;
        mirrored[a] = 2 * c.at - pocket.mouth[a];
        // Where the path to the mirror image meets the cushion's line.
        const double span = mirrored[a] - (*object)[a];
        if (std::abs(span) < 1e-9) continue;
        const double t = (c.at - (*object)[a]) / span;
        if (t <= 0.0 || t >= 1.0) continue;
        const Vec2 mirror_bounce = *object + t * (mirrored - *object);
        for (double shift : shifts) {
          Vec2 bounce = mirror_bounce;
          bounce[o] += shift;
          const double along = bounce[o];
          const double end = (o == 0 ? hx : hy) - kJawClearance;
          if (std::abs(along) > end) continue;
          // The long cushions have the side pockets at their middle.
          if (o == 0 && std::abs(along) < kJawClearance) continue;
          const Vec2 in = (pocket.mouth - bounce).normalized();
          if (std::acos(std::clamp(in.dot(pocket.outward), -1.0, 1.0)) > kBankApproach) continue;
          // The ghost-ball geometry toward the bounce point, the whole roll along the path.
          PotLine line;
          line.ball = id;
          line.pocket = p;
          line.cue = cue;
          line.object = *object;
          const Vec2 d = (bounce - *object).normalized();
          line.object_distance = (bounce - *object).norm() + (pocket.mouth - bounce).norm();
          line.target = *object + line.object_distance * d;
          if (!aimLine(line, d, view)) continue;
          line.difficulty *= kBankDifficulty;
          if (!pathClear(*object, bounce, balls, r, id, physics::kCueBall)) continue;
          if (!pathClear(bounce, pocket.mouth, balls, r, id, physics::kCueBall)) continue;
          if (!pathClear(cue, line.ghost, balls, r, physics::kCueBall, id)) continue;
          lines.push_back(line);
        }
      }
    }
  }
  std::stable_sort(lines.begin(), lines.end(),
                   [](const PotLine& x, const PotLine& y) { return x.difficulty < y.difficulty; });
  return lines;
}

}  // namespace pool::bot
