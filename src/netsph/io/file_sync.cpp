#include "netsph/io/file_sync.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "netsph/core/error.hpp"

namespace netsph {
namespace {

namespace fs = std::filesystem;

// fsync of `path` opened with `flags`; 0 or the errno. A file system that cannot sync (EINVAL:
// some network and FUSE file systems, for folders) has nothing more to give, so that is no
// error.
int sync_path(const fs::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return errno;
  int err = 0;
  if (::fsync(fd) != 0 && errno != EINVAL && errno != ENOTSUP) err = errno;
  ::close(fd);
  return err;
}

}  // namespace

void sync_file(const fs::path& file) {
  if (const int err = sync_path(file, O_RDONLY); err != 0)
    throw Error(file.string(),
                std::string("cannot sync the file to the disk: ") + std::strerror(err));
}

void replace_file_durably(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  try {
    sync_file(from);
  } catch (const Error& e) {
    fs::remove(from, ec);
    throw Error(to.string(), e.message() + " (" + from.string() + ", removed)");
  }
  fs::rename(from, to, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(from, ignored);
    throw Error(to.string(), "cannot replace the file: " + ec.message());
  }
  const fs::path folder = to.has_parent_path() ? to.parent_path() : fs::path(".");
  if (const int err = sync_path(folder, O_RDONLY | O_DIRECTORY); err != 0) {
    throw Error(to.string(), std::string("cannot sync its folder to the disk after the rename: ") +
                                 std::strerror(err));
  }
}

}  // namespace netsph
