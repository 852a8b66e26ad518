#pragma once
// A Simulation split over processes (MPI ranks, or threads in the tests) by slabs along the
// axis the particles spread furthest (slab_partition.hpp). Every process keeps its own
// particles and a halo, and steps them with the CPU backend; dt, the bodies' loads and the
// largest speed are reduced over the processes inside the step (solver/step_partition.hpp),
// and particles move between processes before the next (particle_exchange.hpp). Bodies and
// nets are advanced by every process alike from the summed loads.
//
// Between steps each process's particles are those the step moved, sorted as at its start,
// as one process's are: the outputs measure and sample each process's own particles with its
// grid and sum them over the processes (measure_own, sample_own), and take the particles
// themselves from one process at a time (pack_own; distributed_stepper.hpp).
//
// The slabs are cut again as the flow moves particles between them (RebalancePolicy): every
// few steps the processes compare their own work (particle counts weighted as at the start),
// and when the busiest is above the mean by the threshold, the cuts are chosen anew from the
// summed histograms of their particles and the particles that changed slab move at once.
//
// Each process builds only its part of the scene (scene_parts.hpp, build_scene_part), so no
// process but the outputs' (DistributedStepper) needs the memory of the whole case; a restored
// run keeps the checkpoint's particles in its part, though every process reads the whole
// file. Not yet distributed: the device backends.
#include <memory>

#include "netsph/distributed/collectives.hpp"
#include "netsph/distributed/particle_exchange.hpp"
#include "netsph/distributed/slab_partition.hpp"
#include "netsph/run/output_particles.hpp"
#include "netsph/solver/simulation.hpp"
#include "netsph/solver/step_partition.hpp"

namespace netsph {

/// When a distributed run cuts its slabs again.
struct RebalancePolicy {
  /// Steps between two comparisons of the processes' own work (one reduction of a number per
  /// process); 0: the slabs stay as cut at the start.
  int check_every = 20;
  /// Cut again when the busiest process's own work exceeds the mean by this factor: the
  /// others wait for it in every reduction of the step.
  double threshold = 1.1;
};

class DistributedSimulation final : public StepPartition {
 public:
  /// Collective. Throws netsph::Error (on every process alike) for more processes than the
  /// domain has cells along its axis, or another backend than the CPU's. `resume`:
  /// a checkpoint (of a run on any number of processes) to continue from, or null.
  DistributedSimulation(const CaseSpec& spec, Collectives& coll,
                        const CheckpointData* resume = nullptr, RebalancePolicy rebalance = {});
  ~DistributedSimulation() override;

  /// One step on every process (collective), after the exchange of the particles the last one
  /// moved. Throws SimulationUnstable on every process alike when any of them finds the state
  /// unusable, with that process's diagnosis.
  void step();

  /// This process's part: its own particles and the halo.
  const Simulation& local() const { return *local_; }
  const SlabPartition& slabs() const { return slabs_; }
  Collectives& collectives() const { return coll_; }
  /// The particles of the whole run (every process knows it: the run creates none, and
  /// losses are summed after each step).
  std::uint64_t particle_count() const {
    return count_base_ + diag_.open.created - diag_.open.removed - lost_total_;
  }
  /// The particles this process owns.
  std::size_t owned_count() const { return exchange_.owned_count(); }
  /// Diagnostics of the whole run: lost particles counted over all processes.
  const StepDiagnostics& diagnostics() const { return diag_; }

  /// Seconds this process spent on its own work in the steps, waiting in the steps'
  /// reductions (for the slowest process: the imbalance), and in the exchanges after them.
  double work_seconds() const { return step_seconds_ - wait_seconds_; }
  double wait_seconds() const { return wait_seconds_; }
  double exchange_seconds() const { return exchange_seconds_; }
  /// How many times the slabs were cut again.
  int rebalances() const { return rebalances_; }
  /// This process's share of a step's work: its own particles weighted by particle_work.
  double own_work() const;

  /// Collective (for tests): process 0 passes a Simulation of the same case, which receives
  /// every process's own particles and the run's time, bodies, nets and diagnostics; the
  /// others pass null.
  void gather_into(Simulation* whole) const;

  // This process's share of the outputs' reads (distributed_simulation_outputs.cpp).
  /// The measures of its own particles.
  GlobalMeasures measure_own() const;
  /// The Shepard sums at `points` over its own fluid particles.
  void sample_own(std::span<const Vec3d> points, std::span<ShepardSums> sums) const;
  /// Its own particles of `which`: how many, and packed (ParticleExchange::unpack).
  std::uint64_t count_own(ParticleSelection which) const;
  Bytes pack_own(ParticleSelection which) const;

  // StepPartition
  bool owns(const Vec3d& p) const override { return slabs_.owner_of(p) == coll_.rank(); }
  double global_max(double v) const override;
  void global_sum(std::span<double> v) const override;
  void number_created(ParticleSet& p, std::size_t first, const OpenBoundaryEvents& events) override;

 private:
  void check_lost(const ExchangeReport& report);
  /// Collective: sends the particles the last step moved to their owners, and the halo
  /// (and cuts the slabs again when due); returns what check_lost still has to count.
  ExchangeReport exchange_particles();
  /// keep[i]: whether this process owns particle i (and, for the snapshots, it lies in their
  /// region).
  std::vector<std::uint8_t> own_mask(ParticleSelection which) const;
  /// Collective: cuts the slabs again if the processes' own work is out of balance, and moves
  /// the particles that changed slab.
  void rebalance_if_needed();

  Collectives& coll_;
  std::unique_ptr<Simulation> local_;
  // What the halo width depends on besides the cuts, from every process's particles at the
  // start.
  std::vector<ZoneGeometry> zones_;
  GhostReach ghost_reach_;
  SlabPartition slabs_;            // after the two above, which its halo width needs
  ParticleExchange exchange_;      // after slabs_, which it refers to
  std::size_t initial_fluid_ = 0;  // of the whole case
  std::uint64_t lost_total_ = 0;   // over all processes
  // The case's particles at the start less the events before it (restored runs), so that the
  // run's count is this + created - removed - lost (all processes).
  std::uint64_t count_base_ = 0;
  OpenBoundaryCounts open_base_;  // the restored run's events (every process has them)
  double step_seconds_ = 0, exchange_seconds_ = 0;
  mutable double wait_seconds_ = 0;  // in the reductions the step calls
  RebalancePolicy rebalance_;
  int rebalances_ = 0;
  bool exchange_due_ = false;  // the last step moved particles the exchange has not sent
  std::vector<StepDiagnostics::Lost> last_lost_;
  StepDiagnostics diag_;
};

}  // namespace netsph
