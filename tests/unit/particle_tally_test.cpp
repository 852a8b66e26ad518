// The series rows' measures as a reduction (sph/particle_tally.hpp): what the CPU's OpenMP
// loop (tally_particles) and the device executors' reduce (HostExec::reduce here; CudaExec's
// groups the same merges by blocks) give for hand-built particle sets with known answers,
// including the NaN and empty cases a failing run produces.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "netsph/backend/device/host_exec.hpp"
#include "netsph/run/output_particles.hpp"
#include "netsph/sph/particle_tally.hpp"

namespace netsph {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

void add(ParticleSet& p, ParticleKind k, Vec3f v, Real rho) {
  p.pos.push_back({0, 0, 0});
  p.vel.push_back(v);
  p.rho.push_back(rho);
  p.kind.push_back(k);
  p.id.push_back(static_cast<std::uint32_t>(p.id.size()));
  p.group.push_back(0);
  p.ghost.push_back({0, 0, 0});
}

// The same tally through the device executor's reduction, merged in order.
ParticleTally reduced_on_host_exec(const ParticleSet& p, double mass) {
  return HostExec::reduce(
      p.size(), ParticleTally{},
      [&](std::uint32_t i) { return tally_particle(p.kind[i], p.vel[i], p.rho[i], mass); },
      MergeTallies{});
}

void expect_same(const ParticleTally& a, const ParticleTally& b) {
  EXPECT_EQ(a.fluid, b.fluid);
  EXPECT_EQ(a.walls, b.walls);
  EXPECT_EQ(a.buffer, b.buffer);
  EXPECT_DOUBLE_EQ(a.kinetic_energy, b.kinetic_energy);
  EXPECT_EQ(a.max_speed2, b.max_speed2);
  EXPECT_EQ(a.min_density, b.min_density);
  EXPECT_EQ(a.max_density, b.max_density);
}

void expect_extremes(const ParticleTally& t, double max_speed2, double min_rho, double max_rho) {
  EXPECT_EQ(t.max_speed2, max_speed2);
  EXPECT_EQ(t.min_density, min_rho);
  EXPECT_EQ(t.max_density, max_rho);
}

TEST(ParticleTally, CountsKindsAndMeasuresTheFluidOnly) {
  ParticleSet p;
  add(p, ParticleKind::Fluid, {3, 0, 4}, 1010);  // |v| = 5
  add(p, ParticleKind::Fluid, {0, 1, 0}, 990);
  add(p, ParticleKind::Wall, {50, 0, 0}, 900);  // neither its speed nor its density counts
  add(p, ParticleKind::Wall, {0, 0, 0}, 1000);
  add(p, ParticleKind::Buffer, {60, 0, 0}, 1100);
  add(p, ParticleKind::Body, {70, 0, 0}, 800);
  const double mass = 0.5;
  const ParticleTally t = tally_particles(p, mass);
  EXPECT_EQ(t.fluid, 2u);
  EXPECT_EQ(t.walls, 2u);
  EXPECT_EQ(t.buffer, 1u);
  EXPECT_DOUBLE_EQ(t.kinetic_energy, 0.5 * mass * (25 + 1));
  expect_extremes(t, 25.0, 990.0, 1010.0);
  expect_same(reduced_on_host_exec(p, mass), t);

  const GlobalMeasures g = measures_of(t, mass);
  EXPECT_EQ(g.max_speed, 5.0);
  EXPECT_DOUBLE_EQ(g.fluid_mass, 1.0);

  // One process's own particles: the keep mask drops the first fluid particle and a wall.
  const std::vector<std::uint8_t> keep = {0, 1, 0, 1, 1, 1};
  const ParticleTally own = tally_particles(p, mass, keep);
  EXPECT_EQ(own.fluid, 1u);
  EXPECT_EQ(own.walls, 1u);
  expect_extremes(own, 1.0, 990.0, 990.0);
}

TEST(ParticleTally, ANaNParticleShowsInTheEnergyAndIsPassedOverByTheExtremes) {
  ParticleSet p;
  add(p, ParticleKind::Fluid, {1, 0, 0}, 1000);
  add(p, ParticleKind::Fluid, {kNaN, 0, 0}, kNaN);
  add(p, ParticleKind::Fluid, {2, 0, 0}, 1005);
  for (const ParticleTally& t : {tally_particles(p, 1.0), reduced_on_host_exec(p, 1.0)}) {
    EXPECT_EQ(t.fluid, 3u);
    EXPECT_TRUE(std::isnan(t.kinetic_energy));  // what the finite-state check then reports
    expect_extremes(t, 4.0, 1000.0, 1005.0);
  }
  // A NaN on either side of a merge is passed over (a reduction tree puts it anywhere).
  const ParticleTally nan_one = tally_particle(ParticleKind::Fluid, {kNaN, 0, 0}, kNaN, 1.0);
  const ParticleTally fine = tally_particle(ParticleKind::Fluid, {0, 3, 0}, 998, 1.0);
  for (const ParticleTally& m : {merge_tallies(nan_one, fine), merge_tallies(fine, nan_one)})
    expect_extremes(m, 9.0, 998.0, 998.0);
}

TEST(ParticleTally, WithoutFluidTheDensitiesAreZero) {
  ParticleSet walls;
  add(walls, ParticleKind::Wall, {0, 0, 0}, 1000);
  for (const ParticleSet& p : {ParticleSet{}, walls}) {
    const ParticleTally t = tally_particles(p, 1.0);
    expect_same(reduced_on_host_exec(p, 1.0), t);
    const GlobalMeasures g = measures_of(t, 1.0);
    EXPECT_EQ(g.fluid, 0u);
    EXPECT_EQ(g.kinetic_energy, 0.0);
    EXPECT_EQ(g.max_speed, 0.0);
    EXPECT_EQ(g.min_density, 0.0);
    EXPECT_EQ(g.max_density, 0.0);
  }
}

}  // namespace
}  // namespace netsph
