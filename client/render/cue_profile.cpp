// The cue's lathe profile and its OBJ text.
#include "client/render/cue_profile.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

namespace pool::render {

namespace {

/// Formats a number for the OBJ file (fixed decimals: the same text on every machine).
std::string num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6f", std::abs(v) < 5e-7 ? 0.0 : v);
  return text;
}

/// A ring's normal in the profile's plane (axial, radial parts; unit): perpendicular to the
/// profile between its neighbours, so a widening profile leans toward the tip and the closed
/// butt end faces along the axis.
std::pair<double, double> normalAt(const std::vector<CueRing>& rings, std::size_t i) {
  const std::size_t a = i == 0 ? 0 : i - 1;
  const std::size_t b = i + 1 < rings.size() ? i + 1 : rings.size() - 1;
  const double d_along = rings[b].along - rings[a].along;
  const double d_radius = rings[b].radius - rings[a].radius;
  const double norm = std::hypot(d_along, d_radius);
  if (norm <= 0.0) return {0.0, 1.0};
  return {-d_radius / norm, d_along / norm};
}

}  // namespace

const std::vector<CuePart>& cueProfile() {
  static const std::vector<CuePart> parts{
      // A domed, chalked leather tip of 13 mm.
      {"tip", {{0.0, 0.0}, {0.0004, 0.0040}, {0.0015, 0.0058}, {0.0035, 0.0064}, {0.012, 0.0064}}},
      {"ferrule", {{0.012, 0.0064}, {0.037, 0.0065}}},
      // Pro taper: nearly straight for 30 cm, then opening out to the joint.
      {"shaft", {{0.037, 0.0065}, {0.34, 0.0067}, {0.55, 0.0085}, {0.735, 0.0106}}},
      {"joint", {{0.735, 0.0108}, {0.760, 0.0108}}},
      {"forearm", {{0.760, 0.0110}, {1.000, 0.0127}}},
      {"wrap", {{1.000, 0.0130}, {1.250, 0.0138}}},
      {"sleeve", {{1.250, 0.0139}, {1.450, 0.0150}}},
      {"bumper", {{1.450, 0.0148}, {1.466, 0.0146}, {1.470, 0.0120}, {1.470, 0.0}}},
  };
  return parts;
}

double cueLength() {
  return cueProfile().back().rings.back().along;
}

double cueRadiusAt(double along) {
  for (const CuePart& part : cueProfile()) {
    const auto& r = part.rings;
    for (std::size_t i = 1; i < r.size(); ++i) {
      if (along < r[i - 1].along || along > r[i].along) continue;
      const double span = r[i].along - r[i - 1].along;
      const double t = span > 0.0 ? (along - r[i - 1].along) / span : 1.0;
      return r[i - 1].radius + t * (r[i].radius - r[i - 1].radius);
    }
  }
  return 0.0;
}

std::string cueObj(int segments) {
  std::string out = "# pool cue: tip at the origin, axis along +x toward the butt, metres\n";
  int base = 1;  // OBJ indices start at 1 and run on across objects
  for (const CuePart& part : cueProfile()) {
    out += "o " + part.name + "\n";
    const auto& rings = part.rings;
    for (std::size_t i = 0; i < rings.size(); ++i) {
      const auto [axial, radial] = normalAt(rings, i);
      for (int s = 0; s < segments; ++s) {
        const double phi = 2.0 * std::numbers::pi * s / segments;
        const double c = std::cos(phi), sn = std::sin(phi);
        out += "v " + num(rings[i].along) + " " + num(rings[i].radius * c) + " " +
               num(rings[i].radius * sn) + "\n";
        out += "vn " + num(axial) + " " + num(radial * c) + " " + num(radial * sn) + "\n";
      }
    }
    for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
      for (int s = 0; s < segments; ++s) {
        const int a = base + static_cast<int>(i) * segments + s;
        const int b = base + static_cast<int>(i) * segments + (s + 1) % segments;
        const int c = a + segments, d = b + segments;
        const auto f = [](int x) { return std::to_string(x) + "//" + std::to_string(x); };
        out += "f " + f(a) + " " + f(b) + " " + f(d) + "\n";
        out += "f " + f(a) + " " + f(d) + " " + f(c) + "\n";
      }
    }
    base += static_cast<int>(rings.size()) * segments;
  }
  return out;
}

}  // namespace pool::render
