// The interaction loop gathers per particle, so each particle's sums are taken in the same
// order whatever the thread count, and reductions are max/min: runs with 1 and 2 threads must
// agree bit for bit.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>

#include "case_runs.hpp"

namespace netsph {
namespace {

ParticleSet run_with_threads(int threads, const std::string& name,
                             const std::vector<std::string>& overrides, int steps) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  Simulation sim(test::load_case(name, overrides));
  for (int s = 0; s < steps; ++s) sim.step();
  omp_set_num_threads(before);
  return sim.particles();
}

void expect_identical(const ParticleSet& a, const ParticleSet& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(0, std::memcmp(a.pos.data(), b.pos.data(), a.size() * sizeof(Vec3d)));
  EXPECT_EQ(0, std::memcmp(a.vel.data(), b.vel.data(), a.size() * sizeof(Vec3f)));
  EXPECT_EQ(0, std::memcmp(a.rho.data(), b.rho.data(), a.size() * sizeof(Real)));
}

TEST(ThreadIndependence, DamBreak2DIsBitwiseIdentical) {
  const std::vector<std::string> o = {"simulation.dp=0.04"};
  expect_identical(run_with_threads(1, "dambreak2d.toml", o, 300),
                   run_with_threads(2, "dambreak2d.toml", o, 300));
}

TEST(ThreadIndependence, DamBreak3DIsBitwiseIdentical) {
  const std::vector<std::string> o = {"simulation.dp=0.025"};
  expect_identical(run_with_threads(1, "dambreak3d.toml", o, 40),
                   run_with_threads(2, "dambreak3d.toml", o, 40));
}

}  // namespace
}  // namespace netsph
