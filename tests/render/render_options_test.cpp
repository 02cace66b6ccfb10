// The quality presets: what each sets, the software renderers that get the light one by
// themselves, and the names a player may give.
#include "client/render/render_options.h"

#include <gtest/gtest.h>

namespace pool::render {
namespace {

TEST(RenderOptionsTest, TheLightPresetLowersTheResolutionAndKeepsTheSwitches) {
  RenderOptions switches;
  switches.wireframe = true;
  switches.textures = false;
  const RenderOptions light = withQuality(switches, Quality::Light);
  EXPECT_LT(light.scale, 1.0f);
  EXPECT_GT(light.scale, 0.3f);
  EXPECT_TRUE(light.wireframe);
  EXPECT_FALSE(light.textures);
  EXPECT_TRUE(light.room);
  EXPECT_EQ(withQuality(light, Quality::Full).scale, 1.0f);
}

TEST(RenderOptionsTest, SoftwareRenderersGetTheLightPreset) {
  EXPECT_EQ(qualityFor("llvmpipe (LLVM 15.0.6, 256 bits)"), Quality::Light);
  EXPECT_EQ(qualityFor("softpipe"), Quality::Light);
  EXPECT_EQ(qualityFor("Google SwiftShader"), Quality::Light);
  EXPECT_EQ(qualityFor("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"), Quality::High);
  EXPECT_EQ(qualityFor("NVIDIA GeForce RTX 3060/PCIe/SSE2"), Quality::High);
  EXPECT_EQ(qualityFor(""), Quality::High);
}

TEST(RenderOptionsTest, TheHighPresetSamplesShadowsAndShadesPhysicallyAtFullResolution) {
  RenderOptions switches;
  switches.textures = false;
  const RenderOptions high = withQuality(switches, Quality::High);
  EXPECT_EQ(high.scale, 1.0f);
  EXPECT_EQ(high.samples, kHighSamples);
  EXPECT_GE(high.samples, 4);
  EXPECT_TRUE(high.shadow_maps);
  EXPECT_TRUE(high.physical);
  EXPECT_FALSE(high.textures);
  for (const Quality other : {Quality::Full, Quality::Light}) {
    const RenderOptions back = withQuality(high, other);
    EXPECT_LE(back.samples, 1);
    EXPECT_FALSE(back.shadow_maps);
    EXPECT_FALSE(back.physical);
  }
  EXPECT_STREQ(qualityName(Quality::High), "high");
  EXPECT_STREQ(qualityName(Quality::Full), "full");
  EXPECT_STREQ(qualityName(Quality::Light), "light");
}

TEST(RenderOptionsTest, APlayersSettingOverridesTheRenderersChoice) {
  EXPECT_EQ(resolveQuality(QualitySetting::Auto, "llvmpipe"), Quality::Light);
  EXPECT_EQ(resolveQuality(QualitySetting::Full, "llvmpipe"), Quality::Full);
  EXPECT_EQ(resolveQuality(QualitySetting::Light, "NVIDIA GeForce"), Quality::Light);
  EXPECT_EQ(parseQualitySetting("auto"), QualitySetting::Auto);
  EXPECT_EQ(parseQualitySetting("full"), QualitySetting::Full);
  EXPECT_EQ(parseQualitySetting("light"), QualitySetting::Light);
  EXPECT_EQ(parseQualitySetting("high"), QualitySetting::High);
  EXPECT_EQ(resolveQuality(QualitySetting::High, "llvmpipe"), Quality::High);
  EXPECT_EQ(resolveQuality(QualitySetting::Auto, "NVIDIA GeForce"), Quality::High);
  for (const char* bad : {"", "Full", "High", "light ", "\n"}) {
    EXPECT_FALSE(parseQualitySetting(bad).has_value()) << bad;
  }
}

}  // namespace
}  // namespace pool::render
