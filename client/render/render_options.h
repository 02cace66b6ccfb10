// The drawing's switches (the client's P, T and L keys) and its quality presets: a high one for
// graphics cards, the full one, and a light one for software OpenGL (Mesa's llvmpipe), which
// renders on the CPU.
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
  /// Samples a pixel of the 3-D scene (multisampled anti-aliasing); 0 or 1: one.
  int samples = 0;
  /// Each lamp's light is shadowed through its own depth map (soft edges) instead of the balls'
  /// and the cue's projected shadows.
  bool shadow_maps = false;
  /// Lighting in linear space with tone mapping, the balls' clear coat reflecting the hall and
  /// the lamps, cloth with a weave and nap, varnished wood, leather pockets.
  bool physical = false;
};

/// Quality presets: `high` draws the hall as a graphics card can (kHighSamples samples a pixel,
/// shadow maps, physical shading); `full` draws everything at full resolution; `light` draws the
/// full preset's scene at kLightScale of the resolution, which keeps a software renderer within
/// its frame budget.
enum class Quality { Full, Light, High };
inline constexpr float kLightScale = 0.6f;
inline constexpr int kHighSamples = 4;

/// `options` with the preset's settings (the switches stay).
RenderOptions withQuality(RenderOptions options, Quality quality);

/// The preset for an OpenGL renderer string (GL_RENDERER): light for a software renderer
/// (llvmpipe, softpipe, swrast, SwiftShader), high otherwise.
Quality qualityFor(const std::string& gl_renderer);

/// A player's setting: a preset, or the one qualityFor picks.
enum class QualitySetting { Auto, Full, Light, High };

/// "auto", "full", "light" or "high"; nullopt for anything else.
std::optional<QualitySetting> parseQualitySetting(const std::string& name);

/// The preset `setting` means on the renderer `gl_renderer`.
Quality resolveQuality(QualitySetting setting, const std::string& gl_renderer);

/// The preset's name: "full", "light" or "high".
const char* qualityName(Quality quality);

}  // namespace pool::render
