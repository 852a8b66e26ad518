#include "netsph/io/checkpoint_file.hpp"

#include <fmt/format.h>

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

template <class T>
void write_group(hid_t file, const char* group, const std::map<std::string, std::vector<T>>& m,
                 hid_t ftype, hid_t mtype, const fs::path& path) {
  h5::Handle g(check_id(H5Gcreate2(file, group, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path,
                        std::string("cannot create group ") + group),
               H5Gclose);
  for (const auto& [name, values] : m) {
    const std::string what = fmt::format("cannot write /{}/{}", group, name);
    const hsize_t n = values.size();
    h5::Handle space(check_id(H5Screate_simple(1, &n, nullptr), path, what), H5Sclose);
    h5::Handle d(check_id(H5Dcreate2(g.get(), name.c_str(), ftype, space.get(), H5P_DEFAULT,
                                     H5P_DEFAULT, H5P_DEFAULT),
                          path, what),
                 H5Dclose);
    if (n > 0) {
      check_status(H5Dwrite(d.get(), mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), path,
                   what);
    }
  }
}

template <class T>
void read_group(hid_t file, const char* group, std::map<std::string, std::vector<T>>& m,
                hid_t mtype, const fs::path& path) {
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

void write_checkpoint_file(const fs::path& path, const CheckpointData& data) {
  h5::SilenceErrors quiet;
  const fs::path tmp = path.string() + ".tmp";
  {
    h5::Handle file(check_id(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), tmp,
                             "cannot create the checkpoint"),
                    H5Fclose);
    std::map<std::string, std::vector<std::uint8_t>> texts;
    for (const auto& [k, v] : data.text) texts[k] = std::vector<std::uint8_t>(v.begin(), v.end());
    texts["_magic"] = std::vector<std::uint8_t>(kMagic, kMagic + std::string_view(kMagic).size());
    write_group(file.get(), "f64", data.f64, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, tmp);
    write_group(file.get(), "f32", data.f32, H5T_IEEE_F32LE, H5T_NATIVE_FLOAT, tmp);
    write_group(file.get(), "u32", data.u32, H5T_STD_U32LE, H5T_NATIVE_UINT32, tmp);
    write_group(file.get(), "u8", data.u8, H5T_STD_U8LE, H5T_NATIVE_UINT8, tmp);
    write_group(file.get(), "text", texts, H5T_STD_U8LE, H5T_NATIVE_UINT8, tmp);
    check_status(file.close(), tmp, "cannot finish the checkpoint (disk full?)");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw Error(path.string(), "cannot replace the checkpoint: " + ec.message());
  }
}

CheckpointData read_checkpoint_file(const fs::path& path) {
  h5::SilenceErrors quiet;
  if (!fs::exists(path)) throw Error(path.string(), "no checkpoint here");
  h5::Handle file(check_id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path,
                           "cannot open the checkpoint"),
                  H5Fclose);
  CheckpointData data;
  data.source = path.string();
  read_group(file.get(), "f64", data.f64, H5T_NATIVE_DOUBLE, path);
  read_group(file.get(), "f32", data.f32, H5T_NATIVE_FLOAT, path);
  read_group(file.get(), "u32", data.u32, H5T_NATIVE_UINT32, path);
  read_group(file.get(), "u8", data.u8, H5T_NATIVE_UINT8, path);
  std::map<std::string, std::vector<std::uint8_t>> texts;
  read_group(file.get(), "text", texts, H5T_NATIVE_UINT8, path);
  for (const auto& [k, v] : texts) data.text[k] = std::string(v.begin(), v.end());
  if (data.text["_magic"] != kMagic) throw Error(path.string(), "not a netsph checkpoint");
  data.text.erase("_magic");
  return data;
}

}  // namespace netsph
