// Finds the assets/ folder from any working directory, in a build tree or an installed system.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace pool::table {

/// The assets folder: $POOL_ASSETS if set, else the one beside the running executable
/// (assetsBesideProgram), else the installed data folder recorded at build time
/// (<prefix>/share/pool).
std::filesystem::path assetsDir();

/// The assets folder of a program living in `bin_dir`, if there is one: `bin_dir/../../assets`
/// (a build tree's bin/ inside the source tree) or `bin_dir/../share/pool` (installed, or any build
/// folder: the build links its share/pool to the source tree's assets/).
std::optional<std::filesystem::path> assetsBesideProgram(const std::filesystem::path& bin_dir);

/// assetsDir()/relative if that file exists.
std::optional<std::filesystem::path> findAsset(std::string_view relative);

}  // namespace pool::table
