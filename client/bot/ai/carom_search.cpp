// The bot's three-cushion search: headings, speeds and side, tried in the physics.
#include "client/bot/ai/carom_search.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rules/three_cushion.h"

namespace pool::bot {
namespace {

constexpr int kHeadings = 120;                      // 3° apart round the ball
constexpr double kSpeeds[] = {2.0, 2.8, 3.6, 4.5};  // m/s of the ball: round a match table
constexpr double kSides[] = {-0.4, 0.0, 0.4};       // side, fraction of R (the miscue limit is 0.5)

struct Candidate {
  PlannedShot shot;
  double score = 0.0;  ///< share of tries that scored (1 for an exact point)
};

PlannedShot caromStroke(int ball, double yaw, double speed, double side) {
  PlannedShot shot;
  shot.kind = ShotKind::Carom;
  shot.cue.ball = ball;
  shot.cue.yaw = yaw;
  shot.cue.speed = speed;
  shot.cue.speed_is_ball = true;
  shot.cue.tip_side = side;
  shot.cue.tip_height = 0.2;  // a little follow, so the ball keeps running off the cushions
  return shot;
}

}  // namespace

PlannedShot planCarom(ShotVerifier& verifier, const std::vector<physics::Ball>& balls,
                      const rules::GameState& state, const CaromSearchOptions& options) {
  const int own = rules::caromBallOf(state, state.shooter);
  const int budget_end = verifier.runs() + options.max_runs;
  std::vector<Candidate> scoring;
  PlannedShot fallback = caromStroke(own, 0.0, 1.5, 0.0);
  fallback.kind = ShotKind::Fallback;
  double fallback_lie = 1e9;
  const double step = 2.0 * std::numbers::pi / kHeadings;
  // Interleaved so that a budget cut short still covers the whole circle at the middle speed.
  for (double speed : {kSpeeds[1], kSpeeds[2], kSpeeds[0], kSpeeds[3]}) {
    for (double side : kSides) {
      for (int k = 0; k < kHeadings && verifier.runs() < budget_end; ++k) {
        const PlannedShot shot = caromStroke(own, k * step, speed, side);
        const Trial t = verifier.run(balls, state, shot);
        if (!t.judged) continue;
        if (t.verdict.scored > 0) {
          scoring.push_back({shot, 1.0});
        } else if (t.verdict.legal()) {
          // Keep the legal miss whose ball ends nearest the middle.
          for (const auto& b : t.after) {
            if (b.id != own) continue;
            const double lie = b.pos.head<2>().norm();
            if (lie < fallback_lie) {
              fallback_lie = lie;
              fallback = shot;
              fallback.kind = ShotKind::Safety;
            }
          }
        }
      }
    }
  }
  if (scoring.empty()) return fallback;
  // Neighbours half a step either side: a point that survives them is a wider window.
  for (Candidate& c : scoring) {
    if (verifier.runs() + 2 > budget_end) break;
    int kept = 1;
    for (double d : {-step / 2.0, step / 2.0}) {
      PlannedShot near = c.shot;
      near.cue.yaw += d;
      const Trial t = verifier.run(balls, state, near);
      kept += t.judged && t.verdict.scored > 0 ? 1 : 0;
    }
    c.score = kept / 3.0;
  }
  if (options.samples > 0) {
    std::stable_sort(scoring.begin(), scoring.end(),
                     [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
    Rng rng(static_cast<std::uint64_t>(verifier.runs()) * 0x9e3779b97f4a7c15ULL + 1);
    for (std::size_t i = 0; i < std::min<std::size_t>(scoring.size(), 10); ++i) {
      int made = 0;
      for (int s = 0; s < options.samples; ++s) {
        PlannedShot tried = scoring[i].shot;
        tried.cue = perturbed(tried.cue, options.noise, rng);
        const Trial t = verifier.run(balls, state, tried);
        made += t.judged && t.verdict.scored > 0 ? 1 : 0;
      }
      scoring[i].score = static_cast<double>(made) / options.samples;
    }
  }
  const auto best =
      std::max_element(scoring.begin(), scoring.end(),
                       [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  PlannedShot chosen = best->shot;
  chosen.value = best->score;
  chosen.success = best->score;
  return chosen;
}

}  // namespace pool::bot
