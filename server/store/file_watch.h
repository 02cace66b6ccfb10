// Notices the database file disappearing (or its folder) or being replaced under the server.
#pragma once

#include <sys/types.h>

#include <string>

#include "core/check.h"

namespace pool::store {

/// Remembers which file `path` names when made (device and inode); check() refuses when the path
/// no longer names it. An open SQLite connection goes on writing to a deleted file without an
/// error, so the store asks after every write.
class FileWatch {
 public:
  FileWatch() = default;
  explicit FileWatch(std::string path);

  /// Passes while the path still names the file it named at the start; else refuses with why not.
  Check<> check() const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  dev_t device_ = 0;
  ino_t inode_ = 0;
  bool known_ = false;  ///< the file was there when the watch began
};

}  // namespace pool::store
