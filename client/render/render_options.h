// The drawing's switches (the client's P, T and L keys) and its quality presets: the full one,
// and a light one for software OpenGL (Mesa's llvmpipe), which renders on the CPU.
#pragma once

#include <optional>
#include <string>

namespace pool::render {

/// Switches of the drawing.
struct RenderOptions {
  bool wireframe = false;  ///< polygons as lines
  bool textures = true;    ///< ball numbers, felt and wood grain (off: flat colours)
  bool lighting = true;    ///< spotlights (off: unlit colours)
  bool room = true;        ///< the hall round the table (off: the table in the dark)
  /// The 3-D scene's resolution as a share of the framebuffer's (stretched onto it); the HUD
  /// drawn after it keeps the full resolution.
  float scale = 1.0f;
};

/// Quality presets: `full` draws everything at full resolution; `light` draws the same scene at
/// kLightScale of the resolution, which keeps a software renderer within its frame budget.
enum class Quality { Full, Light };
inline constexpr float kLightScale = 0.6f;

/// `options` with the preset's settings (the switches stay).
RenderOptions withQuality(RenderOptions options, Quality quality);

/// The preset for an OpenGL renderer string (GL_RENDERER): light for a software renderer
/// (llvmpipe, softpipe, swrast, SwiftShader), full otherwise.
Quality qualityFor(const std::string& gl_renderer);

/// A player's setting: a preset, or the one qualityFor picks.
enum class QualitySetting { Auto, Full, Light };

/// "auto", "full" or "light"; nullopt for anything else.
std::optional<QualitySetting> parseQualitySetting(const std::string& name);

/// The preset `setting` means on the renderer `gl_renderer`.
Quality resolveQuality(QualitySetting setting, const std::string& gl_renderer);

}  // namespace pool::render
