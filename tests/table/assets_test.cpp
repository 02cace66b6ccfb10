// Asset lookup from any working directory, installed and build-tree layouts, $POOL_ASSETS.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "table/assets.h"
#include "table/table_spec.h"

namespace pool::table {
namespace {

namespace fs = std::filesystem;

/// Runs the test body from another working directory and restores the old one.
class InOtherDirectory : public ::testing::Test {
 protected:
  void SetUp() override {
    saved_ = fs::current_path();
    fs::current_path(fs::temp_directory_path());
    if (const char* env = std::getenv("POOL_ASSETS")) saved_env_ = env;
    ::unsetenv("POOL_ASSETS");
  }
  void TearDown() override {
    fs::current_path(saved_);
    if (saved_env_) ::setenv("POOL_ASSETS", saved_env_->c_str(), 1);
  }

 private:
  fs::path saved_;
  std::optional<std::string> saved_env_;
};

TEST_F(InOtherDirectory, FindsTheShippedAssets) {
  const fs::path dir = assetsDir();
  EXPECT_TRUE(fs::exists(dir / "tables" / "wpa-9ft.json")) << dir;
  EXPECT_TRUE(dir.is_absolute()) << dir;
  const auto spec = findAsset("tables/wpa-9ft.json");
  ASSERT_TRUE(spec.has_value());
  EXPECT_TRUE(
      fs::equivalent(*spec, fs::path(POOL_SOURCE_DIR) / "assets" / "tables" / "wpa-9ft.json"));
  EXPECT_FALSE(findAsset("tables/no-such-table.json").has_value());
  const auto loaded = loadTableSpec("wpa-7ft");
  EXPECT_TRUE(loaded) << loaded.error();
}

TEST_F(InOtherDirectory, EnvironmentOverrides) {
  const fs::path fake = fs::temp_directory_path() / "pool_assets_override";
  fs::create_directories(fake / "tables");
  ::setenv("POOL_ASSETS", fake.c_str(), 1);
  EXPECT_EQ(assetsDir(), fake);
  EXPECT_FALSE(findAsset("tables/wpa-9ft.json").has_value());
  EXPECT_FALSE(loadTableSpec("wpa-9ft"));
  ::unsetenv("POOL_ASSETS");
  fs::remove_all(fake);
  EXPECT_TRUE(findAsset("tables/wpa-9ft.json").has_value());
}

TEST(AssetsBesideProgram, FindsInstalledAndBuildTreeLayouts) {
  const fs::path root = fs::temp_directory_path() / "pool_assets_layouts";
  fs::remove_all(root);
  // Installed: <prefix>/bin/pool-server reads <prefix>/share/pool/tables/...
  fs::create_directories(root / "usr" / "bin");
  fs::create_directories(root / "usr" / "share" / "pool" / "tables");
  EXPECT_EQ(assetsBesideProgram(root / "usr" / "bin"), root / "usr" / "share" / "pool");
  // A build tree inside the checkout: <src>/build/bin reads <src>/assets/tables/...
  fs::create_directories(root / "src" / "build" / "bin");
  fs::create_directories(root / "src" / "assets" / "tables");
  EXPECT_EQ(assetsBesideProgram(root / "src" / "build" / "bin"), root / "src" / "assets");
  // A folder without table specs is not an assets folder.
  fs::create_directories(root / "opt" / "bin");
  fs::create_directories(root / "opt" / "share" / "pool");
  EXPECT_FALSE(assetsBesideProgram(root / "opt" / "bin").has_value());
  fs::remove_all(root);
}

}  // namespace
}  // namespace pool::table
