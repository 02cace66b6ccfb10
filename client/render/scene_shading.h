// The scene's shading, shared by the table scene and the Magic Eight Ball room: one program per
// material (and the high preset's set, made on its first frame), the number atlas and the noise
// texture, two spotlights and their shadow maps, the P/T/L switches.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "client/render/chalk_marks.h"
#include "client/render/mesh.h"
#include "client/render/palette.h"
#include "client/render/shader.h"
#include "client/render/texture.h"

namespace pool::render {

struct Camera;
struct RenderOptions;

/// Two spotlights pointing straight down (table frame, m).
struct SpotLights {
  std::array<glm::vec3, 2> positions;
  float inner_deg = 30.0f;  ///< full light inside this half-angle
  float outer_deg = 62.0f;  ///< none beyond this one
  /// Each light's shadow map's light matrix (LampShadowMaps), when its maps are bound to
  /// shaders::kShadowUnit0 and kShadowUnit1 (the high preset).
  std::optional<std::array<glm::mat4, 2>> shadow_matrices;
};

/// Needs a current OpenGL 3.3 core context; throws std::runtime_error when a shader or the font
/// cannot be loaded.
class SceneShading {
 public:
  /// The ambient light's share of the albedo, set by beginFrame.
  static constexpr float kAmbient = 0.22f;

  SceneShading();

  /// Clears the bound width × height framebuffer to `background`, sets the depth test and the
  /// polygon mode (wireframe), binds the textures and sets every program's per-frame uniforms.
  /// With options.physical the frame is drawn by the high preset's programs, which read the
  /// environment map bound to shaders::kEnvironmentUnit.
  void beginFrame(const Camera& camera, int width, int height, glm::vec3 background,
                  const SpotLights& lights, const RenderOptions& options) const;
  /// Changes the ambient light's share (kAmbient after beginFrame); the trough under the rail
  /// has its own light, so its balls are drawn with more.
  void setAmbient(float ambient) const;
  /// Back to filled polygons (for whatever is drawn next: overlay, HUD).
  void endFrame() const;
  /// Draws `mesh` with `model` (mesh → table frame) in a material (shaders::Material).
  void draw(const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour, int material,
            float specular) const;
  /// Draws `mesh` with opacity `alpha` (blending is the caller's to enable).
  void drawFaded(const GpuMesh& mesh, const glm::mat4& model, glm::vec3 colour, int material,
                 float alpha) const;
  /// Sets the marks the marked felt draws (kept until set again).
  void setChalkMarks(const ChalkMarks& marks) const;
  /// Draws a ball: `model` includes its orientation and radius; `look` its colour and number.
  void drawBall(const GpuMesh& sphere, const glm::mat4& model, const BallLook& look) const;

 private:
  using Programs = std::vector<std::unique_ptr<ShaderProgram>>;  ///< one per shaders::Material
  const ShaderProgram& program(int material) const;
  const Programs& active() const { return high_ ? high_programs_ : programs_; }
  void applyChalkMarks(const Programs& programs) const;

  Programs programs_;
  mutable Programs high_programs_;  ///< made on the first high frame
  mutable bool high_ = false;       ///< the frame begun is the high preset's
  mutable std::optional<ChalkMarks> marks_;
  GpuTexture numbers_;
  GpuTexture noise_;
};

}  // namespace pool::render
