#include "netsph/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "netsph/core/error.hpp"

namespace netsph {
namespace {

// POSIX I/O rather than std::ofstream: a stream does not say *why* it failed, and the
// message must name the OS error (disk full, permission denied, ...).
std::string os_error(int err) {
  return std::strerror(err);
}

// Writes all of `content`, retrying short writes and EINTR. Returns 0 or the errno.
int write_all(int fd, std::string_view content) {
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return 0;
}

// Writes the temporary file completely and closes it. Returns 0 or the errno.
int write_temp(const std::filesystem::path& tmp, std::string_view content) {
  // 0666 before the umask, like any file a program creates with fopen().
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) return errno;
  int err = write_all(fd, content);
  // close() can report a delayed write error (NFS, disk full), so it counts too.
  if (::close(fd) != 0 && err == 0) err = errno;
  return err;
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  // Same folder as the target, so that the rename stays within one file system (and is
  // therefore atomic); the pid keeps two processes writing the same file apart.
  std::filesystem::path tmp = path;
  tmp += ".tmp." + std::to_string(::getpid());

  // No fsync: the guarantee wanted is that a reader (ParaView, a plot script) never sees a
  // half-written file, which the rename gives. Surviving a power cut is not a goal, and the
  // data files the XDMF points to are not synced either.
  if (const int err = write_temp(tmp, content); err != 0) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw Error(path.string(),
                "cannot write temporary file " + tmp.string() + ": " + os_error(err));
  }

  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw Error(path.string(), "cannot replace the file: " + ec.message());
  }
}

}  // namespace netsph
