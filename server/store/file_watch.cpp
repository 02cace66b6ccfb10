// The database file's identity, checked against its path.
#include "server/store/file_watch.h"

#include <sys/stat.h>

#include <filesystem>

namespace pool::store {

FileWatch::FileWatch(std::string path) : path_(std::move(path)) {
  struct stat st {};
  if (::stat(path_.c_str(), &st) == 0) {
    device_ = st.st_dev;
    inode_ = st.st_ino;
    known_ = true;
  }
}

Check<> FileWatch::check() const {
  if (!known_) return Check<>::pass();
  struct stat st {};
  if (::stat(path_.c_str(), &st) != 0) {
    std::error_code ec;
    const auto folder = std::filesystem::path(path_).parent_path();
    if (!folder.empty() && !std::filesystem::exists(folder, ec)) {
      return Check<>::refuse("folder_deleted", "the database's folder " + folder.string() +
                                                   " was deleted under the server");
    }
    return Check<>::refuse("file_deleted",
                           "the database file " + path_ + " was deleted under the server");
  }
  if (st.st_dev != device_ || st.st_ino != inode_) {
    return Check<>::refuse("file_replaced", "the database file " + path_ +
                                                " was replaced by another file under the server");
  }
  return Check<>::pass();
}

}  // namespace pool::store
