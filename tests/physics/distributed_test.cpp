// A run split into slabs over several processes (distributed/) against the same case on one:
// after N steps every particle and dt must be the same to the bit (each process sums a
// particle's pairs in the order of the one-process run: state_difference.hpp, expect_identical),
// and with bodies or nets, whose loads are double sums over the processes in another order,
// agree to float round-off (expect_parity). The processes here are threads of the test with
// in-process collectives (distributed/thread_collectives.hpp), so the decomposition, halo and
// exchange are checked without mpirun; tests/distributed_mpi_test.sh runs the same step under
// mpirun.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>

#include "case_runs.hpp"
#include "netsph/core/error.hpp"
#include "netsph/distributed/distributed_simulation.hpp"
#include "netsph/distributed/particle_exchange.hpp"
#include "netsph/distributed/thread_collectives.hpp"
#include "state_difference.hpp"
#include "thread_processes.hpp"

namespace netsph {
namespace {

using test::Difference;

struct SplitRun {
  std::unique_ptr<Simulation> whole;  // every process's particles, gathered
  std::vector<double> dts;
  std::vector<std::size_t> owned;  // particles each process owned at the end
  std::vector<double> work;        // each process's own work at the end (own_work)
  int rebalances = 0;
  std::vector<std::string> errors;

