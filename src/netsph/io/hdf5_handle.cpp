#include "netsph/io/hdf5_handle.hpp"

#include "netsph/core/error.hpp"

namespace netsph::h5 {
namespace {

// HDF5's clean-up at exit (H5_term_library) frees memory that the system frees anyway, and it
// cannot finish when HDF5 itself leaked on an error path: reading a damaged file (an object
// header whose checksum does not match) leaves blocks on its free lists, and the clean-up then
// prints "HDF5: infinite loop closing library" and a screen of codes after netsph's one clear
// message. netsph closes every file it opens itself (h5::Handle, h5::OutputFile), so the
// clean-up has nothing to save: it is turned off, here, before anything starts HDF5 (it must
// be, to take effect; this file is linked wherever netsph calls HDF5).
const bool kNoCleanUpAtExit = [] { return H5dont_atexit() >= 0; }();

// H5E_WALK_UPWARD visits the most specific error first (n == 0): the low-level cause,
// which is what a user can act on ("No such file or directory"), not "unable to create file".
herr_t keep_innermost(unsigned n, const H5E_error2_t* err, void* data) {
  if (n == 0 && err != nullptr && err->desc != nullptr) {
    *static_cast<std::string*>(data) = err->desc;
  }
  return 0;
}

}  // namespace

std::string last_error_message() {
  std::string message;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_innermost, &message);
  // The file driver's message repeats the path and adds open() flags around the OS error;
  // the caller names the path already, so only "error message = '...'" is worth keeping.
  const std::string key = "error message = '";
  if (const auto start = message.find(key); start != std::string::npos) {
    const auto begin = start + key.size();
    if (const auto end = message.find('\'', begin); end != std::string::npos) {
      return message.substr(begin, end - begin);
    }
  }
  return message;
}

void fail(const std::filesystem::path& path, const std::string& what) {
  const std::string cause = last_error_message();
  // The stack is this thread's: left filled when the thread ends (a distributed run's
  // process in the tests is a thread), HDF5 cannot release it when the program exits.
  H5Eclear2(H5E_DEFAULT);
  throw Error(path.string(), cause.empty() ? what : what + ": " + cause);
}

hid_t check_id(hid_t id, const std::filesystem::path& path, const std::string& what) {
  if (id < 0) fail(path, what);
  return id;
}

void check_status(herr_t status, const std::filesystem::path& path, const std::string& what) {
  if (status < 0) fail(path, what);
}

}  // namespace netsph::h5
