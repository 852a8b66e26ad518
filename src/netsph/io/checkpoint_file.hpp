#pragma once
// A checkpoint on disk: named arrays of doubles, floats, 32-bit and 8-bit unsigned integers and
// texts in one HDF5 file (groups /f64, /f32, /u32, /u8, /text), stored bit for bit, so that a
// run restarted from it continues exactly as the run that wrote it would have. What the arrays
// hold is the business of the code that fills them (solver/checkpoint.hpp); this file only
// stores them. Written to a temporary file and renamed, so that a run that dies while writing
// keeps its previous checkpoint.
#include <cstdint>
#include <filesystem>
#include <map>
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
};

/// Throws netsph::Error naming the file on failure; the previous file at `path` survives it.
void write_checkpoint_file(const std::filesystem::path& path, const CheckpointData& data);
/// Throws netsph::Error naming the file when it cannot be read or is not a checkpoint.
CheckpointData read_checkpoint_file(const std::filesystem::path& path);

}  // namespace netsph
