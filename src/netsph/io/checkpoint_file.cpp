#include "netsph/io/checkpoint_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <system_error>

#include "netsph/core/error.hpp"
#include "netsph/io/hdf5_handle.hpp"

namespace netsph {
namespace {

namespace fs = std::filesystem;

constexpr const char* kMagic = "netsph checkpoint 1";

using h5::check_id;
using h5::check_status;
using h5::fail;

h5::Handle create_group(hid_t file, const char* group, const fs::path& path) {
  return h5::Handle(check_id(H5Gcreate2(file, group, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path,
                             std::string("cannot create group ") + group),
                    H5Gclose);
}

template <class T>
void write_arrays(hid_t g, const char* group, const std::map<std::string, std::vector<T>>& m,
                  hid_t ftype, hid_t mtype, const fs::path& path) {
  for (const auto& [name, values] : m) {
    const std::string what = fmt::format("cannot write /{}/{}", group, name);
    const hsize_t n = values.size();
    h5::Handle space(check_id(H5Screate_simple(1, &n, nullptr), path, what), H5Sclose);
    h5::Handle d(check_id(H5Dcreate2(g, name.c_str(), ftype, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                                     H5P_DEFAULT),
                          path, what),
                 H5Dclose);
    if (n > 0) {
      check_status(H5Dwrite(d.get(), mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), path,
                   what);
    }
  }
}

// The arrays of one group that grow piece by piece: chunked datasets of unlimited length,
// created with the first piece's names.
template <class T>
class AppendedArrays {
 public:
  AppendedArrays(hid_t group, const char* name, hid_t ftype, hid_t mtype, const fs::path& path)
      : group_(group), name_(name), ftype_(ftype), mtype_(mtype), path_(path) {}

  void add(const std::map<std::string, std::vector<T>>& piece, bool first) {
    if (piece.size() != arrays_.size() && !first) mismatch();
    for (const auto& [name, values] : piece) {
      auto it = arrays_.find(name);
      if (it == arrays_.end()) {
        if (!first) mismatch();
        it = arrays_.emplace(name, Array{create(name), 0}).first;
      }
      append(name, it->second, values);
    }
  }

 private:
  struct Array {
    h5::Handle dataset;
    hsize_t size;
  };

  [[noreturn]] void mismatch() const {
    fail(path_, fmt::format("checkpoint pieces name different arrays in /{}", name_));
  }

  h5::Handle create(const std::string& name) const {
    const std::string what = fmt::format("cannot create /{}/{}", name_, name);
    const hsize_t zero = 0, unlimited = H5S_UNLIMITED, chunk = 1 << 16;
    h5::Handle space(check_id(H5Screate_simple(1, &zero, &unlimited), path_, what), H5Sclose);
    h5::Handle dcpl(check_id(H5Pcreate(H5P_DATASET_CREATE), path_, what), H5Pclose);
    check_status(H5Pset_chunk(dcpl.get(), 1, &chunk), path_, what);
    return h5::Handle(check_id(H5Dcreate2(group_, name.c_str(), ftype_, space.get(), H5P_DEFAULT,
                                          dcpl.get(), H5P_DEFAULT),
                               path_, what),
                      H5Dclose);
  }

  void append(const std::string& name, Array& a, const std::vector<T>& values) const {
    const hsize_t m = values.size();
    if (m == 0) return;
    const std::string what = fmt::format("cannot write /{}/{}", name_, name);
    const hsize_t size = a.size + m;
    check_status(H5Dset_extent(a.dataset.get(), &size), path_, what);
    h5::Handle file_space(check_id(H5Dget_space(a.dataset.get()), path_, what), H5Sclose);
    check_status(
        H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &a.size, nullptr, &m, nullptr), path_,
        what);
    h5::Handle memory_space(check_id(H5Screate_simple(1, &m, nullptr), path_, what), H5Sclose);
    check_status(H5Dwrite(a.dataset.get(), mtype_, memory_space.get(), file_space.get(),
                          H5P_DEFAULT, values.data()),
                 path_, what);
    a.size = size;
  }

  hid_t group_;
  const char* name_;
  hid_t ftype_, mtype_;
  const fs::path& path_;
  std::map<std::string, Array> arrays_;
};

template <class T>
void read_group(hid_t file, const char* group, std::map<std::string, std::vector<T>>& m,
                hid_t mtype, const fs::path& path, const std::vector<std::string>& skip = {}) {
  h5::Handle g(check_id(H5Gopen2(file, group, H5P_DEFAULT), path,
                        std::string("not a netsph checkpoint: no group ") + group),
               H5Gclose);
  H5G_info_t info;
  check_status(H5Gget_info(g.get(), &info), path, "cannot list a checkpoint group");
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len =
        H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len < 0) fail(path, "cannot read a checkpoint dataset name");
    std::string name(static_cast<std::size_t>(len), '\0');
    H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(),
                       static_cast<std::size_t>(len) + 1, H5P_DEFAULT);
    if (std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
    const std::string what = fmt::format("cannot read /{}/{}", group, name);
    h5::Handle d(check_id(H5Dopen2(g.get(), name.c_str(), H5P_DEFAULT), path, what), H5Dclose);
    h5::Handle space(check_id(H5Dget_space(d.get()), path, what), H5Sclose);
    hsize_t n = 0;
    if (H5Sget_simple_extent_ndims(space.get()) != 1) fail(path, what + ": not one-dimensional");
    H5Sget_simple_extent_dims(space.get(), &n, nullptr);
    std::vector<T>& values = m[name];
    values.resize(n);
    if (n > 0) {
      check_status(H5Dread(d.get(), mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), path,
                   what);
    }
  }
}

