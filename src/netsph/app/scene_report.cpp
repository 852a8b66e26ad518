#include "netsph/app/scene_report.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_set>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "netsph/io/snapshot_writer.hpp"
#include "netsph/run/output_schedule.hpp"

namespace netsph::app {

void log_scene(const Simulation& sim, OutputParticles& particles, double setup_seconds) {
  const Scene& s = sim.scene();
  const FluidModel& m = sim.model();
  const CaseSpec& spec = sim.spec();
  const GlobalMeasures counts = particles.measure();
  const std::uint64_t total = particles.count(ParticleSelection::All);
  spdlog::info("{}D, dp = {:g} m, h = {:g} m ({} kernel), c0 = {:.4g} m/s, rho0 = {:g} kg/m^3",
               m.dims, spec.simulation.dp, static_cast<double>(m.kernel.h),
               name_of(kKernelTypeLabels, m.kernel_type), s.sound_speed,
               static_cast<double>(m.eos.rho0));
  spdlog::info("particles: {} fluid, {} wall, {} body, {} open-boundary buffer, {} total{}",
               counts.fluid, counts.walls, total - counts.fluid - counts.walls - counts.buffer,
               counts.buffer, total,
               setup_seconds >= 0 ? fmt::format(" (set up in {:.1f} s)", setup_seconds) : "");
  const char* unit = m.dims == 2 ? "/m" : "";
  // A net's knots are bodies too (hundreds of them): one line per net instead of one per knot.
  std::vector<char> knot(s.bodies.size(), 0);
  for (const CoupledNet& net : sim.nets()) {
    const std::size_t n = net.model.knots.size();
    std::uint32_t fewest = ~0u, most = 0;
    double mass = 0;
    for (std::size_t k = net.first_body; k < net.first_body + n && k < s.bodies.size(); ++k) {
      knot[k] = 1;
      fewest = std::min(fewest, s.bodies[k].count);
      most = std::max(most, s.bodies[k].count);
      mass += s.bodies[k].inertia.mass;
    }
    spdlog::info("  net {:<13} {:>9} knot bodies of {} particles, mass {:.4g} kg{} in all",
                 net.model.name, n,
                 fewest == most ? fmt::format("{}", most) : fmt::format("{}-{}", fewest, most),
                 mass, unit);
  }
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    if (knot[k]) continue;
    const RigidBody& b = s.bodies[k];
    spdlog::info("  body {:<12} {:>9} particles, {} , mass {:.4g} kg{}", b.name, b.count,
                 name_of(b.motion), b.inertia.mass, unit);
  }
  // The bodies' sources are listed above.
  std::unordered_set<std::string> bodies;
  for (const RigidBody& b : s.bodies) bodies.insert(b.name);
  for (const auto& src : s.sources)
    if (!bodies.contains(src.name))
      spdlog::info("  {:<16} {:>10} particles", src.name, src.particles);
  spdlog::info("domain [{:.4g}, {:.4g}, {:.4g}] .. [{:.4g}, {:.4g}, {:.4g}] m{}", s.domain_min.x,
               s.domain_min.y, s.domain_min.z, s.domain_max.x, s.domain_max.y, s.domain_max.z,
               spec.domain.given ? "" : " (default: particles' bounding box + margin)");
  for (const auto& w : s.warnings) spdlog::warn("{}", w);
}

SnapshotVolume snapshot_volume(const Simulation& sim, OutputParticles& particles) {
  const CaseSpec& spec = sim.spec();
  SnapshotVolume v;
  v.particles = particles.count(ParticleSelection::Snapshot);
  v.bytes_each = static_cast<double>(v.particles * SnapshotWriter::bytes_per_particle());
  const double every = snapshot_interval(spec);
  // The snapshots still to write: from t = 0 the start's and one per interval; a restart's
  // from its own time on, at the (new) interval's multiples after it (RunOutputs::restore_state),
  // not the whole run's (issue 46: a restart announced the count of a run from t = 0).
  const double t0 = sim.time(), end = spec.simulation.end_time;
  if (every <= 0) {
    v.count = 1;
  } else if (t0 <= 0) {
    v.count = std::ceil(end / every - 1e-9) + 1;
  } else {
    v.count = std::max(0.0, std::floor(end / every + 1e-9) - std::floor(schedule_time(t0) / every));
  }
  return v;
}

double checkpoint_bytes(std::uint64_t particles) {
  // A particle's state in a checkpoint: position (3 doubles), velocity and ghost vector (3
  // floats each), density, kind, id and group: 61 B; 64 B with the chunks' checksums and index.
  constexpr double kBytesPerParticle = 64;
  return 2 * kBytesPerParticle * static_cast<double>(particles);
}

bool warn_if_output_overfills(double bytes, const std::string& what,
                              const std::filesystem::path& out) {
  std::error_code ec;
  std::filesystem::path at = std::filesystem::absolute(out, ec);
  while (!std::filesystem::exists(at, ec) && at.has_parent_path() && at != at.parent_path())
    at = at.parent_path();
  const std::filesystem::space_info space = std::filesystem::space(at, ec);
  if (ec) return false;
  const double free_bytes = static_cast<double>(space.available);
  if (bytes <= free_bytes) return false;
  spdlog::warn(
      "the run's outputs ({}) need about {} but {} has {} free: the run would fail when the disk "
      "fills; free space, write elsewhere with -o, or write less (output.snapshot_region, a "
      "larger output.snapshot_every, output.snapshots = false)",
      what, format_bytes(bytes), at.string(), format_bytes(free_bytes));
  return true;
}

std::string format_bytes(double b) {
  return b >= 1e9 ? fmt::format("{:.1f} GB", b / 1e9) : fmt::format("{:.1f} MB", b / 1e6);
}

std::string describe_snapshots(const Simulation& sim, const SnapshotVolume& v) {
  const auto size = format_bytes;
  return fmt::format(
      "snapshots every {:g} s: {:.6g} snapshots of {} particles{}, {} each, {} in all",
      snapshot_interval(sim.spec()), v.count, v.particles,
      sim.spec().output.snapshot_region ? " (inside output.snapshot_region)" : "",
      size(v.bytes_each), size(v.total()));
}

}  // namespace netsph::app
