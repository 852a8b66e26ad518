// Reading a checkpoint, whole or some rows of it (the writer is in checkpoint_file.cpp). Each
// dataset's chunks carry Fletcher-32 checksums, which HDF5 verifies as it reads them: a file
// changed after netsph wrote it (a flipped bit on the disk, a page zeroed by a crash, an edit)
// fails here, naming the dataset, and is never restarted from.
#include <fmt/format.h>

#include <algorithm>

#include "netsph/core/error.hpp"
#include "netsph/io/checkpoint_file.hpp"
#include "netsph/io/checkpoint_format.hpp"
#include "netsph/io/hdf5_handle.hpp"
#include "netsph/io/hdf5_layout.hpp"

namespace netsph {
namespace {

namespace fs = std::filesystem;

using h5::check_id;
using h5::check_status;
using h5::fail;

/// Why a read of `what` ("/f64/particles.pos") failed, for a checkpoint that HDF5 cannot read
/// back as written (HDF5's cause follows).
std::string damaged(const std::string& what) {
  return fmt::format(
      "cannot read {}: the checkpoint was changed or damaged after netsph wrote it, and cannot "
      "be restarted from (a copy of it, or an earlier checkpoint, may be intact)",
      what);
}
std::string damaged(const std::string& group, const std::string& name) {
  return damaged("/" + group + "/" + name);
}
std::string damaged_group(const std::string& group) {
  return damaged("group /" + group);
}

/// A checkpoint open for reading, and whether its datasets must carry checksums.
struct OpenCheckpoint {
  hid_t file;
  const fs::path& path;
  bool checksummed;
  std::uintmax_t bytes;  // the file's size

  /// Dataset /group/name, refused when it should carry a checksum and does not (its header
  /// changed), and when it is not one-dimensional.
  h5::Handle dataset(const std::string& group, const std::string& name, hsize_t& size) const {
    const std::string what = damaged(group, name);
    const h5::Handle g(
        check_id(H5Gopen2(file, group.c_str(), H5P_DEFAULT), path, damaged_group(group)), H5Gclose);
    h5::Handle d(check_id(H5Dopen2(g.get(), name.c_str(), H5P_DEFAULT), path, what), H5Dclose);
    if (checksummed && !h5::has_checksum(d.get())) fail(path, what + " (it has no checksum)");
    const h5::Handle space(check_id(H5Dget_space(d.get()), path, what), H5Sclose);
    if (H5Sget_simple_extent_ndims(space.get()) != 1) fail(path, what + " (not one-dimensional)");
    check_status(H5Sget_simple_extent_dims(space.get(), &size, nullptr), path, what);
    // Every value is stored (at least a byte each): a length the file cannot hold is damage
    // (in a file without checksums, which would otherwise be asked for that much memory).
    if (size > bytes) fail(path, what + fmt::format(" (it claims {} values)", size));
    return d;
  }
};

/// The names of the datasets of a group.
std::vector<std::string> names_in(hid_t file, const char* group, const fs::path& path) {
  const h5::Handle g(check_id(H5Gopen2(file, group, H5P_DEFAULT), path, damaged_group(group)),
                     H5Gclose);
  H5G_info_t info;
  check_status(H5Gget_info(g.get(), &info), path, damaged_group(group));
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len =
        H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len < 0) fail(path, damaged_group(group));
    std::string name(static_cast<std::size_t>(len), '\0');
    check_status(static_cast<herr_t>(
                     H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(),
                                        static_cast<std::size_t>(len) + 1, H5P_DEFAULT)),
                 path, damaged_group(group));
    names.push_back(std::move(name));
  }
  return names;
}

