// DistributedSimulation: each process's share of the outputs' reads, which
// distributed_stepper.cpp sums over the processes or hands to process 0 one process at a time.
// Between steps every particle is owned by exactly one process (the exchange's ids), so sums
// over each process's own particles add up to the whole run's.
#include "netsph/backend/cpu/probe_pass.hpp"
#include "netsph/distributed/distributed_simulation.hpp"

namespace netsph {

std::vector<std::uint8_t> DistributedSimulation::own_mask(ParticleSelection which) const {
  const ParticleSet& p = local_->particles();
  const bool region = which == ParticleSelection::Snapshot && local_->spec().output.snapshot_region;
  std::vector<std::uint8_t> keep(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    keep[i] = exchange_.owned(p.id[i]) && (!region || in_snapshot_region(local_->spec(), p.pos[i]));
  }
  return keep;
}

GlobalMeasures DistributedSimulation::measure_own() const {
  return measure_particles(local_->particles(), local_->model().mass,
                           own_mask(ParticleSelection::All));
}

void DistributedSimulation::sample_own(std::span<const Vec3d> points,
                                       std::span<ShepardSums> sums) const {
  // The grid is the one the last step sorted its particles into (this process's own and its
  // halo), searched with the skin that covers their motion over a step.
  point_sums(local_->model(), local_->grid(), local_->particles(), points, sums,
             own_mask(ParticleSelection::All));
}

std::uint64_t DistributedSimulation::count_own(ParticleSelection which) const {
  if (which == ParticleSelection::All || !local_->spec().output.snapshot_region)
    return exchange_.owned_count();
  std::uint64_t n = 0;
  for (const std::uint8_t k : own_mask(which)) n += k;
  return n;
}

Bytes DistributedSimulation::pack_own(ParticleSelection which) const {
  const bool all = which == ParticleSelection::All || !local_->spec().output.snapshot_region;
  return all ? exchange_.pack_owned(local_->particles())
             : exchange_.pack_owned(local_->particles(), own_mask(which));
}

}  // namespace netsph
