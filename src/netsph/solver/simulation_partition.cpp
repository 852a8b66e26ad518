// Simulation as one process of a distributed run (distributed/), and the gathered copy of a
// distributed run that its outputs read.
#include "netsph/solver/simulation.hpp"

namespace netsph {

void Simulation::set_partition(StepPartition* partition) {
  if (partition && backend_ != StepBackend::Cpu) {
    throw Error("solver", "a distributed run (more than one MPI process) needs the CPU backend");
  }
  if (partition && absorber_) {
    throw Error(spec_.waves.where.str(),
                "waves.absorption = \"active\" is not supported in a run split over processes "
                "yet (its gauge's elevation would need a reduction every step): run the case on "
                "one process, or use a damping zone");
  }
  partition_ = partition;
  if (!partition_) owned_ = {};
}

void Simulation::mark_owned() {
  owned_.resize(p_.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(p_.size()); ++i)
    owned_[i] = partition_->owns(p_.pos[i]);
}

void Simulation::adopt_global_state(const Simulation& stepped, const StepDiagnostics& diagnostics) {
  time_ = stepped.time_;
  steps_ = stepped.steps_;
  dt_floor_ = stepped.dt_floor_;
  diag_ = diagnostics;
  p_.next_id = stepped.p_.next_id;
  for (std::size_t b = 0; b < scene_.bodies.size(); ++b)
    scene_.bodies[b] = stepped.scene_.bodies[b];
  for (std::size_t n = 0; n < nets_.size(); ++n) {
    nets_[n].model.knots = stepped.nets_[n].model.knots;
    // The same on every process: the samples are reduced over the processes and each solves
    // every net.
    nets_[n].reactions_at_bar = stepped.nets_[n].reactions_at_bar;
    nets_[n].first_knot_reacting_at_bar = stepped.nets_[n].first_knot_reacting_at_bar;
  }
}

void Simulation::adopt_state(const Simulation& stepped, const StepDiagnostics& diagnostics,
                             ParticleSet&& particles) {
  adopt_global_state(stepped, diagnostics);
  const std::uint32_t next_id = p_.next_id;
  p_ = std::move(particles);
  p_.next_id = next_id;
  // The step's own sort: wrapped into periodic axes, ordered by cell, grid() to match.
  sort_particles(false);
  diag_.lost_total = diagnostics.lost_total;  // the sort found none: the exchange dropped them
}

}  // namespace netsph
