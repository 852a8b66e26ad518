#pragma once
// A checkpoint on disk: named arrays of doubles, floats, 32-bit and 8-bit unsigned integers and
// texts in one HDF5 file (groups /f64, /f32, /u32, /u8, /text), stored bit for bit, so that a
// run restarted from it continues exactly as the run that wrote it would have. What the arrays
// hold is the business of the code that fills them (solver/simulation_checkpoint.cpp,
// RunOutputs::save_state); this file only stores them. Every dataset, the texts included,
// carries a Fletcher-32 checksum per chunk, and its metadata checksums of its own (HDF5 1.10
// format): a file damaged after it was written is refused when read, naming the dataset.
// Written to a temporary file, synced to the disk and renamed, so that a run that dies while
// writing, or a write that fails (a full disk), keeps the previous checkpoint.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace netsph {

struct CheckpointData {
  std::map<std::string, std::vector<double>> f64;
  std::map<std::string, std::vector<float>> f32;
  std::map<std::string, std::vector<std::uint32_t>> u32;
  std::map<std::string, std::vector<std::uint8_t>> u8;
  std::map<std::string, std::string> text;

  /// The array `name`, or netsph::Error naming the checkpoint's `source` and what is missing.
  const std::vector<double>& reals(const std::string& name) const;
  double real(const std::string& name) const;  ///< the first element of reals(name)
  const std::string& text_of(const std::string& name) const;
  std::string source;  ///< the file it was read from (for messages)
  /// Why the data could not be checked for damage (a checkpoint from before checksums: read,
  /// but the reader should warn), or empty.
  std::string unchecked;
};

/// Arrays that come in pieces (a distributed run's particles, one process's at a time): the
/// function calls `add` with each piece's arrays, every piece naming the same ones (no texts).
using CheckpointPieces =
    std::function<void(const std::function<void(const CheckpointData& piece)>& add)>;

/// Throws netsph::Error naming the file on failure; the previous file at `path` survives it.
/// With `pieces`, the file also holds each of their arrays as the pieces' concatenation, as if
/// `data` had held it whole.
void write_checkpoint_file(const std::filesystem::path& path, const CheckpointData& data,
                           const CheckpointPieces& pieces = {});
/// Throws netsph::Error naming the file when it cannot be read or is not a checkpoint, and
/// naming the dataset too when its data or metadata do not match their checksums.
CheckpointData read_checkpoint_file(const std::filesystem::path& path);

/// Some rows of arrays that hold one row per item (a distributed process's particles): row r
/// of every array named in `arrays` is read when keep() accepts row r of the first, an f64
/// array of `key_width` values per row. Without keep() none is read, not even the key: the
/// arrays come back empty.
struct CheckpointRows {
  std::vector<std::string> arrays;
  std::size_t key_width = 1;
  std::function<bool(std::span<const double> key_row)> keep;
};
/// read_checkpoint_file with only the selected rows of rows.arrays (read in blocks: the
/// others never reach memory); the other arrays whole.
CheckpointData read_checkpoint_file(const std::filesystem::path& path, const CheckpointRows& rows);

}  // namespace netsph
