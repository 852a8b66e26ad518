#pragma once
// Private to netsph_io: how netsph lays out the datasets it writes. Every dataset is chunked
// and carries HDF5's Fletcher-32 checksum per chunk, which every HDF5 reader (netsph, h5py,
// ParaView) verifies when it reads the chunk: a byte changed on disk after the write is then
// a read error, never a silently different number.
#include <hdf5.h>

#include <filesystem>

#include "netsph/io/hdf5_handle.hpp"

namespace netsph::h5 {

/// Elements per chunk at most (64 Ki: 512 KiB of doubles, small enough to read back in a
/// partial write, large enough that the chunk index and the checksums cost nothing).
constexpr hsize_t kChunkElements = hsize_t{1} << 16;

/// Rows per chunk of a dataset of `rows` rows of `width` elements: the whole dataset when it
/// is small (a chunk is stored whole, so a larger one would waste the difference), at least
/// one row (a chunk cannot be empty, even for a dataset of no rows).
hsize_t chunk_rows(hsize_t rows, hsize_t width);

/// Creation properties of a dataset of rank 1 (`width` 1) or 2 (rows x `width`) with chunks of
/// `rows_per_chunk` rows, each checksummed (Fletcher-32). No fill value is written: every
/// element is written by the caller.
Handle checksummed_layout(hsize_t rows_per_chunk, hsize_t width, const std::filesystem::path& path);

/// Access properties without a chunk cache: each H5Dwrite then writes its chunks to the file
/// at once, so that a full disk fails the write that met it, and closing the dataset has
/// nothing left to write (a close that fails leaves HDF5 holding an object it cannot free).
Handle uncached_access(const std::filesystem::path& path);

/// Whether `dataset` is stored with the Fletcher-32 checksum.
bool has_checksum(hid_t dataset);

}  // namespace netsph::h5
