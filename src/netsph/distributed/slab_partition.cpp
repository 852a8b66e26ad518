#include "netsph/distributed/slab_partition.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "netsph/core/error.hpp"
#include "netsph/core/periodic_image.hpp"

namespace netsph {

double SlabPartition::coordinate(const Vec3d& p) const {
  const double a = p[axis];
  if (!periodic || !std::isfinite(a)) return a;
  return wrapped_into_period(a, cuts.front(), cuts.back() - cuts.front());
}

int SlabPartition::owner_of(const Vec3d& p) const {
  const double a = coordinate(p);
  if (!(a >= cuts.front())) return 0;  // also NaN: the first process reports it
  const auto it = std::upper_bound(cuts.begin(), cuts.end(), a);
  return std::min(static_cast<int>(it - cuts.begin()) - 1, ranks() - 1);
}

double SlabPartition::distance_to(int r, const Vec3d& p) const {
  const double a = coordinate(p), lo = cuts[r], hi = cuts[r + 1];
  const auto plain = [&](double x) { return x < lo ? lo - x : (x >= hi ? x - hi : 0.0); };
  double d = plain(a);
  if (periodic) {
    const double length = cuts.back() - cuts.front();
    d = std::min({d, plain(a - length), plain(a + length)});
  }
  return d;
}

std::vector<int> SlabPartition::halo_neighbours(int r) const {
  std::vector<int> out;
  const double length = cuts.back() - cuts.front();
  for (int s = 0; s < ranks(); ++s) {
    if (s == r) continue;
    // Gap between the slabs along the axis (through the period too).
    double gap = std::max(cuts[s] - cuts[r + 1], cuts[r] - cuts[s + 1]);
    if (periodic) {
      gap = std::min({gap, std::max(cuts[s] + length - cuts[r + 1], cuts[r] - cuts[s + 1] - length),
                      std::max(cuts[s] - length - cuts[r + 1], cuts[r] - cuts[s + 1] + length)});
    }
    if (gap < halo) out.push_back(s);
  }
  return out;
}

GhostReach ghost_reach(const ParticleSet& own, const std::vector<ZoneGeometry>& zones,
                       Collectives& coll) {
  GhostReach g;
  g.ghost_nodes = !zones.empty();  // buffers take their state at ghost nodes
  for (const Vec3f& v : own.ghost) {
    for (int a = 0; a < 3; ++a)
      g.along[a] = std::max(g.along[a], static_cast<double>(std::fabs(v[a])));
    g.ghost_nodes |= v.x != 0 || v.y != 0 || v.z != 0;
  }
  for (int a = 0; a < 3; ++a) g.along[a] = coll.max(g.along[a]);
  g.ghost_nodes = coll.max(g.ghost_nodes ? 1.0 : 0.0) > 0;
  return g;
}

double work_imbalance(std::span<const double> shares) {
  double total = 0, busiest = 0;
  for (const double w : shares) total += w, busiest = std::max(busiest, w);
  return total > 0 ? busiest * static_cast<double>(shares.size()) / total : 1.0;
}

double halo_width(const SlabPartition& slabs, const GhostReach& ghosts, const CellGrid& grid,
                  double support, const std::vector<ZoneGeometry>& zones) {
  const int axis = slabs.axis;
  double reach = ghosts.along[axis];
  const bool ghost_nodes = ghosts.ghost_nodes;
  const double stage = support + 2 * grid.max_displacement();
  const double base = (ghost_nodes ? 3 : 2) * stage;
  for (const ZoneGeometry& z : zones) {
    if (z.axis != axis) continue;  // its ghost nodes and created particles stay in the slab
    const double a = z.plane, b = z.plane - z.inward * z.width;
    const double lo = std::min(a, b), hi = std::max(a, b);
    for (int r = 1; r < slabs.ranks(); ++r) {
      const double c = slabs.cuts[r];
      const double gap = c < lo ? lo - c : (c > hi ? c - hi : 0.0);
      if (gap < base + 2 * z.width) reach = std::max(reach, 2 * z.width);
    }
  }
  return reach + base;
}

WorkHistogram::WorkHistogram(double lo_, double hi, double cell_) : lo(lo_), cell(cell_) {
  bins.assign(static_cast<std::size_t>(std::max(1.0, std::ceil((hi - lo) / cell - 1e-9))), 0.0);
}

void WorkHistogram::add(double a, ParticleKind kind) {
  const double f = std::floor((a - lo) / cell);
  const auto k = static_cast<std::size_t>(std::clamp(f, 0.0, static_cast<double>(bins.size() - 1)));
  bins[k] += particle_work(kind);
}

std::vector<double> equal_work_cuts(const WorkHistogram& work, double hi, int ranks) {
  const auto n = static_cast<int>(work.bins.size());
  if (ranks > n) {
    throw Error("distributed", fmt::format("{} slabs cannot be cut from {} cells", ranks, n));
  }
  std::vector<double> below(n + 1, 0.0);  // work in the bins before bin k
  for (int k = 0; k < n; ++k) below[k + 1] = below[k] + work.bins[k];
  std::vector<double> cuts(ranks + 1, work.lo);
  cuts.back() = hi;
  int prev = 0;  // bin boundary of the previous cut
  for (int r = 1; r < ranks; ++r) {
    const double target = below[n] * r / ranks;
    int k = static_cast<int>(std::lower_bound(below.begin(), below.end(), target) - below.begin());
    if (k > 0 && target - below[k - 1] < below[k] - target) --k;  // the nearer boundary
    // At least one bin from the previous cut, and room for the slabs after it.
    k = std::clamp(k, prev + 1, n - (ranks - r));
    cuts[r] = work.lo + k * work.cell;
    prev = k;
  }
  return cuts;
}

SlabPartition balanced_slabs(const ParticleSet& own, const CellGrid& grid, const Vec3d& domain_min,
                             const Vec3d& domain_max, Collectives& coll) {
  const int ranks = coll.size();
  SlabPartition s;
  // The axis along which the particles spread furthest (not the domain: a dam break's domain
  // is tall for the splash, its water wide).
  Vec3d lo_p = domain_max, hi_p = domain_min;
  for (const Vec3d& p : own.pos) {
    lo_p = {std::min(lo_p.x, p.x), std::min(lo_p.y, p.y), std::min(lo_p.z, p.z)};
    hi_p = {std::max(hi_p.x, p.x), std::max(hi_p.y, p.y), std::max(hi_p.z, p.z)};
  }
  for (int a = 0; a < 3; ++a) lo_p[a] = -coll.max(-lo_p[a]), hi_p[a] = coll.max(hi_p[a]);
  // With no particles anywhere the box is still inverted (domain_max to domain_min).
  const bool any = lo_p.x <= hi_p.x;
  const Vec3d extent = any ? hi_p - lo_p : domain_max - domain_min;
  for (int a = 1; a < 3; ++a)
    if (extent[a] > extent[s.axis]) s.axis = a;
  s.periodic = grid.periodic(s.axis);
  const double lo = domain_min[s.axis], hi = domain_max[s.axis];
  const double cell = grid.cell_size()[s.axis];
  const int cells = grid.dims()[s.axis];
  if (ranks > cells) {
    throw Error("distributed",
                fmt::format("{} processes for a domain {} cells long along {} (cells of {:.4g} "
                            "m): use at most {} processes",
                            ranks, cells, "xyz"[s.axis], cell, cells));
  }
  // Equal shares of the step's work: a fluid (or buffer) particle sums momentum, continuity and
  // diffusion over its neighbours, a wall or body particle only its density and the viscous
  // criterion over its fluid neighbours (kSolidWork).
  s.cuts.assign(ranks + 1, lo);
  s.cuts.back() = hi;  // the bounds coordinate() wraps into
  WorkHistogram work(lo, hi, cell);
  for (std::size_t i = 0; i < own.size(); ++i)
    work.add(std::clamp(s.coordinate(own.pos[i]), lo, hi), own.kind[i]);
  coll.sum(work.bins);
  s.cuts = equal_work_cuts(work, hi, ranks);
  return s;
}

}  // namespace netsph
