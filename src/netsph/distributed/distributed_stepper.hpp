#pragma once
// A distributed run as run_stepped() drives it (run/run_stepper.hpp): every process steps
// its DistributedSimulation; process 0 also holds the view, a Simulation of the case without
// particles whose time, bodies, nets and diagnostics the outputs read. The outputs' reads of the
// particles (output_particles.hpp) are collective operations that process 0 names to the others,
// which serve them until it says it is done: measures and probe samples summed over each process's
// own particles, snapshots and checkpoints written from one process's particles at a time. So
// no process holds the whole run's particles while it runs, and a step without outputs costs
// one broadcast. Checkpoints hold the whole state: a distributed run can be continued as one
// process.
#include <algorithm>
#include <memory>

#include "netsph/distributed/distributed_simulation.hpp"
#include "netsph/run/run_stepper.hpp"

namespace netsph {

class DistributedStepper final : public RunStepper {
 public:
  /// Collective, like DistributedSimulation's constructor; `resume`: a checkpoint to continue
  /// from (written by a run on any number of processes), or null.
  DistributedStepper(const CaseSpec& spec, Collectives& coll,
                     const CheckpointData* resume = nullptr, RebalancePolicy rebalance = {});
  ~DistributedStepper() override;

  const CaseSpec& spec() const override { return sim_.local().spec(); }
  void step() override { sim_.step(); }
  double time() const override { return sim_.local().time(); }
  std::int64_t steps() const override { return sim_.local().steps(); }
  std::uint64_t particle_count() const override { return sim_.particle_count(); }
  double bytes_per_particle() const override;
  int processes() const override { return coll_.size(); }
  const Simulation* view() const override { return view_.get(); }
  void refresh_view() override;
  OutputParticles& particles() override;
  void outputs_written() override;
  void outputs_failed(const std::string& message) override;
  void serve_outputs() override;
  bool any(bool flag) override { return coll_.min(flag ? 0 : 1) == 0; }
  /// Logs each process's time on its own work, waiting for the others in the step's
  /// reductions (the work's imbalance) and in the exchanges.
  void finish() override;

  const DistributedSimulation& simulation() const { return sim_; }
  /// The largest piece the outputs get of a process's particles (default 2^18 rows): process 0
  /// holds one process's packed bytes and one such piece while it writes them.
  void set_output_block_rows(std::size_t rows) { block_rows_ = std::max<std::size_t>(rows, 1); }

 private:
  class Reads;
  // The outputs' reads of the particles, on every process (collective): process 0 passes the
  // outputs' arguments and gets the results, the others serve.
  GlobalMeasures measure_all();
  void sample_all(std::span<const Vec3d> points, std::span<ShepardValue> values);
  std::uint64_t count_all(ParticleSelection which);
  void pieces_all(ParticleSelection which, const std::function<void(const ParticleSet&)>& take);

  Collectives& coll_;
  DistributedSimulation sim_;
  std::unique_ptr<Simulation> view_;  // process 0 only
  std::unique_ptr<Reads> reads_;      // process 0 only
  std::size_t block_rows_ = std::size_t{1} << 18;
};

}  // namespace netsph
