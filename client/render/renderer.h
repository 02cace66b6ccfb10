// Draws a Scene (the table and its dressing, diamonds, pocket liners, ball shadows, numbered
// balls, the cue, the pool hall round the table, lamps, the pocketed-ball trough) with two
// spotlights and Blinn-Phong shading, then the ghost ball and the overlay lines; in the high
// preset anti-aliased, through each lamp's shadow map, with the hall's environment map.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "client/render/ball_trough.h"
#include "client/render/camera.h"
#include "client/render/cue_model.h"
#include "client/render/cue_pose.h"
#include "client/render/diamonds.h"
#include "client/render/environment_map.h"
#include "client/render/lamp_shadow_maps.h"
#include "client/render/mesh.h"
#include "client/render/overlay_lines.h"
#include "client/render/render_options.h"
#include "client/render/scaled_target.h"
#include "client/render/scene.h"
#include "client/render/scene_shading.h"
#include "client/render/shadow_layer.h"

namespace pool::render {

/// What a cue aimed at the ball at `cue_ball` must clear on `scene`'s table: its rails and the
/// other balls on the table.
CueObstacles cueObstaclesOf(const Scene& scene, glm::vec3 cue_ball);

/// GPU resources of one scene; needs a current OpenGL 3.3 core context. Throws
/// std::runtime_error when a shader, the font or the cue mesh cannot be loaded.
class Renderer {
 public:
  explicit Renderer(const Scene& scene);
  /// Replaces the balls (positions and orientations from the latest snapshot). Pocketed balls
  /// are drawn in the trough in the order they were pocketed.
  void setBalls(std::vector<SceneBall> balls);
  void setOptions(const RenderOptions& options);
  const RenderOptions& options() const { return options_; }
  /// Replaces the overlay segments drawn after the scene.
  void setOverlay(std::vector<OverlayLine> lines);
  /// Shows the cue for `aim` (its cue ball is the aim's), or hides it.
  void setCue(std::optional<CueAim> aim);
  /// Shows the outline of a ghost ball centred at `centre` (table frame, m), or hides it.
  void setGhost(std::optional<glm::vec3> centre) { ghost_ = centre; }
  /// The shot's points no lamp shade may hide (the cue ball, the object ball, the pocket; table
  /// frame, m): a shade fades only where it would (lampOpacity). None: every ball on the table.
  void setKeepClear(std::vector<glm::vec3> points) { keep_clear_ = std::move(points); }
  /// What the shades keep clear of: the shot's points, or every ball on the table.
  std::vector<glm::vec3> keepClear() const;

  /// The balls as drawn: pocketed ones moved to their place in the trough, number to the viewer.
  std::vector<SceneBall> drawnBalls() const;
  /// The cue as drawn (after clearing the rails and balls), if shown.
  const std::optional<CuePlacement>& cue() const { return cue_; }
  const std::optional<glm::vec3>& ghost() const { return ghost_; }
  /// The diamonds' centres on the rail tops (table frame, m).
  const std::vector<glm::vec3>& diamonds() const { return diamonds_; }
  /// Clears and draws the scene into the bound framebuffer of size width × height (through a
  /// smaller target stretched onto it when options().scale < 1).
  void draw(const Camera& camera, int width, int height) const;

 private:
  struct Part {
    std::unique_ptr<GpuMesh> mesh;
    glm::vec3 colour;
    int material;
    bool shell = false;  ///< drawn from its front only (the hall's floor, walls and ceiling)
  };
  void placeCue();
  void updateShadows();
  void drawBalls() const;
  void drawDiamonds() const;
  void drawCue(const Camera& camera) const;
  void drawLamps(const Camera& camera, int width, int height) const;
  void drawGhost(const Camera& camera, const glm::mat4& view_projection) const;
  void drawScene(const Camera& camera, int width, int height) const;
  /// Each lamp's shadow map of the table, the balls and the cue (the high preset).
  void renderShadowMaps() const;
  /// The hall, the table and the lamps into the environment map, from over the table's centre.
  void captureEnvironment() const;
  void drawTable() const;  ///< its parts and diamonds
  void drawRoom() const;   ///< the hall round it (when options().room)

  Scene scene_;
  RenderOptions options_;
  BallTrough trough_;
  SceneShading shading_;
  std::vector<Part> parts_;  ///< the table: collision parts, trough, dressing
  std::vector<Part> room_;   ///< the hall round it
  GpuMesh sphere_;
  GpuMesh shade_;
  GpuMesh bulb_;
  GpuMesh diamond_;
  std::vector<glm::vec3> diamonds_;
  RailExtent rails_;
  CueModel cue_model_;
  std::optional<CueAim> cue_aim_;
  std::optional<CuePlacement> cue_;
  std::optional<glm::vec3> ghost_;
  std::vector<glm::vec3> keep_clear_;
  ShadowLayer shadows_;
  OverlayLines overlay_;
  mutable OverlayLines ghost_lines_;
  /// The scene at options_.scale of the framebuffer's size, or multisampled.
  mutable ScaledTarget scaled_;
  mutable std::unique_ptr<LampShadowMaps> shadow_maps_;  ///< made on the first high frame
  mutable std::unique_ptr<EnvironmentMap> environment_;  ///< made on the first high frame
};

}  // namespace pool::render
