#include "netsph/distributed/distributed_stepper.hpp"

namespace netsph {

DistributedStepper::DistributedStepper(const CaseSpec& spec, Collectives& coll,
                                       const CheckpointData* resume)
    : coll_(coll), sim_(spec, coll, resume) {
  if (coll_.rank() == 0) {
    view_ = std::make_unique<Simulation>(spec, StepBackend::Cpu);
    if (resume) view_->restore_state(*resume);
  }
}

DistributedStepper::~DistributedStepper() = default;

double DistributedStepper::bytes_per_particle() const {
  // This process's memory over the particles it owns: the halo's copies count against them.
  const Simulation& local = sim_.local();
  const double owned = static_cast<double>(std::max<std::size_t>(sim_.owned_count(), 1));
  return local.bytes_per_particle() * static_cast<double>(local.particle_count()) / owned;
}

bool DistributedStepper::from_view_process(bool flag) {
  // One reduction: the others vote "no".
  return coll_.min(coll_.rank() == 0 && flag ? 0 : 1) == 0;
}

}  // namespace netsph
