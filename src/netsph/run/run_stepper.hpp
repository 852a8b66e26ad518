#pragma once
// What run_simulation advances and what its outputs read. One process: the Simulation itself
// (SingleStepper). A distributed run (distributed/distributed_stepper.hpp): every process
// steps its part; process 0 holds a Simulation of the case without particles, the view, whose
// time, bodies and nets refresh_view() brings up to date, and reads the particles through
// particles(), operations in which the other processes take part (serve_outputs()).
#include <cstdint>
#include <string>

#include "netsph/run/output_particles.hpp"
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

  /// The state the outputs read (time, bodies, nets, diagnostics), on the process that writes
  /// them; null on the others.
  virtual const Simulation* view() const = 0;
  /// Brings the view to the present time, bodies, nets and diagnostics (no communication).
  virtual void refresh_view() = 0;
  /// What the outputs read of the run's particles, on the view's process.
  virtual OutputParticles& particles() = 0;
  /// On the view's process, once its outputs of this point of the run are written: releases
  /// the others from serve_outputs().
  virtual void outputs_written() {}
  /// On the view's process, when an output failed with `message`: the others stop too.
  virtual void outputs_failed(const std::string& /*message*/) {}
  /// On the other processes meanwhile: take part in the view's reads of the particles until
  /// it is done; throws netsph::Error with its message when its outputs failed.
  virtual void serve_outputs() {}
  /// True on every process when true on any (a stop request).
  virtual bool any(bool flag) { return flag; }
  /// At the end of the run (collective): report what only the stepper knows.
  virtual void finish() {}
};

/// One process: the simulation is its own view.
class SingleStepper final : public RunStepper {
 public:
  explicit SingleStepper(Simulation& sim) : sim_(sim), particles_(sim) {}
  const CaseSpec& spec() const override { return sim_.spec(); }
  void step() override { sim_.step(); }
  double time() const override { return sim_.time(); }
  std::int64_t steps() const override { return sim_.steps(); }
  std::uint64_t particle_count() const override { return sim_.particle_count(); }
  double bytes_per_particle() const override { return sim_.bytes_per_particle(); }
  const Simulation* view() const override { return &sim_; }
  void refresh_view() override {}
  OutputParticles& particles() override { return particles_; }

 private:
  Simulation& sim_;
  SimulationParticles particles_;
};

}  // namespace netsph
