#pragma once
// What run_simulation advances and what its outputs read. One process: the Simulation itself
// (SingleStepper). A distributed run (distributed/distributed_stepper.hpp): every process
// steps its part, and process 0 holds a whole Simulation of the case, the view, which
// refresh_view() brings up to date before the outputs read it.
#include <cstdint>

#include "netsph/solver/simulation.hpp"

namespace netsph {

class RunStepper {
 public:
  virtual ~RunStepper() = default;
  virtual const CaseSpec& spec() const = 0;
  /// One step (collective).
  virtual void step() = 0;
  virtual double time() const = 0;
  virtual std::int64_t steps() const = 0;
  /// Particles of the whole run.
  virtual std::uint64_t particle_count() const = 0;
  /// Bytes per particle held by this process.
  virtual double bytes_per_particle() const = 0;
  /// Processes stepping the run.
  virtual int processes() const { return 1; }

  /// The state the outputs read, on the process that writes them; null on the others.
  virtual const Simulation* view() const = 0;
  /// Brings the view to the present time, bodies and nets; with `particles` also its particles
  /// (collective: every process calls it with the same flag).
  virtual void refresh_view(bool particles) = 0;
  /// Process 0's flag on every process.
  virtual bool from_view_process(bool flag) { return flag; }
  /// True on every process when true on any (a stop request).
  virtual bool any(bool flag) { return flag; }
  /// At the end of the run (collective): report what only the stepper knows.
  virtual void finish() {}
};

/// One process: the simulation is its own view.
class SingleStepper final : public RunStepper {
 public:
  explicit SingleStepper(Simulation& sim) : sim_(sim) {}
  const CaseSpec& spec() const override { return sim_.spec(); }
  void step() override { sim_.step(); }
  double time() const override { return sim_.time(); }
  std::int64_t steps() const override { return sim_.steps(); }
  std::uint64_t particle_count() const override { return sim_.particle_count(); }
  double bytes_per_particle() const override { return sim_.bytes_per_particle(); }
  const Simulation* view() const override { return &sim_; }
  void refresh_view(bool) override {}

 private:
  Simulation& sim_;
};

}  // namespace netsph