/// One-dimensional dataset /group/name of a checkpoint, read in blocks of rows.
class RowReader {
 public:
  RowReader(hid_t file, const char* group, const std::string& name, const fs::path& path)
      : what_(fmt::format("cannot read /{}/{}", group, name)), path_(path) {
    h5::Handle g(check_id(H5Gopen2(file, group, H5P_DEFAULT), path, what_), H5Gclose);
    dataset_ =
        h5::Handle(check_id(H5Dopen2(g.get(), name.c_str(), H5P_DEFAULT), path, what_), H5Dclose);
    h5::Handle space(check_id(H5Dget_space(dataset_.get()), path, what_), H5Sclose);
    if (H5Sget_simple_extent_ndims(space.get()) != 1) fail(path, what_ + ": not one-dimensional");
    H5Sget_simple_extent_dims(space.get(), &size_, nullptr);
  }
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
  h5::Handle dataset_;
  hsize_t size_ = 0;
};

/// The rows of /group/name with keep[r], `rows` rows in all, appended to `out`.
template <class T>
void read_kept_rows(hid_t file, const char* group, const std::string& name,
                    const std::vector<bool>& keep, hid_t mtype, std::vector<T>& out,
                    const fs::path& path) {
  const RowReader reader(file, group, name, path);
  const hsize_t rows = keep.size();
  if (rows == 0 ? reader.size() != 0 : reader.size() % rows != 0)
    fail(path, fmt::format("/{}/{} holds {} values for {} rows", group, name, reader.size(), rows));
  const hsize_t width = rows == 0 ? 0 : reader.size() / rows;
  reader.for_each_block<T>(rows, width, mtype, [&](hsize_t first, std::span<const T> block) {
    for (hsize_t r = 0; r < block.size() / width; ++r)
      if (keep[first + r])
        out.insert(out.end(), block.begin() + r * width, block.begin() + (r + 1) * width);
  });
}

