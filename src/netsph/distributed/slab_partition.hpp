#pragma once
// Domain decomposition of a distributed run into slabs along one axis: process r owns every
// particle whose coordinate on that axis (wrapped into a periodic axis, clamped into the
// domain otherwise) lies in [cuts[r], cuts[r+1]), and keeps copies (the halo) of the other
// processes' particles within `halo` of its slab.
//
// Why slabs, and why a wide halo: one exchange per step (after the corrector) is enough when
// every particle a process owns has correct neighbours through both stages of the step. The
// state of a halo copy is exact at the exchange, but its rates are not where its own
// neighbours are missing (within one support of the halo's outer edge); each later stage
// spreads that error one support further in: the mDBC state of a wall copy reaches ghost
// offset + support, the rates of the first pass one support more, the second pass (after the
// predictor) one more. So the halo is the ghost offset along the axis + 3 supports (+ the
// distance particles may move in a step) wide (halo_width), and the owned particles' results
// are those of one process to round-off, without a second exchange at the half step.
#include <span>
#include <vector>

#include "netsph/boundary/open_boundary.hpp"
#include "netsph/core/vec3.hpp"
#include "netsph/distributed/collectives.hpp"
#include "netsph/neighbours/cell_grid.hpp"
#include "netsph/sph/particle_set.hpp"

namespace netsph {

struct SlabPartition {
  int axis = 0;
  std::vector<double> cuts;  ///< ranks + 1 coordinates: cuts.front() and back() bound the domain
  bool periodic = false;     ///< the axis is periodic (its period is back() - front())
  double halo = 0;           ///< m

  int ranks() const { return static_cast<int>(cuts.size()) - 1; }
  /// The coordinate along the axis, wrapped into a periodic axis.
  double coordinate(const Vec3d& p) const;
  /// The process that owns a particle at p (any p, also outside the domain).
  int owner_of(const Vec3d& p) const;
  /// Distance along the axis from p to process r's slab (0 inside it; the nearer image on a
  /// periodic axis).
  double distance_to(int r, const Vec3d& p) const;
  /// The processes other than `r` whose slabs lie within the halo width of r's.
  std::vector<int> halo_neighbours(int r) const;
};

/// A wall or body particle's share of a step's work relative to a fluid particle's, for
/// balancing slabs. An estimate, checked on the 3D dam break (2.4e5 particles, 2 processes):
/// with equal counts (1.0) the run took 148 s, with 0.3 127 s and the two processes' own work
/// was within 2% (123.0 and 120.7 s; docs/PERFORMANCE.md, "Distributed runs").
inline constexpr double kSolidWork = 0.3;

/// A particle's share of a step's work: 1 for a fluid (or buffer) particle, kSolidWork else.
inline double particle_work(ParticleKind kind) {
  return carries_fluid(kind) ? 1.0 : kSolidWork;
}

/// The work of the particles along a slab axis in bins one grid cell wide from the domain's
/// low end (a fluid particle 1, a solid one kSolidWork): what the cuts are chosen from, at the
/// start from the whole scene and when rebalancing from every process's own particles summed.
struct WorkHistogram {
  double lo = 0, cell = 1;
  std::vector<double> bins;

  /// Bins of `cell` over [lo, hi) (the last one may be partial).
  WorkHistogram(double lo, double hi, double cell);
  /// Adds a particle at coordinate a along the axis (wrapped or clamped by the caller).
  void add(double a, ParticleKind kind);
};

/// Cuts `ranks` slabs from a histogram: cuts.front() and back() are lo and hi, the others on bin
/// boundaries where the work below comes nearest to r / ranks of the total, each slab at least
/// one bin wide. Throws netsph::Error when there are fewer bins than ranks.
std::vector<double> equal_work_cuts(const WorkHistogram& work, double hi, int ranks);

/// Collective: slabs along the axis the particles spread furthest with equal shares of the
/// work (fluid particles 1, solid ones kSolidWork), one per process of `coll`; `own` is this
/// process's share of the particles, no particle held by two processes. `halo` is left for
/// halo_width. Throws netsph::Error (on every process alike) naming the limit when the axis
/// cannot hold the slabs at least one cell wide.
SlabPartition balanced_slabs(const ParticleSet& own, const CellGrid& grid, const Vec3d& domain_min,
                             const Vec3d& domain_max, Collectives& coll);

/// What of the particles the halo width depends on (halo_width): the largest component along
/// each axis of their mDBC ghost offsets, and whether anything is interpolated at ghost nodes.
/// Taken from every process's particles at the start (collective), so that every process uses
/// the same halo when the slabs are cut again.
struct GhostReach {
  Vec3d along{};  ///< m, per axis
  bool ghost_nodes = false;
};
GhostReach ghost_reach(const ParticleSet& own, const std::vector<ZoneGeometry>& zones,
                       Collectives& coll);

/// The busiest process's share of the work over the mean (1: balanced).
double work_imbalance(std::span<const double> shares);

/// The halo width the step needs along the slabs' axis (see above), m: the largest component
/// along the axis of the mDBC ghost offsets among `particles`, and of the open boundaries'
/// reach where a buffer lies near a cut (`zones`: the ghost nodes of a buffer lie up to twice
/// its width from it, a created particle its width behind its parent), plus three stages of
/// the kernel support and the displacement the grid allows, or two when nothing is
/// interpolated at ghost nodes (the walls' and buffers' state then comes from the pass).
double halo_width(const SlabPartition& slabs, const GhostReach& ghosts, const CellGrid& grid,
                  double support, const std::vector<ZoneGeometry>& zones);

}  // namespace netsph
