#pragma once
// Private to netsph_io: what a checkpoint file holds besides its arrays, shared by its writer
// (checkpoint_file.cpp) and its reader (checkpoint_file_read.cpp).

namespace netsph::checkpoint_format {

/// /text/_magic of the files written now: every dataset chunked with a Fletcher-32 checksum,
/// in the HDF5 1.10 format (metadata checksummed too).
inline constexpr const char* kMagic = "netsph checkpoint 2";
/// /text/_magic of the files written before checksums (contiguous datasets, HDF5 1.8 format).
inline constexpr const char* kMagicBeforeChecksums = "netsph checkpoint 1";

/// The groups of arrays, by element type, and of texts.
inline constexpr const char* kArrayGroups[] = {"f64", "f32", "u32", "u8"};
inline constexpr const char* kTextGroup = "text";

}  // namespace netsph::checkpoint_format
