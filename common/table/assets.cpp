// Asset folder lookup: $POOL_ASSETS, then beside the executable, then the install path.
#include "table/assets.h"

#include <cstdlib>
#include <system_error>

#include "core/program_dir.h"

namespace pool::table {
namespace {

namespace fs = std::filesystem;

/// An assets folder candidate counts only if it holds the table specs.
bool looksLikeAssets(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "tables", ec);
}

std::optional<fs::path> besideExecutable() {
  const auto bin = programDir();
  return bin ? assetsBesideProgram(*bin) : std::nullopt;
}

}  // namespace

std::optional<fs::path> assetsBesideProgram(const fs::path& bin_dir) {
  for (const fs::path& candidate :
       {bin_dir / ".." / ".." / "assets", bin_dir / ".." / "share" / "pool"}) {
    if (looksLikeAssets(candidate)) return candidate.lexically_normal();
  }
  return std::nullopt;
}

fs::path assetsDir() {
  if (const char* env = std::getenv("POOL_ASSETS"); env != nullptr && *env != '\0') {
    return fs::path(env);
  }
  if (auto beside = besideExecutable()) return *beside;
  return fs::path(POOL_INSTALL_ASSETS_DIR);
}

std::optional<fs::path> findAsset(std::string_view relative) {
  const fs::path candidate = assetsDir() / fs::path(relative);
  std::error_code ec;
  if (fs::exists(candidate, ec)) return candidate;
  return std::nullopt;
}

}  // namespace pool::table