template <class T>
void read_group(const OpenCheckpoint& c, const char* group,
                std::map<std::string, std::vector<T>>& m, hid_t mtype,
                const std::vector<std::string>& skip = {}) {
  for (const std::string& name : names_in(c.file, group, c.path)) {
    if (std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
    hsize_t n = 0;
    const h5::Handle d = c.dataset(group, name, n);
    std::vector<T>& values = m[name];
    values.resize(n);
    if (n > 0) {
      check_status(H5Dread(d.get(), mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), c.path,
                   damaged(group, name));
    }
  }
}

/// One-dimensional dataset /group/name of a checkpoint, read in blocks of rows.
class RowReader {
 public:
  RowReader(const OpenCheckpoint& c, const char* group, const std::string& name)
      : what_(damaged(group, name)), path_(c.path), dataset_(c.dataset(group, name, size_)) {}
  hsize_t size() const { return size_; }
  /// Calls take(first_row, block) for the dataset's `rows` rows of `width` values each, read
  /// a block of rows at a time (never the whole dataset at once).
  template <class T, class Take>
  void for_each_block(hsize_t rows, hsize_t width, hid_t mtype, Take&& take) const {
    constexpr hsize_t kBlock = 1 << 18;  // rows read at once
    std::vector<T> block;
    for (hsize_t first = 0; first < rows; first += kBlock) {
      block.resize(std::min(kBlock, rows - first) * width);
      read(first * width, std::span<T>(block), mtype);
      take(first, std::span<const T>(block));
    }
  }

 private:
  /// Values [first, first + out.size()).
  template <class T>
  void read(hsize_t first, std::span<T> out, hid_t mtype) const {
    if (out.empty()) return;
    const hsize_t count = out.size();
    h5::Handle file_space(check_id(H5Dget_space(dataset_.get()), path_, what_), H5Sclose);
    check_status(
        H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &first, nullptr, &count, nullptr),
        path_, what_);
    h5::Handle memory_space(check_id(H5Screate_simple(1, &count, nullptr), path_, what_), H5Sclose);
    check_status(H5Dread(dataset_.get(), mtype, memory_space.get(), file_space.get(), H5P_DEFAULT,
                         out.data()),
                 path_, what_);
  }

  std::string what_;
  const fs::path& path_;
  hsize_t size_ = 0;
  h5::Handle dataset_;
};

/// The rows of /group/name with keep[r], `rows` rows in all, appended to `out`.
template <class T>
void read_kept_rows(const OpenCheckpoint& c, const char* group, const std::string& name,
                    const std::vector<bool>& keep, hid_t mtype, std::vector<T>& out) {
  const RowReader reader(c, group, name);
  const hsize_t rows = keep.size();
  if (rows == 0 ? reader.size() != 0 : reader.size() % rows != 0)
    fail(c.path,
         fmt::format("/{}/{} holds {} values for {} rows", group, name, reader.size(), rows));
  const hsize_t width = rows == 0 ? 0 : reader.size() / rows;
  reader.for_each_block<T>(rows, width, mtype, [&](hsize_t first, std::span<const T> block) {
    for (hsize_t r = 0; r < block.size() / width; ++r)
      if (keep[first + r])
        out.insert(out.end(), block.begin() + r * width, block.begin() + (r + 1) * width);
  });
}

/// Which group holds the array `name` (null when none does), by trying each.
const char* group_holding(hid_t file, const std::string& name) {
  for (const char* group : checkpoint_format::kArrayGroups) {
    h5::Handle g(H5Gopen2(file, group, H5P_DEFAULT), H5Gclose);
    if (g.valid() && H5Lexists(g.get(), name.c_str(), H5P_DEFAULT) > 0) return group;
  }
  return nullptr;
}

/// The file's /text/_magic, which says whether its datasets carry checksums: read first, and
/// not itself required to carry one (a file written before checksums has none).
bool has_checksums(hid_t file, const fs::path& path) {
  std::map<std::string, std::vector<std::uint8_t>> magic;
  const OpenCheckpoint unchecked{file, path, false, fs::file_size(path)};
  hsize_t n = 0;
  const h5::Handle d = unchecked.dataset(checkpoint_format::kTextGroup, "_magic", n);
  std::string text(n, '\0');
  if (n > 0) {
    check_status(H5Dread(d.get(), H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()),
                 path, damaged(checkpoint_format::kTextGroup, "_magic"));
  }
  if (text == checkpoint_format::kMagic) {
    if (!h5::has_checksum(d.get())) fail(path, damaged("text", "_magic") + " (it has no checksum)");
    return true;
  }
  if (text == checkpoint_format::kMagicBeforeChecksums) return false;
  throw Error(path.string(), "not a netsph checkpoint");
}

}  // namespace