  /// The busiest process's own work at the end over the mean.
  double imbalance() const { return work_imbalance(work); }
};

SplitRun run_split(const CaseSpec& spec, int processes, int steps, RebalancePolicy policy = {},
                   const CheckpointData* resume = nullptr) {
  SplitRun run;
  run.whole = std::make_unique<Simulation>(spec);
  run.owned.resize(processes);
  run.work.resize(processes);
  run.errors = test::on_thread_processes(processes, [&](ThreadCollectives& coll) {
    const int r = coll.rank();
    DistributedSimulation sim(spec, coll, resume, policy);
    for (int s = 0; s < steps; ++s) {
      sim.step();
      if (r == 0) run.dts.push_back(sim.local().last_dt());
    }
    run.owned[r] = sim.owned_count();
    run.work[r] = sim.own_work();
    if (r == 0) run.rebalances = sim.rebalances();
    sim.gather_into(r == 0 ? run.whole.get() : nullptr);
  });
  return run;
}

Difference compare_split(const CaseSpec& spec, int processes, int steps,
                         RebalancePolicy policy = {}, SplitRun* kept = nullptr) {
  Simulation one(spec);
  const std::uint32_t created_ids = one.particles().next_id;
  std::vector<double> dts;
  for (int s = 0; s < steps; ++s) one.step(), dts.push_back(one.last_dt());
  SplitRun split = run_split(spec, processes, steps, policy);
  for (const std::string& e : split.errors) EXPECT_EQ(e, "");
  std::size_t owned = 0;
  for (int r = 0; r < processes; ++r) {
    EXPECT_GT(split.owned[r], 0u) << "process " << r << " owns nothing";
    owned += split.owned[r];
  }
  EXPECT_EQ(owned, one.particles().size()) << "particles doubled or lost between processes";
  const OpenBoundaryCounts &a = one.diagnostics().open, &b = split.whole->diagnostics().open;
  EXPECT_EQ(b.created, a.created);
  EXPECT_EQ(b.removed, a.removed);
  EXPECT_EQ(b.entered_fluid, a.entered_fluid);
  EXPECT_EQ(b.absorbed, a.absorbed);
  EXPECT_EQ(split.whole->diagnostics().lost_total, one.diagnostics().lost_total);
  Difference d = test::state_difference(one, *split.whole, created_ids);
  for (std::size_t s = 0; s < dts.size() && s < split.dts.size(); ++s)
    d.dt = std::max(d.dt, std::fabs(split.dts[s] / dts[s] - 1));
  if (kept) *kept = std::move(split);
  return d;
}

// DBC walls and a free surface: the dam's front crosses the slab boundaries.
TEST(Distributed, DamBreak2DOnThreeProcessesMatchesOne) {
  const CaseSpec spec = test::load_case("dambreak2d.toml", {"simulation.dp=0.04"});
  test::expect_identical(compare_split(spec, 3, 200));
}

// As the water column collapses and runs along the tank, the slabs cut at the start leave the
// process at the front with little water and the others with more: the slabs are cut again
// (RebalancePolicy), and the particles that changed slab move at once. Over the 1500 steps
// (0.75 s: the surge reaches the far wall and breaks) the runs with and without cutting again
// stay the same to the bit: each sums every pair in the order of the run on one process.
TEST(Distributed, SlabsAreCutAgainAsTheDamBreaks) {
  const CaseSpec spec = test::load_case("dambreak2d.toml", {"simulation.dp=0.04"});
  const int steps = 1500;
  const SplitRun fixed = run_split(spec, 3, steps, RebalancePolicy{0});
  const SplitRun moving = run_split(spec, 3, steps);
  std::printf(
      "after %d steps, busiest process's own work over the mean: %.3f with the slabs cut "
      "once, %.3f cut again %d times\n",
      steps, fixed.imbalance(), moving.imbalance(), moving.rebalances);
  for (const SplitRun* run : {&fixed, &moving}) {
    for (const std::string& e : run->errors) EXPECT_EQ(e, "");
    std::size_t owned = 0;
    for (const std::size_t n : run->owned) owned += n;
    EXPECT_EQ(owned, run->whole->particles().size()) << "particles doubled or lost";
  }
  EXPECT_EQ(fixed.rebalances, 0);
  EXPECT_GT(fixed.imbalance(), 1.3) << "the flow no longer unbalances the slabs: test nothing";
  EXPECT_GT(moving.rebalances, 0);
  EXPECT_LE(moving.imbalance(), RebalancePolicy{}.threshold);
  test::Difference d = test::state_difference(*fixed.whole, *moving.whole);
  ASSERT_EQ(fixed.dts.size(), moving.dts.size());
  for (std::size_t s = 0; s < fixed.dts.size(); ++s)
    d.dt = std::max(d.dt, std::fabs(moving.dts[s] / fixed.dts[s] - 1));
  test::expect_identical(d);
}

// Cut again early and often (at 2% out of balance, every 10 steps): the results are those of
// one process, to the bit.
TEST(Distributed, SlabsCutAgainGiveTheResultsOfOneProcess) {
  const CaseSpec spec = test::load_case("dambreak2d.toml", {"simulation.dp=0.04"});
  SplitRun split;
  test::expect_identical(compare_split(spec, 3, 800, RebalancePolicy{10, 1.02}, &split));
  std::printf("slabs cut again %d times\n", split.rebalances);
  EXPECT_GE(split.rebalances, 2);
}

// 3D, mDBC walls (the halo carries their ghost offsets), cubic spline kernel, shifting.
TEST(Distributed, DamBreak3DWithMdbcAndShiftingOnTwoProcessesMatchesOne) {
  const CaseSpec spec = test::load_case(
      "dambreak3d.toml",
      {"simulation.dp=0.03", "simulation.kernel=\"cubic_spline\"", "wall.0.model=\"mdbc\"",
       "wall.0.layers=3", "fluid.shifting={model=\"fickian\"}"});
  test::expect_identical(compare_split(spec, 2, 40));
}

// Periodic along the split axis (each process's halo wraps round), moving mDBC walls.
TEST(Distributed, PeriodicCouetteOnTwoProcessesMatchesOne) {
  test::expect_identical(compare_split(test::load_case("couette2d.toml"), 2, 200));
}

// A floating mDBC box: its loads are summed over the processes that own its particles.
TEST(Distributed, FloatingBoxOnTwoProcessesMatchesOne) {
  const CaseSpec spec = test::load_case("floating_box2d.toml", {"simulation.dp=0.04"});
  test::expect_parity(compare_split(spec, 2, 200));
}

// A floating box carried across the periodic end of the split axis: its particles are wrapped
// into the other process's slab while its centre is not (place_rigid_particle, rigid_lever_arm).
// The Poiseuille channel made 0.3 m long so that the slabs go along x, cut at its ends and middle.
TEST(Distributed, FloatingBoxAcrossThePeriodicEndOnTwoProcessesMatchesOne) {
  const CaseSpec spec = test::load_case(
      "poiseuille2d.toml",
      {"domain.max=[0.3, 0.0, 0.13]", "fill=[{min=[0.0, 0.0, 0.0], max=[0.3, 0.0, 0.1]}]",
       "wall=[{name=\"plates\", min=[0.0, 0.0, 0.0], max=[0.3, 0.0, 0.1], faces=[\"zmin\", "
       "\"zmax\"], layers=3, model=\"mdbc\", slip=\"no_slip\"}]",
       "body=[{name=\"box\", shape=\"box\", size=[0.02, 0.02, 0.02], center=[0.2965, 0, 0.035], "
       "motion=\"floating\", density=1000, initial_velocity=[0.5, 0, 0]}]"});
  Simulation one(spec);
  for (int s = 0; s < 400; ++s) one.step();
  ASSERT_GT(one.bodies()[0].state.com.x, 0.3) << "the box's centre did not cross the end";
  test::expect_parity(compare_split(spec, 2, 400));
}

// A knot on a twine in a periodic current with shifting, the knot across the cut: the net's
// solver runs on every process from the summed loads. Without the case's inlet and outlet
// buffers (not distributed yet): the duct is periodic and its walls move with the current.
TEST(Distributed, CoupledNetOnTwoProcessesMatchesOne) {
  CaseSpec spec = test::load_case("net_tethered_knot.toml");
  spec.inlets.clear();
  spec.outlets.clear();
  test::expect_parity(compare_split(spec, 2, 40));
}

// Inlet and outlet buffers: particles created at the inlet get the same ids on every process
// holding a copy of their parent, those removed at the outlet are not counted as lost, and
// the split run creates and removes exactly what the one-process run does.
TEST(Distributed, OpenChannelOnTwoProcessesMatchesOne) {
  test::expect_identical(compare_split(test::load_case("channel2d.toml"), 2, 300));
}

// The same with the knot, its twine and the inlet and outlet of the case as written.
TEST(Distributed, CoupledNetWithInletAndOutletOnTwoProcessesMatchesOne) {
  test::expect_parity(compare_split(test::load_case("net_tethered_knot.toml"), 2, 40));
}

TEST(Distributed, ACheckpointOfOneProcessContinuedOnThreeMatchesOne) {
  // Each process restores only the checkpoint's particles in its part of the scene.
  const CaseSpec spec = test::load_case("floating_box2d.toml", {"simulation.dp=0.04"});
  Simulation one(spec);
  for (int s = 0; s < 30; ++s) one.step();
  CheckpointData saved;
  one.save_state(saved);
  const std::uint32_t created_ids = one.particles().next_id;
  for (int s = 0; s < 30; ++s) one.step();
  const SplitRun split = run_split(spec, 3, 30, {}, &saved);
  for (const std::string& e : split.errors) EXPECT_EQ(e, "");
  std::size_t owned = 0;
  for (const std::size_t n : split.owned) owned += n;
  EXPECT_EQ(owned, one.particles().size()) << "particles doubled or lost between processes";
  EXPECT_EQ(split.whole->steps(), 60);
  test::expect_parity(test::state_difference(one, *split.whole, created_ids));
}

TEST(Distributed, AnErrorInOneProcesssPartOfTheSceneStopsEveryProcess) {
  // The domain ends where the tank's right wall begins: its particles lie outside it. Only
  // the process whose part of the scene holds that wall finds them; every process must stop
  // with its message instead of waiting for the others.
  const CaseSpec spec =
      test::load_case("dambreak2d.toml", {"simulation.dp=0.04", "domain.max=[4.0, 0.0, 8.0]"});
  EXPECT_THROW(Simulation{spec}, Error);
  const std::vector<std::string> errors = test::on_thread_processes(
      3, [&](ThreadCollectives& coll) { DistributedSimulation(spec, coll); });
  for (int r = 0; r < 3; ++r) {
    EXPECT_NE(errors[r].find("lies outside [domain]"), std::string::npos)
        << "process " << r << ": " << errors[r];
    EXPECT_EQ(errors[r], errors[0]);
  }
}

TEST(Distributed, CutsFallOnTheBinBoundariesNearestEqualShares) {
  // Ten bins of 0.1 m from 1.0 m, the last partial (the domain ends at 1.95 m).
  WorkHistogram h(1.0, 1.95, 0.1);
  ASSERT_EQ(h.bins.size(), 10u);
  for (int k = 0; k < 10; ++k) h.add(1.0 + 0.1 * k + 0.05, ParticleKind::Fluid);
  h.add(0.2, ParticleKind::Fluid);  // below lo: the first bin (callers clamp)
  h.add(1.31, ParticleKind::Wall);  // kSolidWork in bin 3
  EXPECT_DOUBLE_EQ(h.bins[0], 2.0);
  EXPECT_DOUBLE_EQ(h.bins[3], 1.0 + kSolidWork);
  // Uniform work: equal slabs.
  WorkHistogram u(0.0, 1.0, 0.1);
  for (double& b : u.bins) b = 1.0;
  const std::vector<double> halves = equal_work_cuts(u, 1.0, 2);
  ASSERT_EQ(halves.size(), 3u);
  EXPECT_DOUBLE_EQ(halves[0], 0.0);
  EXPECT_NEAR(halves[1], 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(halves[2], 1.0);
  // All the work in bins 7 and 8: the cut between them, the others kept a bin apart.
  for (double& b : u.bins) b = 0.0;
  u.bins[7] = u.bins[8] = 50.0;
  const std::vector<double> peak = equal_work_cuts(u, 1.0, 4);
  EXPECT_NEAR(peak[2], 0.8, 1e-12);  // half the work on each side
  for (int r = 0; r < 4; ++r) EXPECT_GE(peak[r + 1] - peak[r], 0.1 - 1e-12) << r;
  EXPECT_THROW(equal_work_cuts(u, 1.0, 11), Error);  // fewer bins than slabs
}

TEST(Distributed, TheExchangeSendsOwnersTheirParticlesAndTheHaloOnAnyThreadCount) {
  // Three processes, each starting with 30000 particles anywhere in the domain (and 7 outside
  // it): after one exchange each holds exactly the particles of its slab and copies of the
  // others' within the halo, in the same order whether it packs on one thread or four.
  const double halo = 0.3;
  SlabPartition slabs;
  slabs.axis = 0;
  slabs.cuts = {0.0, 1.5, 2.5, 4.0};
  slabs.halo = halo;
  CellGrid grid;
  grid.configure({0, 0, 0}, {4, 1, 1}, 0.1, 0.0, 3);
  const auto start = [](int r) {
    std::mt19937 rng(100 + r);
    std::uniform_real_distribution<double> u(0, 1);
    ParticleSet p;
    p.next_id = 100000 * r;
    for (int k = 0; k < 30000; ++k)
      p.add({4 * u(rng), u(rng), u(rng)}, {}, 1000, ParticleKind::Fluid,
            static_cast<std::uint32_t>(k));
    for (int k = 0; k < 7; ++k) p.add({5, 0.5, 0.5}, {}, 1000, ParticleKind::Fluid);
    return p;
  };
  std::vector<ParticleSet> everyone;
  for (int r = 0; r < 3; ++r) everyone.push_back(start(r));
  std::map<int, std::vector<ParticleSet>> after;
  for (const int threads : {1, 4}) {
    after[threads].resize(3);
    std::vector<std::uint64_t> lost(3);
    const auto errors = test::on_thread_processes(3, [&](ThreadCollectives& coll) {
      omp_set_num_threads(threads);
      ParticleExchange exchange(slabs, coll);
      ParticleSet p = start(coll.rank());
      exchange.own_all(p);
      lost[coll.rank()] = exchange.exchange(p, grid).lost;
      after[threads][coll.rank()] = p;
    });
    for (const std::string& e : errors) EXPECT_EQ(e, "");
    for (int r = 0; r < 3; ++r) EXPECT_EQ(lost[r], 7u);
  }
  for (int r = 0; r < 3; ++r) {
    const ParticleSet &one = after[1][r], &four = after[4][r];
    EXPECT_TRUE(one.pos == four.pos && one.id == four.id && one.group == four.group &&
                one.rho == four.rho && one.kind == four.kind)
        << "process " << r << ": four threads pack another order or other particles";
    // What process r must hold: its slab's particles and the others' within the halo.
    std::vector<std::uint32_t> expected;
    for (const ParticleSet& p : everyone)
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.pos[i].x < 4 &&
            (slabs.owner_of(p.pos[i]) == r || slabs.distance_to(r, p.pos[i]) < halo))
          expected.push_back(p.id[i]);
    std::vector<std::uint32_t> held = one.id;
    std::sort(expected.begin(), expected.end());
    std::sort(held.begin(), held.end());
    EXPECT_EQ(held, expected) << "process " << r;
    for (std::size_t i = 0; i < one.size(); ++i) {  // every field arrived with its particle
      const ParticleSet& from = everyone[one.id[i] / 100000];
      const std::size_t k = one.id[i] % 100000;
      ASSERT_EQ(one.pos[i], from.pos[k]);
      ASSERT_EQ(one.group[i], from.group[k]);
    }
  }
}

TEST(Distributed, SlabsBalanceParticlesAndOwnEveryPositionOnce) {
  SlabPartition s;
  s.axis = 0;
  s.cuts = {0.0, 1.0, 2.5, 4.0};
  s.halo = 0.3;
  s.periodic = true;
  EXPECT_EQ(s.owner_of({0.5, 0, 0}), 0);
  EXPECT_EQ(s.owner_of({1.0, 0, 0}), 1);                   // a cut belongs to the slab above it
  EXPECT_EQ(s.owner_of({4.2, 0, 0}), 0);                   // wrapped round the period
  EXPECT_EQ(s.owner_of({-0.1, 0, 0}), 2);                  // wrapped
  EXPECT_NEAR(s.distance_to(0, {3.9, 0, 0}), 0.1, 1e-12);  // through the period
  EXPECT_EQ(s.halo_neighbours(1), (std::vector<int>{0, 2}));
  s.periodic = false;
  EXPECT_EQ(s.owner_of({-0.1, 0, 0}), 0);  // clamped
  EXPECT_EQ(s.owner_of({9.0, 0, 0}), 2);
  EXPECT_NEAR(s.distance_to(0, {3.9, 0, 0}), 2.9, 1e-12);
  EXPECT_EQ(s.halo_neighbours(0), (std::vector<int>{1}));
}

}  // namespace
}  // namespace netsph
