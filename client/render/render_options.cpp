// Quality presets and the software renderer's detection.
#include "client/render/render_options.h"

namespace pool::render {

RenderOptions withQuality(RenderOptions options, Quality quality) {
  options.scale = quality == Quality::Light ? kLightScale : 1.0f;
  const bool high = quality == Quality::High;
  options.samples = high ? kHighSamples : 0;
  options.shadow_maps = high;
  options.physical = high;
  return options;
}

Quality qualityFor(const std::string& gl_renderer) {
  for (const char* software : {"llvmpipe", "softpipe", "swrast", "SwiftShader"}) {
    if (gl_renderer.find(software) != std::string::npos) return Quality::Light;
  }
  return Quality::High;
}

std::optional<QualitySetting> parseQualitySetting(const std::string& name) {
  if (name == "auto") return QualitySetting::Auto;
  if (name == "full") return QualitySetting::Full;
  if (name == "light") return QualitySetting::Light;
  if (name == "high") return QualitySetting::High;
  return std::nullopt;
}

Quality resolveQuality(QualitySetting setting, const std::string& gl_renderer) {
  switch (setting) {
    case QualitySetting::Full:
      return Quality::Full;
    case QualitySetting::Light:
      return Quality::Light;
    case QualitySetting::High:
      return Quality::High;
    case QualitySetting::Auto:
      break;
  }
  return qualityFor(gl_renderer);
}

const char* qualityName(Quality quality) {
  switch (quality) {
    case Quality::Light:
      return "light";
    case Quality::High:
      return "high";
    case Quality::Full:
      break;
  }
  return "full";
}

}  // namespace pool::render
