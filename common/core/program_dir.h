// The folder of the running program's executable (a build tree's bin/, or /usr/bin installed):
// where the programs look for what was built or installed beside them.
#pragma once

#include <filesystem>
#include <optional>
#include <system_error>

namespace pool {

/// The folder holding the running executable (/proc/self/exe), or none when it cannot be read.
inline std::optional<std::filesystem::path> programDir() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec || exe.empty()) return std::nullopt;
  return exe.parent_path();
}

}  // namespace pool
