#include "netsph/io/hdf5_layout.hpp"

#include <algorithm>
#include <array>

namespace netsph::h5 {

hsize_t chunk_rows(hsize_t rows, hsize_t width) {
  const hsize_t most = std::max<hsize_t>(1, kChunkElements / std::max<hsize_t>(1, width));
  return std::clamp<hsize_t>(rows, 1, most);
}

Handle checksummed_layout(hsize_t rows_per_chunk, hsize_t width,
                          const std::filesystem::path& path) {
  const std::string what = "cannot set up a checksummed dataset";
  Handle dcpl(check_id(H5Pcreate(H5P_DATASET_CREATE), path, what), H5Pclose);
  const std::array<hsize_t, 2> chunk = {rows_per_chunk, width};
  check_status(H5Pset_chunk(dcpl.get(), width == 1 ? 1 : 2, chunk.data()), path, what);
  check_status(H5Pset_fletcher32(dcpl.get()), path, what);
  check_status(H5Pset_fill_time(dcpl.get(), H5D_FILL_TIME_NEVER), path, what);
  return dcpl;
}

Handle uncached_access(const std::filesystem::path& path) {
  const std::string what = "cannot set up a dataset's access";
  Handle dapl(check_id(H5Pcreate(H5P_DATASET_ACCESS), path, what), H5Pclose);
  check_status(H5Pset_chunk_cache(dapl.get(), 0, 0, H5D_CHUNK_CACHE_W0_DEFAULT), path, what);
  return dapl;
}

bool has_checksum(hid_t dataset) {
  const Handle dcpl(H5Dget_create_plist(dataset), H5Pclose);
  if (!dcpl.valid()) return false;
  unsigned flags = 0;
  std::size_t values = 0;
  const bool found = H5Pget_filter_by_id2(dcpl.get(), H5Z_FILTER_FLETCHER32, &flags, &values,
                                          nullptr, 0, nullptr, nullptr) >= 0;
  H5Eclear2(H5E_DEFAULT);  // "not found" is an error on HDF5's stack; this thread's, so cleared
  return found;
}

}  // namespace netsph::h5
