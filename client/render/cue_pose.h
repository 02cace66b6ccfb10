// Where the cue is drawn: its tip at the point the physics strikes (the offset line a·R, b·R from
// the cue ball's centre), drawn back with the power, and raised (for drawing only) until it clears
// the cushions, the rails and the other balls. Pure (no GL).
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace pool::render {

/// The shot as aimed (the physics' CueShot, plus the power bar). Angles in radians.
struct CueAim {
  glm::vec3 cue_ball{0.0f};  ///< the cue ball's centre, table frame, m
  float yaw = 0.0f;          ///< heading of the cue in the table plane, 0 = +x
  float tip_side = 0.0f;     ///< a: offset right of centre seen from behind, fraction of R
  float tip_height = 0.0f;   ///< b: offset above centre, perpendicular to the cue, fraction of R
  float elevation = 0.0f;    ///< cue above horizontal, [0, 89°]
  float power = 0.0f;  ///< 0–1: how far the cue is drawn back; down to kFollowThrough: pushed
                       ///< through past the struck point (the stroke after release)
};

/// What the cue must stay clear of (table frame, m).
struct CueObstacles {
  float half_length = 0.0f;  ///< playing surface: |x| up to this, m
  float half_width = 0.0f;   ///< |y| up to this, m
  float rail_outer = 0.0f;   ///< cushion + rail beyond the nose lines, m
  float rail_top = 0.0f;     ///< height of the cushion and rail tops above the slate, m
  float ball_radius = 0.0f;
  std::vector<glm::vec3> balls;  ///< centres of the other balls on the table
};

/// The cue as drawn.
struct CuePlacement {
  glm::vec3 tip{0.0f};                  ///< centre of the tip's face, m
  glm::vec3 butt{0.0f};                 ///< centre of the butt's end, m
  glm::vec3 forward{1.0f, 0.0f, 0.0f};  ///< unit, from the butt toward the tip
  float drawn_elevation = 0.0f;         ///< rad; the aim's elevation, or more where blocked
};

/// How far the cue is drawn back at full power, m.
inline constexpr float kMaxDrawBack = 0.22f;
/// The stroke's end: the tip this share of kMaxDrawBack past the struck point.
inline constexpr float kFollowThrough = -0.15f;
/// The stroke after release: the cue goes forward from the power at release to the follow-through
/// in kStrokeForward seconds, stays there until kStrokeEnd, then is gone.
inline constexpr float kStrokeForward = 0.10f;
inline constexpr float kStrokeEnd = 0.35f;

/// The cue's power (draw-back) `seconds` after a release at `released` (0–1); below 0 when
/// pushed through; NaN once the stroke is over.
float strokePower(float released, float seconds);

/// The point where the physics' cue line first meets the cue ball of radius `radius` (m), and the
/// cue's unit direction toward the ball (common/physics/cue_strike.cpp's frame).
glm::vec3 struckPoint(const CueAim& aim, float radius);
glm::vec3 cueDirection(float yaw, float elevation);

/// The cue for `aim`: its line through the struck point along the aim's direction, tilted up about
/// that point in 0.5° steps until the cue, drawn back along its line by the power, clears
/// `obstacles` (at most to 89°).
CuePlacement placeCue(const CueAim& aim, const CueObstacles& obstacles);

/// How opaque the cue is drawn for an eye at `eye`: 1, down to 0.3 as the eye comes within
/// 0.09 m of the cue's axis (a cue passing by the camera would fill the view).
float cueOpacity(const CuePlacement& cue, glm::vec3 eye);

}  // namespace pool::render
