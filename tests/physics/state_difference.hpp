#pragma once
// Two runs of the same case compared particle by particle (matched by id) and body by body:
// the CPU backend against the device step (device_parity_test), one process against a
// distributed run (distributed_test). Both sum each particle's pairs in another order, so the
// states agree to float round-off, amplified by the flow over the steps; a logic error (a
// missed neighbour, a wrong sign, a stale array, a particle lost or doubled) shows at 1e-3 or
// more.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "netsph/solver/simulation.hpp"

namespace netsph::test {

struct Difference {
  double pos = 0;         ///< largest position difference, in dp
  double vel = 0;         ///< largest velocity difference over the largest speed
  double rho = 0;         ///< largest relative density difference
  double dt = 0;          ///< largest relative dt difference over the steps (set by the caller)
  double body_pos = 0;    ///< largest body centre difference, in dp
  double body_force = 0;  ///< largest body fluid-force difference over the largest force
};

/// The differences of `other` from `reference`; also checks that both hold the same
/// particles, time and largest speed. Particles with ids from `created_ids` on (made by open
/// boundaries during the runs) are matched by position instead: a distributed run numbers
/// them in another order than one process (distributed/distributed_simulation.hpp).
inline Difference state_difference(const Simulation& reference, const Simulation& other,
                                   std::uint32_t created_ids = UINT32_MAX) {
  Difference d;
  EXPECT_NEAR(other.time(), reference.time(), 1e-5 * reference.time());
  const ParticleSet& q = other.particles();
  const ParticleSet& p = reference.particles();
  EXPECT_EQ(q.size(), p.size());
  std::unordered_map<std::uint32_t, std::size_t> where;
  for (std::size_t i = 0; i < q.size(); ++i) where[q.id[i]] = i;
  EXPECT_EQ(where.size(), q.size()) << "a particle id appears twice";
  const double dp = reference.spec().simulation.dp;
  // Created particles: each of the reference's to the nearest unclaimed one of the other run.
  std::vector<std::size_t> created;
  for (std::size_t j = 0; j < q.size(); ++j)
    if (q.id[j] >= created_ids) created.push_back(j);
  const auto match_created = [&](std::size_t i) -> std::size_t {
    std::size_t best = q.size();
    double best_d = 1e-3 * dp;  // round-off apart, or no match
    for (const std::size_t j : created) {
      const double dist = norm(p.pos[i] - q.pos[j]);
      if (dist < best_d) best_d = dist, best = j;
    }
    return best;
  };
  double vmax = 1e-3;
  for (const Vec3f& v : p.vel) vmax = std::max(vmax, static_cast<double>(norm(v)));
  EXPECT_NEAR(other.diagnostics().max_speed, reference.diagnostics().max_speed, 1e-3 * vmax);
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::size_t j = q.size();
    if (p.id[i] >= created_ids) {
      j = match_created(i);
    } else if (const auto it = where.find(p.id[i]); it != where.end()) {
      j = it->second;
    }
    if (j == q.size()) {
      ADD_FAILURE() << "particle id " << p.id[i] << " is missing from the compared run";
      continue;
    }
    EXPECT_EQ(p.kind[i], q.kind[j]);
    d.pos = std::max(d.pos, norm(p.pos[i] - q.pos[j]) / dp);
    d.vel = std::max(d.vel, static_cast<double>(norm(p.vel[i] - q.vel[j])) / vmax);
    d.rho = std::max(d.rho, std::fabs(static_cast<double>(p.rho[i] - q.rho[j])) / p.rho[i]);
  }
  const auto& bodies = reference.bodies();
  EXPECT_EQ(bodies.size(), other.bodies().size());
  // Fluid and contact forces (the device sums them in different kernels).
  double fmax = 1e-12;
  for (const RigidBody& b : bodies)
    fmax = std::max({fmax, norm(b.fluid_force), norm(b.contact_force)});
  for (std::size_t b = 0; b < bodies.size() && b < other.bodies().size(); ++b) {
    const RigidBody &c = bodies[b], &g = other.bodies()[b];
    d.body_pos = std::max(d.body_pos, norm(c.state.com - g.state.com) / dp);
    d.body_force = std::max({d.body_force, norm(c.fluid_force - g.fluid_force) / fmax,
                             norm(c.contact_force - g.contact_force) / fmax});
  }
  return d;
}

inline void print_difference(const Difference& d) {
  std::printf(
      "largest differences: position %.3g dp, velocity %.3g of the top speed, density "
      "%.3g, dt %.3g, body centre %.3g dp, body force %.3g of the largest\n",
      d.pos, d.vel, d.rho, d.dt, d.body_pos, d.body_force);
}

// Two runs that sum each particle's pairs in different orders (the CPU backend in vector
// lanes, the device step one pair after another) or, with bodies and nets, a split run whose
// loads are summed over the processes in another order. One evaluation of a rate then differs
// by at most 2 n u sum_k |t_k| (Higham 2002, eq. 4.4: n neighbours' terms t_k, u = 6e-8 in
// float), but over tens to hundreds of steps the flow amplifies that by a factor that no
// closed-form bound gives. So these limits are gates for logic errors (a missed neighbour, a
// wrong sign, a stale array: 1e-3 and more), set a decade and more above the round-off. The
// largest differences of the DeviceParity.Host tests, on an AVX-512 Xeon with -march=native and
// in a build for the baseline x86-64 (SSE2, no FMA), 2026-12-07: position 4.6e-6 dp, velocity
// 1.3e-4 of the top speed, density 6.7e-7, dt 1.6e-8, body force 2.9e-5 of the largest.
inline void expect_parity(const Difference& d) {
  print_difference(d);
  EXPECT_LT(d.pos, 1e-4) << "largest position difference, dp";
  EXPECT_LT(d.vel, 1e-3) << "largest velocity difference over the largest speed";
  EXPECT_LT(d.rho, 1e-5) << "largest relative density difference";
  EXPECT_LT(d.dt, 1e-4) << "largest relative time-step difference";
  EXPECT_LT(d.body_pos, 1e-4) << "largest body centre difference, dp";
  EXPECT_LT(d.body_force, 1e-3) << "largest body force difference over the largest force";
}

// Two runs that must agree to the bit: a run split over processes against the same run on
// one. The split run sums every particle's pairs over the same neighbours in the same order
// (the cell grid orders particles by position, neighbours/cell_grid.cpp; every process sorts
// again when one must) with the same instructions, and reduces dt's inputs with max, which
// does not round; so nothing in it rounds otherwise, on any CPU and instruction set. Not for
// cases with bodies or nets: their loads are double sums over the processes, in another
// order (expect_parity).
inline void expect_identical(const Difference& d) {
  print_difference(d);
  EXPECT_EQ(d.pos, 0.0) << "largest position difference, dp";
  EXPECT_EQ(d.vel, 0.0) << "largest velocity difference over the largest speed";
  EXPECT_EQ(d.rho, 0.0) << "largest relative density difference";
  EXPECT_EQ(d.dt, 0.0) << "largest relative time-step difference";
}

}  // namespace netsph::test
