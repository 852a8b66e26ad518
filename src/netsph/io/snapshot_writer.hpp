#pragma once
// Particle snapshots for ParaView: one HDF5 file per snapshot under <dir>/snapshots/ and one
// XDMF 3 file, <dir>/<base>.xdmf, listing every snapshot written so far as a temporal
// collection. One file per snapshot means a run that dies mid-write loses at most the
// snapshot being written; the XDMF file is replaced atomically after each snapshot. Every
// dataset carries Fletcher-32 checksums (io/hdf5_layout.hpp), which readers verify.
// Explicit Polyvertex connectivity is written because ParaView 5.11's Xdmf3 readers build no
// cells from an implicit one (shared/notes/debian-stack.md, section 2c).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "netsph/core/vec3.hpp"

namespace netsph {

/// One snapshot's particle fields; all spans have the same length (the particle count).
struct SnapshotFields {
  double time = 0;  ///< s
  std::int64_t step = 0;
  std::span<const Vec3d> position;     ///< m
  std::span<const Vec3f> velocity;     ///< m/s
  std::span<const float> density;      ///< kg/m^3
  std::span<const float> pressure;     ///< Pa
  std::span<const std::uint8_t> kind;  ///< particle kind code (0 fluid, 1 boundary, ...)
  std::span<const std::uint32_t> id;   ///< unique particle id
};

class SnapshotWriter;

/// One snapshot written in pieces (a distributed run's processes' particles, in turn):
/// SnapshotWriter::begin() with the total count, append() every piece, finish(). Destroyed
/// unfinished (an error on the way), it removes its file: no half-written snapshot is left.
class SnapshotPieces {
 public:
  SnapshotPieces(SnapshotPieces&&) noexcept;
  ~SnapshotPieces();
  /// Writes the next piece's particles (its time and step are ignored). Throws netsph::Error
  /// on I/O failure, or when the pieces hold more particles than begin() was told.
  void append(const SnapshotFields& piece);
  /// Closes the file and lists it in the XDMF file; throws netsph::Error when the pieces held
  /// fewer particles than begin() was told. Returns the path of the .h5 file.
  std::filesystem::path finish();

 private:
  friend class SnapshotWriter;
  struct Impl;
  explicit SnapshotPieces(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

class SnapshotWriter {
 public:
  /// Creates <dir>/snapshots/ if needed and removes <base>_*.h5 files a previous run left
  /// there (unless `resume`: a restart then calls resume()). `base` names the XDMF file and
  /// the snapshot files.
  explicit SnapshotWriter(std::filesystem::path dir, std::string base = "particles",
                          bool resume = false);

  /// Writes <dir>/snapshots/<base>_NNNNNN.h5 (NNNNNN = snapshot index from 0) and rewrites
  /// <dir>/<base>.xdmf. Returns the path of the .h5 file. Throws netsph::Error on I/O failure.
  std::filesystem::path write(const SnapshotFields& fields);
  /// The same snapshot file, written in pieces: `n` particles in all at `time`, `step`.
  SnapshotPieces begin(double time, std::int64_t step, std::size_t n);

  /// A restarted run: takes over the snapshots its checkpoint lists (one line each,
  /// "<relative .h5 path> <time> <step> <count>", as entries_text() gives them), keeps their
  /// files, removes later ones, and rewrites the XDMF file.
  void resume(const std::string& entries);
  /// The snapshots written so far, for a checkpoint.
  std::string entries_text() const;

  int count() const { return static_cast<int>(entries_.size()); }
  /// Bytes a snapshot file holds per particle (its datasets, uncompressed).
  static std::size_t bytes_per_particle();
  std::filesystem::path xdmf_path() const;

 private:
  friend class SnapshotPieces;
  struct Entry {
    std::string h5_relative;  // path of the .h5 relative to dir_
    double time;
    std::int64_t step;
    std::size_t n;
  };
  void rewrite_xdmf() const;

  std::filesystem::path dir_;
  std::string base_;
  std::vector<Entry> entries_;
};

}  // namespace netsph
