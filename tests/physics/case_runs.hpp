#pragma once
// Helpers for the physics tests: load a case from cases/ (with overrides), step it, and
// measure fields the way a user would read them.
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "netsph/case/case_reader.hpp"
#include "netsph/neighbours/cell_grid.hpp"
#include "netsph/solver/simulation.hpp"
#include "netsph/sph/kernels.hpp"

namespace netsph::test {

/// cases/ of the source tree, or $NETSPH_CASES_DIR when set (a test binary carried to another
/// machine, tools/gpu_bundle.sh).
inline std::string cases_dir() {
  const char* env = std::getenv("NETSPH_CASES_DIR");
  return env && *env ? std::string(env) : std::string(NETSPH_CASES_DIR);
}

inline CaseSpec load_case(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return read_case_file(cases_dir() + "/" + name, overrides);
}

/// Steps until the simulation time reaches t (the last step may pass it by less than dt).
inline void run_until(Simulation& sim, double t) {
  while (sim.time() < t) sim.step();
}

/// L2 norm of (u - u_exact) over fluid particles, relative to the L2 norm of u_exact, for the
/// x velocity against a profile u_exact(z).
template <class Profile>
double relative_l2_error_x(const Simulation& sim, Profile exact) {
  const ParticleSet& p = sim.particles();
  double num = 0, den = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!is_fluid(p.kind[i])) continue;
    const double ue = exact(p.pos[i].z), e = p.vel[i].x - ue;
    num += e * e, den += ue * ue;
  }
  return std::sqrt(num / den);
}

/// Kernel sum of particle volumes, sum_b (m / rho_b) W_ab including a itself: 1 where the
/// kernel is full and the particles are evenly spread, < 1 in voids, > 1 in clusters.
/// Computed with its own grid so it is valid at any moment of a run.
inline std::vector<double> kernel_volume_sums(const Simulation& sim) {
  const ParticleSet& p = sim.particles();
  const FluidModel& m = sim.model();
  CellGrid grid;
  const Vec3d pad(m.support, m.support, m.support);
  Vec3d lo = sim.scene().domain_min, hi = sim.scene().domain_max;
  std::array<bool, 3> periodic{};
  for (int a = 0; a < 3; ++a) periodic[a] = sim.grid().periodic(a);
  for (int a = 0; a < 3; ++a)
    if (!periodic[a]) lo[a] -= pad[a], hi[a] += pad[a];
  grid.configure(lo, hi, m.support, 0.0, m.dims, periodic);
  std::vector<Vec3d> pos(p.pos.begin(), p.pos.end());
  grid.wrap(pos);
  std::vector<std::uint32_t> order;
  grid.sort(pos, order);
  std::vector<double> sums(p.size(), 0.0);
  NeighbourRanges ranges;
  for (std::int64_t c : grid.occupied_cells()) {
    const IndexRange own = grid.cell_range(c);
    const int nr = grid.neighbour_ranges(c, ranges);
    for (std::uint32_t s = own.begin; s < own.end; ++s) {
      const std::uint32_t a = order[s];
      double sum = 0;
      for (int k = 0; k < nr; ++k)
        for (std::uint32_t t = ranges[k].begin; t < ranges[k].end; ++t) {
          const std::uint32_t b = order[t];
          const double r = norm(pos[a] - (pos[b] + Vec3d(ranges[k].shift)));
          if (r < m.support) {
            sum += static_cast<double>(m.mass) / p.rho[b] *
                   kernel_value<WendlandC2>(m.kernel, static_cast<Real>(r));
          }
        }
      sums[a] = sum;
    }
  }
  return sums;
}

}  // namespace netsph::test
