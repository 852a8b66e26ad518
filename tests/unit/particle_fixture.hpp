#pragma once
// The fixture the tests of the CPU passes share (interaction_test, periodic_rates_test,
// ghost_pass_test, probe_sampling_test): a block of particles with its fluid model, cell grid
// and interaction view, prepared as the solver prepares them before a pass (particles sorted
// by cell, the view built from the sorted set), and the interaction pass that fills its rates.
// Each test places its own particles (a lattice, jittered or not, walls below it, ...) with
// for_each_site and site_centre; they fix the order the particles are added in, and so their
// ids, which some tests use to find a particle again after the sort.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "netsph/backend/cpu/interaction_view.hpp"
#include "netsph/backend/cpu/rates.hpp"

namespace netsph::test {

/// The fluid model input the tests start from: the defaults, but for the dimension, the
/// particle spacing and a low speed of sound (short tests, small pressures); each test sets
/// the models it checks (viscosity, diffusion, gravity, ...) on top.
inline FluidModelInput fluid_input(int dims, double dp, double c0) {
  FluidModelInput in;
  in.dims = dims;
  in.dp = dp;
  in.c0 = c0;
  return in;
}

/// Particles and what the CPU passes read and write.
struct ParticleBlock {
  ParticleSet p;
  FluidModel m;
  CellGrid grid;
  InteractionView view;
  // compute()'s results: compute_rates' outputs.
  std::vector<Vec3f> acc;
  std::vector<Real> drho;
  RateReductions red;
  bool with_shifting = false;  ///< compute() also fills `shifting` (compute_rates' option)
  ShiftingSums shifting;

  /// Sorts the particles by cell, as the solver does before any pass. A particle outside the
  /// grid fails the test: the sort would leave it out.
  void sort() {
    std::vector<std::uint32_t> order;
    grid.sort(p.pos, order);
    ASSERT_EQ(order.size(), p.size()) << "particles outside the grid";
    reorder(p, order);
  }

  /// sort(), then the interaction view of the sorted particles, which the neighbour passes
  /// (rates, ghost nodes) read.
  void sort_and_build_view() {
    ASSERT_NO_FATAL_FAILURE(sort());
    view.build(p, m, grid.origin());
  }

  /// The interaction pass on the particles as they are now: sorts them, builds the view and
  /// fills acc, drho and red (and shifting if with_shifting).
  void compute() {
    ASSERT_NO_FATAL_FAILURE(sort_and_build_view());
    red = compute_rates(m, grid, view, p.kind, acc, drho, with_shifting ? &shifting : nullptr);
  }
};

/// Configures b.grid for b.m's kernel support (b.m set first), skin 0.05, over [lo, hi] on
/// every axis with `pad` of room on both sides of each axis that is not periodic; a periodic
/// axis spans [lo, hi] exactly, its period. In 2-D y is not an axis of the grid; its range
/// starts at lo, which the view's y offsets are taken from.
inline void configure_grid(ParticleBlock& b, double lo, double hi, double pad, int dims = 3,
                           std::array<bool, 3> periodic = {}) {
  const auto low = [&](int a) { return periodic[a] ? lo : lo - pad; };
  const auto high = [&](int a) { return periodic[a] ? hi : hi + pad; };
  b.grid.configure({low(0), dims == 3 ? low(1) : lo, low(2)}, {high(0), high(1), high(2)},
                   b.m.support, 0.05, dims, periodic);
}

/// Calls site(i, j, k) for each site of a lattice of n sites per side, i fastest and k
/// slowest: the order the tests add particles in. In 2-D (dims == 2) there is one row, j = 0.
/// The layers k start at k_begin (negative for layers under the block, walls for instance).
template <class Site>
void for_each_site(int dims, int n, Site&& site, int k_begin = 0) {
  for (int k = k_begin; k < n; ++k)
    for (int j = 0; j < (dims == 3 ? n : 1); ++j)
      for (int i = 0; i < n; ++i) site(i, j, k);
}

/// The centre of lattice site (i, j, k) at spacing dp: ((i + 1/2) dp, (j + 1/2) dp,
/// (k + 1/2) dp), with y = 0 in 2-D. A lattice of n sites per side fills [0, n dp].
inline Vec3d site_centre(int i, int j, int k, double dp, int dims = 3) {
  return {(i + 0.5) * dp, dims == 3 ? (j + 0.5) * dp : 0.0, (k + 0.5) * dp};
}

/// Random perturbations from `seed`: positions moved by up to dx on each axis, velocities up
/// to 0.5 m/s on each axis, densities in 1000 +- 5 kg/m^3. Positions are not wrapped.
inline void perturb(ParticleBlock& b, unsigned seed, double dx) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t i = 0; i < b.p.size(); ++i) {
    b.p.pos[i] += Vec3d(u(rng), u(rng), u(rng)) * dx;
    b.p.vel[i] = Vec3f(Vec3d(u(rng), u(rng), u(rng)) * 0.5);
    b.p.rho[i] = static_cast<Real>(1000 + 5 * u(rng));
  }
}

}  // namespace netsph::test
