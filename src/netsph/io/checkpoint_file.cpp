// The checkpoint's writer and the accessors of CheckpointData; the reader is in
// checkpoint_file_read.cpp.
#include "netsph/io/checkpoint_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string_view>

#include "netsph/core/error.hpp"
#include "netsph/io/checkpoint_format.hpp"
#include "netsph/io/file_sync.hpp"
#include "netsph/io/hdf5_handle.hpp"
#include "netsph/io/hdf5_layout.hpp"
#include "netsph/io/hdf5_output_file.hpp"

namespace netsph {
namespace {

namespace fs = std::filesystem;

using h5::check_id;
using h5::check_status;
using h5::fail;

/// The arrays of one group of a checkpoint being written: each a chunked, checksummed dataset
/// of unlimited length, created with its first values and appended to. The file keeps the
/// datasets (h5::OutputFile), so that whatever fails, they close with it.
template <class T>
class GroupWriter {
 public:
  GroupWriter(h5::OutputFile& file, const char* group, hid_t ftype, hid_t mtype)
      : file_(file), name_(group), ftype_(ftype), mtype_(mtype) {
    group_ = file.keep(
        h5::Handle(check_id(H5Gcreate2(file.get(), group, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                            file.path(), std::string("cannot create group ") + group),
                   H5Gclose));
  }

  /// Each array whole, in chunks of its own size (up to h5::kChunkElements).
  void write(const std::map<std::string, std::vector<T>>& arrays) {
    for (const auto& [name, values] : arrays) {
      Array a{create(name, h5::chunk_rows(values.size(), 1)), 0};
      append(name, a, values);
    }
  }

  /// One piece of arrays that come in pieces: the first creates them (in chunks of the first
  /// piece's size, at least 4096 elements: the pieces of a large run are blocks of many
  /// particles), every later one must name the same.
  void add(const std::map<std::string, std::vector<T>>& piece, bool first) {
    if (piece.size() != appended_.size() && !first) mismatch();
    for (const auto& [name, values] : piece) {
      auto it = appended_.find(name);
      if (it == appended_.end()) {
        if (!first) mismatch();
        const hsize_t chunk = h5::chunk_rows(std::max<std::size_t>(values.size(), 4096), 1);
        it = appended_.emplace(name, Array{create(name, chunk), 0}).first;
      }
      append(name, it->second, values);
    }
  }

 private:
  struct Array {
    hid_t dataset;  // kept by the file
    hsize_t size;
  };

  [[noreturn]] void mismatch() const {
    fail(file_.path(), fmt::format("checkpoint pieces name different arrays in /{}", name_));
  }

  hid_t create(const std::string& name, hsize_t chunk) const {
    const fs::path& path = file_.path();
    const std::string what = fmt::format("cannot create /{}/{}", name_, name);
    const hsize_t zero = 0, unlimited = H5S_UNLIMITED;
    const h5::Handle space(check_id(H5Screate_simple(1, &zero, &unlimited), path, what), H5Sclose);
    const h5::Handle dcpl = h5::checksummed_layout(chunk, 1, path);
    const h5::Handle dapl = h5::uncached_access(path);
    return file_.keep(h5::Handle(check_id(H5Dcreate2(group_, name.c_str(), ftype_, space.get(),
                                                     H5P_DEFAULT, dcpl.get(), dapl.get()),
                                          path, what),
                                 H5Dclose));
  }

  void append(const std::string& name, Array& a, const std::vector<T>& values) const {
    const hsize_t m = values.size();
    if (m == 0) return;
    const fs::path& path = file_.path();
    const std::string what = fmt::format("cannot write /{}/{}", name_, name);
    const hsize_t size = a.size + m;
    check_status(H5Dset_extent(a.dataset, &size), path, what);
    const h5::Handle file_space(check_id(H5Dget_space(a.dataset), path, what), H5Sclose);
    check_status(
        H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &a.size, nullptr, &m, nullptr), path,
        what);
    const h5::Handle memory_space(check_id(H5Screate_simple(1, &m, nullptr), path, what), H5Sclose);
    check_status(H5Dwrite(a.dataset, mtype_, memory_space.get(), file_space.get(), H5P_DEFAULT,
                          values.data()),
                 path, what);
    a.size = size;
  }

