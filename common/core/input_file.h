// Reads an input file (a scenario, a table spec) whole, refusing what is no ordinary file (a
// device such as /dev/zero, a fifo, a folder) and what is too large to be one, before reading.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include "core/result.h"

namespace pool {

/// The largest input file read, in bytes: far above any real scenario or table spec.
inline constexpr std::uintmax_t kMaxInputFileBytes = 4u << 20;

/// The text of `path`, or why not: "cannot open it: <errno text>", "not a regular file", "larger
/// than 4 MiB", "read error". The reason does not name the file: callers put it in their line.
inline Result<std::string> readInputFile(const std::filesystem::path& path) {
  using R = Result<std::string>;
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec) return R::fail("cannot open it: " + ec.message());
  if (!std::filesystem::is_regular_file(status)) return R::fail("not a regular file");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) return R::fail("cannot open it: " + ec.message());
  if (size > kMaxInputFileBytes) return R::fail("larger than 4 MiB");
  std::ifstream in(path, std::ios::binary);
  if (!in) return R::fail(std::string("cannot open it: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return R::fail("read error");
  return R::ok(text.str());
}

}  // namespace pool
