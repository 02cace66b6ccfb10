// Impacts read off 60 Hz frames of real shots agree with the physics' own event log.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "audio/shots.h"
#include "client/audio/frame_impacts.h"
#include "physics/contact_models.h"
#include "table/table_spec.h"

namespace pool::audio {
namespace {

using physics::EventLog;
using physics::EventType;

constexpr double kFrame = 1.0 / 60.0;

/// A scene run with 60 Hz frames, and the events read off those frames.
struct FramedShot {
  physics::ShotOutcome outcome;
  EventLog inferred;
};

FramedShot frameShot(const std::string& scene) {
  FramedShot shot{test::framedShot(scene), {}};
  FrameImpacts impacts;
  for (const auto& frame : shot.outcome.trajectory) {
    const auto events = impacts.onFrame(frame.balls, frame.t);
    shot.inferred.insert(shot.inferred.end(), events.begin(), events.end());
  }
  return shot;
}

std::vector<physics::Event> ofType(const EventLog& log, EventType type) {
  std::vector<physics::Event> out;
  std::copy_if(log.begin(), log.end(), std::back_inserter(out),
               [&](const physics::Event& e) { return e.type == type; });
  return out;
}

/// The least horizontal rebound ratio r = −v_n,out / v_n,in of `spec`'s cushion model over what a
/// break brings to a cushion: incidence 0–80° from the normal, backspin through stun to natural
/// roll, 0.1–6 m/s on the slate (the model itself, as the physics resolves each contact).
double leastRebound(const table::TableSpec& spec) {
  const auto models = physics::makeContactModels(spec.models, spec.params);
  if (!models) throw std::runtime_error(models.error());
  const double R = spec.params.ball_radius;
  const double sin_theta = (spec.params.cushion_height - R) / R;
  const physics::Vec3 normal(0.0, -std::sqrt(1.0 - sin_theta * sin_theta), -sin_theta);
  double least = 1.0;
  for (double incidence = 0.0; incidence <= 80.0; incidence += 5.0) {
    for (double roll : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
      for (double speed : {0.1, 0.5, 1.0, 2.0, 4.0, 6.0}) {
        const double a = incidence * M_PI / 180.0;
        physics::Vec3 v(speed * std::sin(a), speed * std::cos(a), 0.0);
        physics::Vec3 w(-v.y() / R * roll, v.x() / R * roll, 0.0);
        const double in = v.y();
        models->cushion->resolve(v, w, normal, spec.params.e_c, true);
        least = std::min(least, -v.y() / in);
      }
    }
  }
  return least;
}

TEST(FrameImpacts, AStraightPotReadsAsStrikeClickAndDropInTime) {
  const auto shot = frameShot("straight_pocket");
  const auto strikes = ofType(shot.inferred, EventType::Strike);
  const auto true_strike = ofType(shot.outcome.events, EventType::Strike);
  ASSERT_EQ(strikes.size(), 1u);
  ASSERT_EQ(true_strike.size(), 1u);
  EXPECT_EQ(strikes[0].t, 0.0);
  // The first frame is the table at t = 0, just after the strike: the cue ball's velocity there
  // is the strike's (1e-9: the same number through a frame).
  EXPECT_NEAR(strikes[0].speed, true_strike[0].speed, 1e-9);

  const auto clicks = ofType(shot.inferred, EventType::BallBall);
  const auto true_clicks = ofType(shot.outcome.events, EventType::BallBall);
  ASSERT_EQ(clicks.size(), 1u);
  ASSERT_EQ(true_clicks.size(), 1u);
  EXPECT_NEAR(clicks[0].t, true_clicks[0].t, kFrame);
  // The click's closing speed is read from the frame before the contact, when the sliding cue
  // ball (2.3 m/s stunned 0.11 s before: it slides for 2 v / (7 u_s g) = 0.34 s) was faster by
  // what the cloth took since, at most u_s g over one frame (0.033 m/s), and never slower.
  const double cloth = 0.2 * physics::kGravity * kFrame;
  EXPECT_GE(clicks[0].speed, true_clicks[0].speed - 1e-9);
  EXPECT_LE(clicks[0].speed, true_clicks[0].speed + cloth);
  EXPECT_EQ(std::set<int>({clicks[0].ball_a, clicks[0].ball_b}), std::set<int>({0, 1}));

  const auto drops = ofType(shot.inferred, EventType::Pocket);
  const auto true_drops = ofType(shot.outcome.events, EventType::Pocket);
  ASSERT_EQ(drops.size(), 1u);
  ASSERT_EQ(true_drops.size(), 1u);
  EXPECT_EQ(drops[0].ball_a, 1);
  EXPECT_NEAR(drops[0].t, true_drops[0].t, kFrame);
}

/// Whether time `t` falls in the frame interval ending at frame `i` (1e-6 s either side: an
/// event on a frame's own time may be read in the frame before or after it).
bool inInterval(const std::vector<physics::Sample>& frames, std::size_t i, double t) {
  return t > frames[i - 1].t - 1e-6 && t <= frames[i].t + 1e-6;
}

/// The frame interval (index of its closing frame) a heard event was read in: a heard event is
/// stamped inside it (a thump half a frame back from the frame that showed it).
std::size_t intervalOfHeard(const std::vector<physics::Sample>& frames, double t) {
  std::size_t i = 1;
  while (i + 1 < frames.size() && frames[i].t <= t) ++i;
  return i;
}

TEST(FrameImpacts, ABreakReadsWithItsFirstClickAndEveryDrop) {
  const auto shot = frameShot("break");
  const auto clicks = ofType(shot.inferred, EventType::BallBall);
  const auto true_clicks = ofType(shot.outcome.events, EventType::BallBall);
  ASSERT_FALSE(clicks.empty());
  EXPECT_NEAR(clicks.front().t, true_clicks.front().t, kFrame);

  // Thumps, one against one with the physics' cushion contacts. A frame interval's cushion
  // contact jolts the ball by |Δv| ≥ (1 + r) v_n, r the horizontal rebound ratio, at least the
  // cushion model's least over what a break brings (leastRebound: 0.76), v_n = v / cos θ the
  // horizontal normal speed of the physics' nose speed v (cos θ = 0.963, nose at 1.27 R), less
  // what the cloth does over the frame (u_s g dt = 0.033 m/s, sliding). FrameImpacts hears a jolt
  // beyond 0.25 g dt + min_dv = 0.091 m/s: every contact of v > 0.963 (0.091 + 0.033) / 1.76 =
  // 0.068 m/s is heard, in its own frame interval, unless its ball also met a ball there (then it
  // may be paired with that ball).
  const auto& frames = shot.outcome.trajectory;
  const auto spec = table::loadTableSpec("wpa-9ft");  // the break scene's table
  ASSERT_TRUE(spec) << spec.error();
  ASSERT_EQ(spec->params.u_s, 0.2);
  ASSERT_NEAR(spec->params.cushion_height, 1.27 * spec->params.ball_radius, 1e-9);
  const FrameImpactOptions detector;
  const double dt = kFrame;
  const double least = leastRebound(*spec);
  const double heard_from = 0.963 *
                            (0.25 * physics::kGravity * dt + detector.min_dv +
                             spec->params.u_s * physics::kGravity * dt) /
                            (1.0 + least);
  ASSERT_NEAR(heard_from, 0.068, 0.001);
  // The derivation holds for a ball on the slate: the break has no ball in the air.
  ASSERT_TRUE(ofType(shot.outcome.events, EventType::Airborne).empty());
  const auto thumps = ofType(shot.inferred, EventType::BallCushion);
  const auto true_thumps = ofType(shot.outcome.events, EventType::BallCushion);
  // Ball–ball contacts of ball `id` in the frame interval ending at frame `i`.
  const auto contactsIn = [&](std::size_t i, int id) {
    std::vector<physics::Event> out;
    for (const auto& c : true_clicks) {
      if ((c.ball_a == id || c.ball_b == id) && inInterval(frames, i, c.t)) out.push_back(c);
    }
    return out;
  };
  const auto heardIn = [&](std::size_t i, int id) {
    return std::count_if(thumps.begin(), thumps.end(), [&](const physics::Event& h) {
      return h.ball_a == id && intervalOfHeard(frames, h.t) == i;
    });
  };
  std::size_t must = 0;
  for (const auto& c : true_thumps) {
    if (c.speed <= heard_from) continue;
    std::size_t i = 1;
    while (i + 1 < frames.size() && !inInterval(frames, i, c.t)) ++i;
    ASSERT_TRUE(inInterval(frames, i, c.t)) << "cushion contact at " << c.t << " past the frames";
    if (!contactsIn(i, c.ball_a).empty()) continue;
    ++must;
    EXPECT_EQ(heardIn(i, c.ball_a), 1) << "ball " << c.ball_a << " at " << c.t << " s, " << c.speed
                                       << " m/s on " << c.where << ": not heard once";
  }
  EXPECT_GE(must, 10u) << "too few clear cushion contacts in the break to judge";
  // Every thump is a cushion contact of its ball in its frame interval, or a ball the detector
  // could leave without a partner: one of three or more balls meeting in one frame (the ball
  // met two, or its partner met another), which FrameImpacts pairs one pair a ball. A rack's
  // chain (touching balls jolted together) and a two-ball contact are never taken for cushions.
  for (const auto& h : thumps) {
    const std::size_t i = intervalOfHeard(frames, h.t);
    const bool cushion = std::any_of(true_thumps.begin(), true_thumps.end(), [&](const auto& c) {
      return c.ball_a == h.ball_a && inInterval(frames, i, c.t);
    });
    const auto contacts = contactsIn(i, h.ball_a);
    bool crowded = contacts.size() >= 2;
    for (const auto& c : contacts) {
      const int other = c.ball_a == h.ball_a ? c.ball_b : c.ball_a;
      crowded = crowded || contactsIn(i, other).size() >= 2;
    }
    EXPECT_TRUE(cushion || crowded)
        << "thump of ball " << h.ball_a << " at " << h.t << " s with no cushion contact of it";
  }

  // Clicks: several contacts of one ball inside one frame cannot all be told apart (FrameImpacts
  // pairs one partner a ball a frame), but a contact whose two balls meet nothing else in its
  // frame interval is heard, once, as that pair in that interval.
  std::size_t clear = 0;
  for (const auto& c : true_clicks) {
    std::size_t i = 1;
    while (i + 1 < frames.size() && !inInterval(frames, i, c.t)) ++i;
    ASSERT_TRUE(inInterval(frames, i, c.t)) << "contact at " << c.t << " past the frames";
    if (contactsIn(i, c.ball_a).size() != 1 || contactsIn(i, c.ball_b).size() != 1) continue;
    ++clear;
    const auto pair = std::set<int>{c.ball_a, c.ball_b};
    const auto heard = std::count_if(clicks.begin(), clicks.end(), [&](const physics::Event& h) {
      return std::set<int>{h.ball_a, h.ball_b} == pair && inInterval(frames, i, h.t);
    });
    EXPECT_EQ(heard, 1) << "balls " << c.ball_a << " and " << c.ball_b << " at " << c.t << " s, "
                        << c.speed << " m/s: not heard once";
  }
  EXPECT_GE(clear, 10u) << "too few clear contacts in the break to judge";

  std::multiset<int> dropped, true_dropped;
  for (const auto& e : ofType(shot.inferred, EventType::Pocket)) dropped.insert(e.ball_a);
  for (const auto& e : ofType(shot.outcome.events, EventType::Pocket))
    true_dropped.insert(e.ball_a);
  EXPECT_EQ(dropped, true_dropped);
  EXPECT_TRUE(std::is_sorted(shot.inferred.begin(), shot.inferred.end(),
                             [](const auto& a, const auto& b) { return a.t < b.t; }));
}

TEST(FrameImpacts, CushionsAreHeardInACushionShot) {
  const auto shot = frameShot("bank");
  EXPECT_EQ(ofType(shot.inferred, EventType::Pocket).size(), 1u);  // at rest: the final frame
  const auto thumps = ofType(shot.inferred, EventType::BallCushion);
  const auto true_thumps = ofType(shot.outcome.events, EventType::BallCushion);
  ASSERT_FALSE(true_thumps.empty());
  ASSERT_FALSE(thumps.empty());
  EXPECT_NEAR(thumps.front().t, true_thumps.front().t, kFrame);
  // The heard speed is the frame-to-frame |Δv| / (1 + 0.75) (FrameImpactOptions); the physics'
  // speed is the closing speed along the nose's normal, cos θ = 0.963 of the horizontal normal
  // speed v_n (nose at 1.27 R: sin θ = 0.27). Head-on, |Δv| is (1 + r) v_n with r the horizontal
  // rebound ratio, between the cushion model's least (leastRebound: 0.76; 0.80 for a ball rolling
  // in head-on, the published Mathavan rebound of CushionMathavan) and e_c = 0.85, the frictionless
  // ceiling: (1 + r) / (1.75 · 0.963) = 1.04–1.10 of the physics' speed. The cloth's pull over one
  // frame (u_s g / 60 = 0.033 m/s) and the small change along the cushion move it by under 3 % of
  // a 1.7 m/s impact either way.
  const auto spec = table::loadTableSpec("wpa-9ft");  // the bank scene's table
  ASSERT_TRUE(spec) << spec.error();
  ASSERT_EQ(spec->params.e_c, 0.85);
  ASSERT_EQ(spec->params.u_s, 0.2);
  ASSERT_NEAR(spec->params.cushion_height, 1.27 * spec->params.ball_radius, 1e-9);
  const FrameImpactOptions detector;
  const double lowest =
      (1.0 + leastRebound(*spec)) / ((1.0 + detector.cushion_restitution) * 0.963);
  const double highest = (1.0 + spec->params.e_c) / ((1.0 + detector.cushion_restitution) * 0.963);
  const double heard = thumps.front().speed / true_thumps.front().speed;
  EXPECT_GT(heard, lowest - 0.03);
  EXPECT_LT(heard, highest + 0.03);
}

TEST(FrameImpacts, ALateFirstFrameGivesNoStrikeAndOldFramesGiveNothing) {
  const auto shot = frameShot("straight_pocket");
  const auto& frames = shot.outcome.trajectory;
  ASSERT_GT(frames.size(), 30u);
  FrameImpacts late;
  EXPECT_TRUE(late.onFrame(frames[20].balls, frames[20].t).empty());
  EXPECT_TRUE(late.onFrame(frames[10].balls, frames[10].t).empty());  // out of order
  EXPECT_TRUE(late.onFrame(frames[20].balls, frames[20].t).empty());  // repeated
  FrameImpacts fresh;
  EXPECT_EQ(fresh.onFrame(frames[0].balls, frames[0].t).size(), 1u);
  fresh.reset();
  EXPECT_EQ(fresh.onFrame(frames[0].balls, frames[0].t).size(), 1u);
}

}  // namespace
}  // namespace pool::audio
