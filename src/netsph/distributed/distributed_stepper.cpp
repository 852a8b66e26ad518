#include "netsph/distributed/distributed_stepper.hpp"

#include <cstring>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace netsph {

DistributedStepper::DistributedStepper(const CaseSpec& spec, Collectives& coll,
                                       const CheckpointData* resume, RebalancePolicy rebalance)
    : coll_(coll), sim_(spec, coll, resume, rebalance) {
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

void DistributedStepper::finish() {
  const double mine[3] = {sim_.work_seconds(), sim_.wait_seconds(), sim_.exchange_seconds()};
  Bytes b(sizeof mine);
  std::memcpy(b.data(), mine, sizeof mine);
  const std::vector<Bytes> all = coll_.gather(b);
  if (all.empty()) return;
  std::string line;
  for (std::size_t r = 0; r < all.size(); ++r) {
    double t[3];
    std::memcpy(t, all[r].data(), sizeof t);
    line += fmt::format("{}process {}: {:.1f} s working, {:.1f} s waiting, {:.1f} s exchanging",
                        line.empty() ? "" : "; ", r, t[0], t[1], t[2]);
  }
  spdlog::info("distributed run: {}; slabs cut again {} time{}", line, sim_.rebalances(),
               sim_.rebalances() == 1 ? "" : "s");
}

bool DistributedStepper::from_view_process(bool flag) {
  // One reduction: the others vote "no".
  return coll_.min(coll_.rank() == 0 && flag ? 0 : 1) == 0;
}

}  // namespace netsph
