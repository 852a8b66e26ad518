#pragma once
// Reads a whole dataset of an HDF5 file (a snapshot) for the physics tests.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <vector>

namespace netsph::test {

/// Dataset `name` of `file` as values of mem_type, `per` values per row (3 for vectors).
template <class T>
std::vector<T> read_dataset(const std::filesystem::path& file, const char* name, hid_t mem_type,
                            std::size_t per) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << file;
  if (f < 0) return {};
  const hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
  const hid_t s = H5Dget_space(d);
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(s, dims, nullptr);
  std::vector<T> out(dims[0] * per);
  if (!out.empty()) H5Dread(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
  H5Sclose(s), H5Dclose(d), H5Fclose(f);
  return out;
}

}  // namespace netsph::test
