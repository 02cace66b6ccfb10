// The cue's profile and mesh: a cue's proportions, and the committed OBJ is what the generator
// writes (regenerate with build/bin/pool-cuegen -o assets/cue/cue.obj).
#include "client/render/cue_profile.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "client/render/cue_model.h"

namespace pool::render {
namespace {

TEST(CueProfileTest, ProportionsOfAPoolCue) {
  EXPECT_NEAR(cueLength(), 1.47, 0.01);                 // 58 in
  EXPECT_NEAR(2 * cueRadiusAt(0.005), 0.013, 0.0005);   // a 13 mm tip
  EXPECT_GT(cueRadiusAt(1.4), 2.0 * cueRadiusAt(0.1));  // tapered: the butt twice the shaft
  // Never narrower toward the butt, past the tip's dome.
  for (double s = 0.004; s + 0.01 < cueLength() - 0.02; s += 0.01) {
    EXPECT_GE(cueRadiusAt(s + 0.01), cueRadiusAt(s) - 0.0003) << "at " << s;
  }
}

TEST(CueProfileTest, CommittedMeshIsTheGeneratorsOutputAndLoadsThroughAssimp) {
  std::ifstream in(std::string(POOL_SOURCE_DIR) + "/assets/cue/cue.obj");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), cueObj(20)) << "regenerate: build/bin/pool-cuegen -o assets/cue/cue.obj";
  const auto parts = loadCueAsset();
  ASSERT_TRUE(static_cast<bool>(parts)) << parts.error();
  std::vector<std::string> names;
  for (const auto& p : *parts) {
    names.push_back(p.name);
    EXPECT_FALSE(p.mesh.positions.empty()) << p.name;
    EXPECT_EQ(p.mesh.positions.size(), p.mesh.normals.size()) << p.name;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"tip", "ferrule", "shaft", "joint", "forearm", "wrap",
                                             "sleeve", "bumper"}));
}

}  // namespace
}  // namespace pool::render