CheckpointData read_checkpoint_file(const fs::path& path) {
  return read_checkpoint_file(path, CheckpointRows{});
}

CheckpointData read_checkpoint_file(const fs::path& path, const CheckpointRows& rows) {
  const h5::SilenceErrors quiet;
  if (!fs::exists(path)) throw Error(path.string(), "no checkpoint here");
  h5::Handle file(check_id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path,
                           "cannot open the checkpoint"),
                  H5Fclose);
  CheckpointData data;
  data.source = path.string();
  const OpenCheckpoint c{file.get(), path, has_checksums(file.get(), path), fs::file_size(path)};
  // A checkpoint of an earlier netsph is read, with a warning for the user, rather than
  // refused: it is as trustworthy as it was when written, and refusing it would throw away
  // the run it continues, which is what checksums are meant to save.
  if (!c.checksummed) {
    data.unchecked =
        "this checkpoint was written by a netsph from before checkpoints carried checksums: its "
        "data cannot be checked for damage";
  }
  read_group(c, "f64", data.f64, H5T_NATIVE_DOUBLE, rows.arrays);
  read_group(c, "f32", data.f32, H5T_NATIVE_FLOAT, rows.arrays);
  read_group(c, "u32", data.u32, H5T_NATIVE_UINT32, rows.arrays);
  read_group(c, "u8", data.u8, H5T_NATIVE_UINT8, rows.arrays);
  std::map<std::string, std::vector<std::uint8_t>> texts;
  read_group(c, checkpoint_format::kTextGroup, texts, H5T_NATIVE_UINT8);
  for (const auto& [k, v] : texts) data.text[k] = std::string(v.begin(), v.end());
  data.text.erase("_magic");
  if (rows.arrays.empty()) return data;
  if (!rows.keep) {  // no row: the arrays are there, empty
    for (const std::string& name : rows.arrays) {
      const char* group = group_holding(file.get(), name);
      if (!group) fail(path, "checkpoint has no array " + name);
      const std::string_view g = group;
      if (g == "f64") data.f64[name].clear();
      if (g == "f32") data.f32[name].clear();
      if (g == "u32") data.u32[name].clear();
      if (g == "u8") data.u8[name].clear();
    }
    return data;
  }

  // Which rows to keep, from the key array read a block at a time.
  const std::string& key = rows.arrays.front();
  const RowReader key_reader(c, "f64", key);
  const hsize_t width = rows.key_width;
  if (width == 0 || key_reader.size() % width != 0)
    fail(path, fmt::format("/f64/{} does not hold rows of {} values", key, width));
  std::vector<bool> keep(key_reader.size() / width);
  key_reader.for_each_block<double>(
      keep.size(), width, H5T_NATIVE_DOUBLE, [&](hsize_t first, std::span<const double> block) {
        for (hsize_t r = 0; r < block.size() / width; ++r)
          keep[first + r] = rows.keep(block.subspan(r * width, width));
      });
  for (const std::string& name : rows.arrays) {
    const char* group = group_holding(file.get(), name);
    if (!group) fail(path, "checkpoint has no array " + name);
    const std::string_view g = group;
    if (g == "f64") read_kept_rows(c, group, name, keep, H5T_NATIVE_DOUBLE, data.f64[name]);
    if (g == "f32") read_kept_rows(c, group, name, keep, H5T_NATIVE_FLOAT, data.f32[name]);
    if (g == "u32") read_kept_rows(c, group, name, keep, H5T_NATIVE_UINT32, data.u32[name]);
    if (g == "u8") read_kept_rows(c, group, name, keep, H5T_NATIVE_UINT8, data.u8[name]);
  }
  return data;
}

}  // namespace netsph
