// Finds the assets/ folder from any working directory.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace pool::table {

/// The assets folder: $POOL_ASSETS if set, else next to the executable (../../assets or
/// ../share/pool/assets), else the source tree's assets/ recorded at build time.
std::filesystem::path assetsDir();

/// assetsDir()/relative if that file exists.
std::optional<std::filesystem::path> findAsset(std::string_view relative);

}  // namespace pool::table
