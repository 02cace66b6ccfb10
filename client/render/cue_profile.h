// The cue's shape as a lathe profile: rings along its axis from the tip to the butt, each part
// (tip, ferrule, shaft, joint, forearm, wrap, sleeve, bumper) a run of rings. Pure (no GL).
#pragma once

#include <string>
#include <vector>

namespace pool::render {

/// One ring of the profile: `along` metres from the tip toward the butt, `radius` metres.
struct CueRing {
  double along = 0.0;
  double radius = 0.0;
};

/// A part of the cue: its name (the OBJ object's) and its rings, in order from the tip.
struct CuePart {
  std::string name;
  std::vector<CueRing> rings;
};

/// The cue: a 1.47 m (58 in) two-piece cue with a 13 mm tip, a pro-taper maple shaft, a linen
/// wrap and a rubber bumper. Consecutive parts share their boundary ring's position.
const std::vector<CuePart>& cueProfile();

/// The cue's length from tip to bumper, m.
double cueLength();

/// The cue's radius `along` metres from the tip (0 outside the cue), m.
double cueRadiusAt(double along);

/// The cue as a Wavefront OBJ: one `o` object per part, `segments` facets around the axis,
/// smooth normals (`vn`); the tip's face at the origin, the axis along +x toward the butt, the
/// butt's end closed. The output is byte-identical for the same arguments.
std::string cueObj(int segments);

}  // namespace pool::render
