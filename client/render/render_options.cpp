// Quality presets and the software renderer's detection.
#include "client/render/render_options.h"

namespace pool::render {

RenderOptions withQuality(RenderOptions options, Quality quality) {
  options.scale = quality == Quality::Light ? kLightScale : 1.0f;
  return options;
}

Quality qualityFor(const std::string& gl_renderer) {
  for (const char* software : {"llvmpipe", "softpipe", "swrast", "SwiftShader"}) {
    if (gl_renderer.find(software) != std::string::npos) return Quality::Light;
  }
  return Quality::Full;
}

std::optional<QualitySetting> parseQualitySetting(const std::string& name) {
  if (name == "auto") return QualitySetting::Auto;
  if (name == "full") return QualitySetting::Full;
  if (name == "light") return QualitySetting::Light;
  return std::nullopt;
}

Quality resolveQuality(QualitySetting setting, const std::string& gl_renderer) {
  if (setting == QualitySetting::Full) return Quality::Full;
  if (setting == QualitySetting::Light) return Quality::Light;
  return qualityFor(gl_renderer);
}

}  // namespace pool::render
