#pragma once
// Human-readable description of a built scene: particle counts per source, model constants,
// domain and memory. Shared by `run` (logged) and `check` (printed).
#include <cstdint>
#include <filesystem>
#include <string>

#include "netsph/run/output_particles.hpp"
#include "netsph/solver/simulation.hpp"

namespace netsph::app {

/// The scene of `sim`, with the counts of `particles` (the run's particles: a distributed
/// run's view holds none). setup_seconds: how long the case took to build (not shown when
/// negative).
void log_scene(const Simulation& sim, OutputParticles& particles, double setup_seconds = -1);

/// What the particle snapshots of a whole run will take on disk, from the present particles.
struct SnapshotVolume {
  std::size_t particles = 0;  ///< per snapshot (inside output.snapshot_region when given)
  double bytes_each = 0;      ///< one snapshot file
  /// Snapshots over the run, t = 0 and the end included; a double: a tiny snapshot_every over
  /// a long run overflowed an int, and the disk-space warning then never fired.
  double count = 0;
  double total() const { return bytes_each * count; }
};
SnapshotVolume snapshot_volume(const Simulation& sim, OutputParticles& particles);
/// "snapshots every 0.1 s: 41 snapshots of 3.3e6 particles (inside output.snapshot_region), 190 MB
/// each, 7.6 GB in all"
std::string describe_snapshots(const Simulation& sim, const SnapshotVolume& v);
/// What a run's checkpoint takes on disk, twice over: the new one is written beside the last
/// before it replaces it (io/checkpoint_file.hpp).
double checkpoint_bytes(std::uint64_t particles);
/// Warns when the free space where `out` would lie (its nearest existing folder) is less than
/// `bytes`, the run's estimated output (`what` says of what); true when it warned. A run that
/// fills the disk fails at its next write, hours in.
bool warn_if_output_overfills(double bytes, const std::string& what,
                              const std::filesystem::path& out);
/// "5.8 MB", "7.7 GB"
std::string format_bytes(double bytes);

}  // namespace netsph::app
