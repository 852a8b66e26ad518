#pragma once
// Private to netsph_io: RAII for HDF5 C API identifiers, and HDF5 errors turned into
// netsph::Error. HDF5's own error printing is switched off while netsph writes, so that a
// failure shows as one netsph message naming the file instead of a 20-line HDF5 stack.
#include <hdf5.h>

#include <filesystem>
#include <string>
#include <utility>

namespace netsph::h5 {

/// Owns one hid_t and closes it with the matching H5?close function.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);

  Handle() = default;
  Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), closer_(o.closer_) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, H5I_INVALID_HID);
      closer_ = o.closer_;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

  /// Closes now and returns the closer's status: closing a file flushes it, so that is
  /// where a full disk shows up, and the caller must see it (a destructor cannot throw).
  herr_t close() {
    herr_t status = 0;
    if (id_ >= 0) status = closer_(id_);
    id_ = H5I_INVALID_HID;
    return status;
  }

 private:
  void reset() {
    if (id_ >= 0) closer_(id_);
    id_ = H5I_INVALID_HID;
  }

  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

/// Switches HDF5's automatic error printing off for its lifetime (on this thread: the
/// setting is per thread in thread-safe builds such as Debian's) and restores it after.
class SilenceErrors {
 public:
  SilenceErrors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~SilenceErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  SilenceErrors(const SilenceErrors&) = delete;
  SilenceErrors& operator=(const SilenceErrors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

/// Throws netsph::Error naming the file, with HDF5's most specific cause appended.
[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what);
/// `id`, or fail(path, what) when it is an HDF5 error (negative).
hid_t check_id(hid_t id, const std::filesystem::path& path, const std::string& what);
/// fail(path, what) when `status` is an HDF5 error (negative).
void check_status(herr_t status, const std::filesystem::path& path, const std::string& what);

/// The most specific message on HDF5's error stack (e.g. "unable to open file: name =
/// '...', errno = 2, error message = 'No such file or directory'"), or "" when empty.
std::string last_error_message();

}  // namespace netsph::h5
