#pragma once
// A distributed run as run_stepped() drives it (solver/run_stepper.hpp): every process steps
// its DistributedSimulation; process 0 also holds a whole Simulation of the case, the view the
// outputs read, into which the processes' particles are gathered only when an output needs
// them (snapshots, series rows, probe samples, checkpoints), so a step costs no gather.
// Checkpoints hold the whole state: a distributed run can be continued as one process.
#include <memory>

#include "netsph/distributed/distributed_simulation.hpp"
#include "netsph/solver/run_stepper.hpp"

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
  void refresh_view(bool particles) override { sim_.gather_into(view_.get(), particles); }
  bool from_view_process(bool flag) override;
  bool any(bool flag) override { return coll_.min(flag ? 0 : 1) == 0; }
  /// Logs each process's time on its own work, waiting for the others in the step's
  /// reductions (the work's imbalance) and in the exchanges.
  void finish() override;

  const DistributedSimulation& simulation() const { return sim_; }

 private:
  Collectives& coll_;
  DistributedSimulation sim_;
  std::unique_ptr<Simulation> view_;  // process 0 only
};

}  // namespace netsph
