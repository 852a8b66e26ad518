// read_file_text (case_reader.hpp): a case file read whole, bounded, and only if it is a
// regular file; the reader's entry points (case_reader.cpp) parse what it returns.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "netsph/case/case_reader.hpp"
#include "netsph/core/error.hpp"

namespace netsph {

std::string read_file_text(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  const auto fail = [&](const std::string& why) {
    throw Error(path.string(), "cannot read the file: " + why);
  };
  // O_NONBLOCK: opening a FIFO with no writer must not wait for one (a regular file ignores it).
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) fail(std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) fail(std::strerror(errno));
  if (S_ISDIR(st.st_mode)) fail("it is a directory");
  // A device (/dev/zero, /dev/urandom), a FIFO or a socket has no end or no size to check:
  // reading one ran until std::bad_alloc. A case is a file on disk.
  if (!S_ISREG(st.st_mode)) {
    fail("it is not a regular file (a device, a pipe or a socket); give a file on disk");
  }
  const auto too_big = [&] {
    fail(
        fmt::format("it is larger than {} MiB, the limit for a case file (the largest case "
                    "shipped is 5 KB)",
                    max_bytes >> 20));
  };
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) too_big();
  std::string text;
  text.reserve(static_cast<std::size_t>(st.st_size));
  char buffer[1 << 16];
  for (;;) {  // read to the end, which a file still growing may put beyond st_size
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(std::strerror(errno));
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > max_bytes) too_big();
  }
  return text;
}

}  // namespace netsph
