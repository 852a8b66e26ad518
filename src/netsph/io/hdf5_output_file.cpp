#include "netsph/io/hdf5_output_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "netsph/core/error.hpp"

namespace netsph::h5 {
namespace {

namespace fs = std::filesystem;

// The file format of HDF5 1.10 (readable by HDF5 1.10 and later; Debian's is 1.10): unlike
// the default (1.8's earliest format), its metadata carries checksums too, so a flipped byte
// in a dataset's header or chunk index is a read error rather than another layout.
Handle format_1_10(const fs::path& path, const std::string& what) {
  Handle fapl(check_id(H5Pcreate(H5P_FILE_ACCESS), path, what), H5Pclose);
  check_status(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V110, H5F_LIBVER_V110), path, what);
  return fapl;
}

// The file's descriptor, for HDF5's default driver (sec2), whose handle it is; -1 otherwise.
int descriptor_of(hid_t file) {
  const Handle fapl(H5Fget_access_plist(file), H5Pclose);
  if (!fapl.valid() || H5Pget_driver(fapl.get()) != H5FD_SEC2) return -1;
  void* handle = nullptr;
  if (H5Fget_vfd_handle(file, fapl.get(), &handle) < 0 || handle == nullptr) return -1;
  return *static_cast<int*>(handle);
}

// The end of HDF5's allocation in `file`: the size the file will have (0 when unknown).
haddr_t end_of_allocation(hid_t file) {
  haddr_t eoa = 0;
  return H5Fget_eoa(file, &eoa) < 0 ? 0 : eoa;
}

// Reserves the disk blocks of the whole file as far as HDF5 has laid it out, and some more
// (flushing the metadata allocated another 2 KiB block in the tests), before HDF5 writes its
// metadata into them: a full disk or a file size limit then fails here, where the file can
// still be abandoned, rather than in the flush, after which HDF5 1.10 can never close it (its
// metadata cache is left unable to flush again: "slist already enabled?"). The file grows to
// that size; finish() cuts it back to HDF5's end. File systems that cannot reserve
// (EOPNOTSUPP) go on without.
void reserve_blocks(hid_t file, const fs::path& path) {
  constexpr haddr_t kMargin = 64 * 1024;
  const int fd = descriptor_of(file);
  const haddr_t eoa = end_of_allocation(file);
  if (fd < 0 || eoa == 0) return;
  if (::fallocate(fd, 0, 0, static_cast<off_t>(eoa + kMargin)) != 0 && errno != EOPNOTSUPP &&
      errno != ENOSYS) {
    throw Error(path.string(), std::string("cannot write the file: ") + std::strerror(errno));
  }
}

// Sends the file's further writes to an anonymous file in memory (reads too, of what it did
// not write: zeros) by putting one in place of its descriptor. HDF5 then closes it without an
// error, whatever the disk does; what it writes is lost, as intended for a file being removed.
// Only for HDF5's default driver (sec2), whose handle is the descriptor; otherwise nothing.
void divert_writes_to_memory(hid_t file) {
  const int fd = descriptor_of(file);
  if (fd < 0) return;
  const int memory = ::memfd_create("netsph-abandoned-hdf5", MFD_CLOEXEC);
  if (memory < 0) return;
  ::dup2(memory, fd);
  ::close(memory);
}

// While it lives, the file size limit (RLIMIT_FSIZE, `ulimit -f`) is raised as far as the hard
// limit allows: a memory file counts against it too, so a file abandoned for passing it would
// fail its last writes again, in memory.
class FileSizeLimitLifted {
 public:
  FileSizeLimitLifted() {
    if (::getrlimit(RLIMIT_FSIZE, &saved_) != 0 || saved_.rlim_cur == saved_.rlim_max) return;
    const rlimit lifted{saved_.rlim_max, saved_.rlim_max};
    lifted_ = ::setrlimit(RLIMIT_FSIZE, &lifted) == 0;
  }
  ~FileSizeLimitLifted() {
    if (lifted_) ::setrlimit(RLIMIT_FSIZE, &saved_);
  }
  FileSizeLimitLifted(const FileSizeLimitLifted&) = delete;
  FileSizeLimitLifted& operator=(const FileSizeLimitLifted&) = delete;

 private:
  rlimit saved_{};
  bool lifted_ = false;
};

}  // namespace

OutputFile::OutputFile(fs::path path, const std::string& what) : path_(std::move(path)) {
  const SilenceErrors quiet;
  const Handle fapl = format_1_10(path_, what);
  const hid_t id = H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get());
  if (id < 0) {
    const std::string cause = last_error_message();
    H5Eclear2(H5E_DEFAULT);
    // What a create that failed half way leaves (a full disk: an empty file) goes; anything
    // else there (a folder in the way, a file it could not open) is someone else's.
    std::error_code ec;
    if (fs::is_regular_file(path_, ec) && fs::file_size(path_, ec) == 0) fs::remove(path_, ec);
    throw Error(path_.string(), cause.empty() ? what : what + ": " + cause);
  }
  file_ = Handle(id, H5Fclose);
}

OutputFile::~OutputFile() {
  if (!finished_) abandon();
}

hid_t OutputFile::keep(Handle object) {
  objects_.push_back(std::move(object));
  return objects_.back().get();
}

void OutputFile::finish() {
  const SilenceErrors quiet;
  try {
    while (!objects_.empty()) {
      check_status(objects_.back().close(), path_, "cannot write the file");
      objects_.pop_back();
    }
    reserve_blocks(file_.get(), path_);
    // The metadata goes out here, with the file still open: where the disk is full, the file
    // can still be abandoned (a failed H5Fclose would leave it half closed).
    check_status(H5Fflush(file_.get(), H5F_SCOPE_LOCAL), path_, "cannot write the file");
    const haddr_t size = end_of_allocation(file_.get());
    check_status(file_.close(), path_, "cannot close the file");
    // Cut back to HDF5's own end what reserve_blocks added beyond it (if HDF5 did not).
    std::error_code ec;
    if (size > 0 && fs::file_size(path_, ec) > size) fs::resize_file(path_, size, ec);
  } catch (...) {
    abandon();
    throw;
  }
  finished_ = true;
}

void OutputFile::abandon() noexcept {
  const SilenceErrors quiet;
  {
    const FileSizeLimitLifted lifted;
    if (file_.valid()) divert_writes_to_memory(file_.get());
    while (!objects_.empty()) objects_.pop_back();  // newest first: datasets before their groups
    file_.close();
  }
  H5Eclear2(H5E_DEFAULT);
  std::error_code ignored;
  fs::remove(path_, ignored);
  finished_ = true;
}

}  // namespace netsph::h5
