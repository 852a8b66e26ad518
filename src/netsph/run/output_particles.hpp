#pragma once
// What the outputs read of a run's particles (series rows and summary: measures; probes:
// samples; snapshots and checkpoints: the particles themselves), computed where the particles
// are. On one process that is the simulation's own set (SimulationParticles). In a distributed
// run each process measures and samples its own particles and the sums are reduced, and the
// particles reach the writing process one process's share at a time
// (distributed/distributed_stepper.hpp): no process holds the whole run for its outputs.
#include <cstdint>
#include <functional>
#include <span>

#include "netsph/solver/simulation.hpp"
#include "netsph/sph/particle_tally.hpp"
#include "netsph/sph/shepard.hpp"

namespace netsph {

/// Global quantities of the current state (double sums, fluid particles only unless noted).
struct GlobalMeasures {
  std::size_t fluid = 0, walls = 0, buffer = 0;
  double kinetic_energy = 0;                ///< J (J/m in 2D)
  double fluid_mass = 0;                    ///< kg (kg/m in 2D)
  double max_speed = 0;                     ///< m/s
  double min_density = 0, max_density = 0;  ///< kg/m^3 (0 without fluid)
};

/// The tally (sph/particle_tally.hpp) of the particles of `p` (those with keep[i] != 0 when
/// `keep` is given), each of mass `mass`.
ParticleTally tally_particles(const ParticleSet& p, double mass,
                              std::span<const std::uint8_t> keep = {});
/// The measures a tally gives (0 for the densities without fluid).
GlobalMeasures measures_of(const ParticleTally& t, double mass);
/// The measures of the particles of `p` (those with keep[i] != 0 when `keep` is given), each
/// of mass `mass`.
GlobalMeasures measure_particles(const ParticleSet& p, double mass,
                                 std::span<const std::uint8_t> keep = {});
GlobalMeasures measure(const Simulation& sim);

/// Whether a particle at x goes into the snapshots (inside output.snapshot_region, or all).
bool in_snapshot_region(const CaseSpec& spec, const Vec3d& x);
/// How many of the simulation's particles a snapshot would hold.
std::size_t snapshot_particle_count(const Simulation& sim);

/// Which particles an output takes.
enum class ParticleSelection : std::uint8_t {
  All,       ///< checkpoints
  Snapshot,  ///< those in output.snapshot_region (all without one)
};

class OutputParticles {
 public:
  virtual ~OutputParticles() = default;
  /// The measures of every particle of the run.
  virtual GlobalMeasures measure() = 0;
  /// Shepard-corrected values of the run's fluid at `points` (backend/cpu/probe_pass.hpp).
  virtual void sample(std::span<const Vec3d> points, std::span<ShepardValue> values) = 0;
  /// How many particles pieces(which) hands over in all.
  virtual std::uint64_t count(ParticleSelection which) = 0;
  /// Calls take() with the run's particles of `which`, in pieces (one process's at a time, in
  /// blocks of rows; one piece on one process); a piece lives only during its call.
  virtual void pieces(ParticleSelection which,
                      const std::function<void(const ParticleSet&)>& take) = 0;
};

/// One process: the simulation's own particles.
class SimulationParticles final : public OutputParticles {
 public:
  explicit SimulationParticles(const Simulation& sim) : sim_(sim) {}
  GlobalMeasures measure() override { return netsph::measure(sim_); }
  void sample(std::span<const Vec3d> points, std::span<ShepardValue> values) override;
  std::uint64_t count(ParticleSelection which) override;
  void pieces(ParticleSelection which,
              const std::function<void(const ParticleSet&)>& take) override;

 private:
  const Simulation& sim_;
};

}  // namespace netsph
