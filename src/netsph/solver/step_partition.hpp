#pragma once
// What a Simulation needs from a domain decomposition (distributed/): each process steps the
// particles it owns plus a halo of copies of its neighbours' particles, and takes the step's
// global decisions (dt, the bodies' loads, the largest speed) over the particles it owns,
// together with the other processes. Every process calls these in the same order.
#include <span>

#include "netsph/boundary/open_boundary.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

class StepPartition {
 public:
  virtual ~StepPartition() = default;
  /// Whether this process owns a particle at `pos`: exactly one process owns any position.
  virtual bool owns(const Vec3d& pos) const = 0;
  /// The largest of every process's value.
  virtual double global_max(double v) const = 0;
  /// Element-wise sums over the processes, bit for bit the same on all of them (the bodies
  /// they advance must stay identical).
  virtual void global_sum(std::span<double> v) const = 0;
  /// After the open boundaries' update: the particles it created (appended to `p` from index
  /// `first`, in the order of events.created_from) get ids that every process holding a copy
  /// agrees on and that are unique over the run; the removed ones stop being this process's.
  /// Called every step by every process of a case with open boundaries.
  virtual void number_created(ParticleSet& p, std::size_t first,
                              const OpenBoundaryEvents& events) = 0;
};

}  // namespace netsph
