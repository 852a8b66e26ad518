// output.snapshot_region (run/run_outputs.cpp): a snapshot holds exactly the particles that
// are inside the box when it is written, with their own fields; without a region, all of them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "case_runs.hpp"
#include "hdf5_read.hpp"
#include "netsph/run/run_outputs.hpp"

namespace netsph {
namespace {

namespace fs = std::filesystem;

/// The ids and positions in a snapshot file against those of the particles inside the region.
void expect_snapshot_holds_the_region(const fs::path& h5, const Simulation& sim) {
  const auto ids = test::read_dataset<std::uint32_t>(h5, "id", H5T_NATIVE_UINT32, 1);
  const auto pos = test::read_dataset<double>(h5, "position", H5T_NATIVE_DOUBLE, 3);
  const auto rho = test::read_dataset<float>(h5, "density", H5T_NATIVE_FLOAT, 1);
  ASSERT_EQ(pos.size(), 3 * ids.size());
  const ParticleSet& p = sim.particles();
  std::set<std::uint32_t> expected;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (in_snapshot_region(sim.spec(), p.pos[i])) expected.insert(p.id[i]);
  EXPECT_EQ(std::set<std::uint32_t>(ids.begin(), ids.end()), expected) << h5;
  EXPECT_EQ(ids.size(), expected.size());
  // Each row is its particle's own state.
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const auto i =
        static_cast<std::size_t>(std::find(p.id.begin(), p.id.end(), ids[k]) - p.id.begin());
    ASSERT_LT(i, p.size());
    EXPECT_EQ(pos[3 * k], p.pos[i].x);
    EXPECT_EQ(pos[3 * k + 2], p.pos[i].z);
    EXPECT_EQ(rho[k], p.rho[i]);
  }
}

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() /
                     ("netsph_snapshot_region_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  return d;
}

TEST(SnapshotRegion, SnapshotsHoldExactlyTheParticlesInsideTheBox) {
  // The 2D tank (5798 particles), a box around its middle: fluid and floor wall particles.
  const CaseSpec spec =
      test::load_case("hydrostatic2d.toml",
                      {"simulation.end_time=0.01", "output.snapshot_every=0.005",
                       "output.snapshot_region={ min = [0.2, 0, -0.1], max = [0.6, 0, 0.3] }"});
  Simulation sim(spec);
  SimulationParticles particles(sim);
  const fs::path dir = temp_dir("box");
  {
    RunOutputs out(sim, dir, true);
    out.maybe_write(sim, particles, 0);
    expect_snapshot_holds_the_region(dir / "snapshots" / "particles_000000.h5", sim);
    const std::size_t first = snapshot_particle_count(sim);
    std::printf("snapshot 0: %zu of %zu particles\n", first, sim.particles().size());
    EXPECT_GT(first, 500u);
    EXPECT_LT(first, sim.particles().size() / 2);
    while (sim.time() < 0.01) sim.step();
    out.write_final(sim, particles, 0);
    expect_snapshot_holds_the_region(dir / "snapshots" / "particles_000001.h5", sim);
  }
  fs::remove_all(dir);
}

TEST(SnapshotRegion, WithoutARegionEveryParticleIsWritten) {
  const CaseSpec spec = test::load_case("hydrostatic2d.toml",
                                        {"simulation.end_time=0.01", "output.snapshot_every=0.01"});
  Simulation sim(spec);
  SimulationParticles particles(sim);
  const fs::path dir = temp_dir("all");
  {
    RunOutputs out(sim, dir, true);
    out.maybe_write(sim, particles, 0);
    const auto ids = test::read_dataset<std::uint32_t>(dir / "snapshots" / "particles_000000.h5",
                                                       "id", H5T_NATIVE_UINT32, 1);
    EXPECT_EQ(ids.size(), sim.particles().size());
    EXPECT_EQ(snapshot_particle_count(sim), sim.particles().size());
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace netsph