  h5::OutputFile& file_;
  const char* name_;
  hid_t ftype_, mtype_;
  hid_t group_ = H5I_INVALID_HID;  // kept by the file
  std::map<std::string, Array> appended_;
};

/// Writes the whole checkpoint into `file` (still to be finished).
void write_contents(h5::OutputFile& file, const CheckpointData& data,
                    const CheckpointPieces& pieces) {
  // The texts, the case's TOML among them, are bytes under the same checksums as the arrays.
  std::map<std::string, std::vector<std::uint8_t>> texts;
  for (const auto& [k, v] : data.text) texts[k] = std::vector<std::uint8_t>(v.begin(), v.end());
  const std::string_view magic = checkpoint_format::kMagic;
  texts["_magic"] = std::vector<std::uint8_t>(magic.begin(), magic.end());
  GroupWriter<double> f64(file, "f64", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
  GroupWriter<float> f32(file, "f32", H5T_IEEE_F32LE, H5T_NATIVE_FLOAT);
  GroupWriter<std::uint32_t> u32(file, "u32", H5T_STD_U32LE, H5T_NATIVE_UINT32);
  GroupWriter<std::uint8_t> u8(file, "u8", H5T_STD_U8LE, H5T_NATIVE_UINT8);
  GroupWriter<std::uint8_t> text(file, checkpoint_format::kTextGroup, H5T_STD_U8LE,
                                 H5T_NATIVE_UINT8);
  f64.write(data.f64), f32.write(data.f32), u32.write(data.u32), u8.write(data.u8);
  text.write(texts);
  if (!pieces) return;
  bool first = true;
  pieces([&](const CheckpointData& piece) {
    if (!piece.text.empty()) fail(file.path(), "checkpoint pieces hold texts");
    f64.add(piece.f64, first), f32.add(piece.f32, first);
    u32.add(piece.u32, first), u8.add(piece.u8, first);
    first = false;
  });
}

}  // namespace

const std::vector<double>& CheckpointData::reals(const std::string& name) const {
  const auto it = f64.find(name);
  if (it == f64.end())
    throw Error(source, "checkpoint has no '" + name +
                            "': written by another "
                            "netsph version or for another case");
  return it->second;
}

double CheckpointData::real(const std::string& name) const {
  const std::vector<double>& v = reals(name);
  if (v.empty()) throw Error(source, "checkpoint entry '" + name + "' is empty");
  return v.front();
}

const std::string& CheckpointData::text_of(const std::string& name) const {
  const auto it = text.find(name);
  if (it == text.end()) throw Error(source, "checkpoint has no text '" + name + "'");
  return it->second;
}

void write_checkpoint_file(const fs::path& path, const CheckpointData& data,
                           const CheckpointPieces& pieces) {
  const fs::path tmp = path.string() + ".tmp";
  try {
    {
      // Whatever fails in here, the temporary file is closed and removed (h5::OutputFile).
      h5::OutputFile file(tmp, "cannot create the checkpoint");
      const h5::SilenceErrors quiet;
      write_contents(file, data, pieces);
      file.finish();
    }
    // On the disk before it replaces the previous one: a machine that crashes after the
    // rename must not come back with a new name on a file whose data never reached the disk.
    replace_file_durably(tmp, path);
  } catch (const Error& e) {
    if (e.where() == path.string()) throw;
    throw Error(path.string(), fmt::format("cannot write the new checkpoint ({}: {}); the previous "
                                           "checkpoint, if any, is kept",
                                           fs::path(e.where()).filename().string(), e.message()));
  }
}

}  // namespace netsph
