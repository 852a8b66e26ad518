#pragma once
// Private to netsph_io: an HDF5 file being written, from its creation to a complete file, and
// the owner of every group and dataset opened in it. It exists for the writes that fail half
// way (a full disk, a quota, a file size limit, an I/O error): HDF5 1.10 cannot close a file
// whose data it cannot write; the close fails and leaves the file half closed, open to the end
// of the run (where HDF5's clean-up at exit used to crash on it: SIGSEGV in H5F__close_cb). So
// a file that failed is abandoned: its remaining writes go to memory instead of the disk,
// every object and the file close, and the file is removed. The caller sees one netsph::Error
// naming the file.
#include <hdf5.h>

#include <filesystem>
#include <string>
#include <vector>

#include "netsph/io/hdf5_handle.hpp"

namespace netsph::h5 {

class OutputFile {
 public:
  /// Creates `path` (replacing a file there) in the HDF5 1.10 file format, whose metadata
  /// (superblock, object headers, chunk indexes) is checksummed. Throws netsph::Error
  /// naming the file, `what` and the cause when it cannot; nothing of ours is left then.
  OutputFile(std::filesystem::path path, const std::string& what);
  /// A file not finished is abandoned (removed).
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  hid_t get() const { return file_.get(); }
  const std::filesystem::path& path() const { return path_; }

  /// Keeps `object`, a group or dataset of this file, open until finish(); returns its id.
  hid_t keep(Handle object);

  /// Closes every object kept and the file, each checked: the file is then complete on disk
  /// (in the system's cache: not yet synced). Throws netsph::Error naming the file when any
  /// of it cannot be written; the file is then abandoned.
  void finish();

 private:
  void abandon() noexcept;

  std::filesystem::path path_;
  Handle file_;
  std::vector<Handle> objects_;
  bool finished_ = false;
};

}  // namespace netsph::h5