/// Which group holds the array `name` (null when none does), by trying each.
const char* group_holding(hid_t file, const std::string& name) {
  for (const char* group : {"f64", "f32", "u32", "u8"}) {
    h5::Handle g(H5Gopen2(file, group, H5P_DEFAULT), H5Gclose);
    if (g.valid() && H5Lexists(g.get(), name.c_str(), H5P_DEFAULT) > 0) return group;
  }
  return nullptr;
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
  h5::SilenceErrors quiet;
  const fs::path tmp = path.string() + ".tmp";
  h5::Handle file(check_id(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), tmp,
                           "cannot create the checkpoint"),
                  H5Fclose);
  // From here on the temporary file is ours: one that failed half-way is removed.
  try {
    std::map<std::string, std::vector<std::uint8_t>> texts;
    for (const auto& [k, v] : data.text) texts[k] = std::vector<std::uint8_t>(v.begin(), v.end());
    texts["_magic"] = std::vector<std::uint8_t>(kMagic, kMagic + std::string_view(kMagic).size());
    h5::Handle f64 = create_group(file.get(), "f64", tmp);
    h5::Handle f32 = create_group(file.get(), "f32", tmp);
    h5::Handle u32 = create_group(file.get(), "u32", tmp);
    h5::Handle u8 = create_group(file.get(), "u8", tmp);
    h5::Handle text = create_group(file.get(), "text", tmp);
    write_arrays(f64.get(), "f64", data.f64, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, tmp);
    write_arrays(f32.get(), "f32", data.f32, H5T_IEEE_F32LE, H5T_NATIVE_FLOAT, tmp);
    write_arrays(u32.get(), "u32", data.u32, H5T_STD_U32LE, H5T_NATIVE_UINT32, tmp);
    write_arrays(u8.get(), "u8", data.u8, H5T_STD_U8LE, H5T_NATIVE_UINT8, tmp);
    write_arrays(text.get(), "text", texts, H5T_STD_U8LE, H5T_NATIVE_UINT8, tmp);
    if (pieces) {
      AppendedArrays<double> a64(f64.get(), "f64", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, tmp);
      AppendedArrays<float> a32(f32.get(), "f32", H5T_IEEE_F32LE, H5T_NATIVE_FLOAT, tmp);
      AppendedArrays<std::uint32_t> au32(u32.get(), "u32", H5T_STD_U32LE, H5T_NATIVE_UINT32, tmp);
      AppendedArrays<std::uint8_t> au8(u8.get(), "u8", H5T_STD_U8LE, H5T_NATIVE_UINT8, tmp);
      bool first = true;
      pieces([&](const CheckpointData& piece) {
        if (!piece.text.empty()) fail(tmp, "checkpoint pieces hold texts");
        a64.add(piece.f64, first), a32.add(piece.f32, first);
        au32.add(piece.u32, first), au8.add(piece.u8, first);
        first = false;
      });
    }
    // Every object of the file closed first: only then does closing it flush (and report a
    // full disk).
    for (h5::Handle* g : {&f64, &f32, &u32, &u8, &text})
      check_status(g->close(), tmp, "cannot finish the checkpoint");
    check_status(file.close(), tmp, "cannot finish the checkpoint (disk full?)");
  } catch (...) {
    file.close();
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw Error(path.string(), "cannot replace the checkpoint: " + ec.message());
  }
}

CheckpointData read_checkpoint_file(const fs::path& path) {
  return read_checkpoint_file(path, CheckpointRows{});
}

CheckpointData read_checkpoint_file(const fs::path& path, const CheckpointRows& rows) {
  h5::SilenceErrors quiet;
  if (!fs::exists(path)) throw Error(path.string(), "no checkpoint here");
  h5::Handle file(check_id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path,
                           "cannot open the checkpoint"),
                  H5Fclose);
  CheckpointData data;
  data.source = path.string();
  read_group(file.get(), "f64", data.f64, H5T_NATIVE_DOUBLE, path, rows.arrays);
  read_group(file.get(), "f32", data.f32, H5T_NATIVE_FLOAT, path, rows.arrays);
  read_group(file.get(), "u32", data.u32, H5T_NATIVE_UINT32, path, rows.arrays);
  read_group(file.get(), "u8", data.u8, H5T_NATIVE_UINT8, path, rows.arrays);
  std::map<std::string, std::vector<std::uint8_t>> texts;
  read_group(file.get(), "text", texts, H5T_NATIVE_UINT8, path);
  for (const auto& [k, v] : texts) data.text[k] = std::string(v.begin(), v.end());
  if (data.text["_magic"] != kMagic) throw Error(path.string(), "not a netsph checkpoint");
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
  const RowReader key_reader(file.get(), "f64", key, path);
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
    if (g == "f64")
      read_kept_rows(file.get(), group, name, keep, H5T_NATIVE_DOUBLE, data.f64[name], path);
    if (g == "f32")
      read_kept_rows(file.get(), group, name, keep, H5T_NATIVE_FLOAT, data.f32[name], path);
    if (g == "u32")
      read_kept_rows(file.get(), group, name, keep, H5T_NATIVE_UINT32, data.u32[name], path);
    if (g == "u8")
      read_kept_rows(file.get(), group, name, keep, H5T_NATIVE_UINT8, data.u8[name], path);
  }
  return data;
}

}  // namespace netsph
