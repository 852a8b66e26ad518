#include "netsph/distributed/slab_partition.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "netsph/core/error.hpp"

namespace netsph {

double SlabPartition::coordinate(const Vec3d& p) const {
  const double lo = cuts.front(), length = cuts.back() - cuts.front();
  double a = p[axis];
  if (periodic && std::isfinite(a)) {
    a = lo + (a - lo) - length * std::floor((a - lo) / length);
    if (a >= cuts.back()) a = lo;  // round-off of the wrap
  }
  return a;
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

double halo_width(const SlabPartition& slabs, const ParticleSet& particles, const CellGrid& grid,
                  double support, const std::vector<ZoneGeometry>& zones) {
  const int axis = slabs.axis;
  double reach = 0;
  bool ghost_nodes = !zones.empty();  // buffers take their state at ghost nodes
  for (const Vec3f& g : particles.ghost) {
    reach = std::max(reach, static_cast<double>(std::fabs(g[axis])));
    ghost_nodes |= g.x != 0 || g.y != 0 || g.z != 0;
  }
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

SlabPartition balanced_slabs(const ParticleSet& particles, const CellGrid& grid,
                             const Vec3d& domain_min, const Vec3d& domain_max, int ranks) {
  SlabPartition s;
  // The axis along which the particles spread furthest (not the domain: a dam break's domain
  // is tall for the splash, its water wide).
  Vec3d lo_p = domain_max, hi_p = domain_min;
  for (const Vec3d& p : particles.pos) {
    lo_p = {std::min(lo_p.x, p.x), std::min(lo_p.y, p.y), std::min(lo_p.z, p.z)};
    hi_p = {std::max(hi_p.x, p.x), std::max(hi_p.y, p.y), std::max(hi_p.z, p.z)};
  }
  const Vec3d extent = particles.size() > 0 ? hi_p - lo_p : domain_max - domain_min;
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
  s.cuts.assign(ranks + 1, lo);
  s.cuts.back() = hi;  // the bounds coordinate() wraps into
  // Cut at equal shares of the step's work: a fluid (or buffer) particle sums momentum,
  // continuity and diffusion over its neighbours, a wall or body particle only its density
  // and the viscous criterion over its fluid neighbours (kSolidWork).
  std::vector<std::pair<double, double>> work;  // coordinate, weight
  work.reserve(particles.size());
  double total = 0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const double w = carries_fluid(particles.kind[i]) ? 1.0 : kSolidWork;
    work.emplace_back(std::clamp(s.coordinate(particles.pos[i]), lo, hi), w);
    total += w;
  }
  std::sort(work.begin(), work.end());
  std::size_t k = 0;
  double below = 0;  // work of the particles before k
  for (int r = 1; r < ranks; ++r) {
    while (k < work.size() && below + work[k].second <= total * r / ranks)
      below += work[k++].second;
    const double q = k < work.size() ? work[k].first : lo + (hi - lo) * r / ranks;
    // On a cell boundary, at least one cell from the previous cut and room for the rest.
    double cut = lo + std::round((q - lo) / cell) * cell;
    cut = std::clamp(cut, s.cuts[r - 1] + cell, hi - (ranks - r) * cell);
    s.cuts[r] = cut;
  }
  return s;
}

}  // namespace netsph
