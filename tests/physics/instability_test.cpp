// A run that goes wrong stops within one step with a diagnosis (time, step, particle ids and
// positions), keeps everything written before, adds a final snapshot, keeps its last good
// checkpoint, and reports "unstable": a non-finite state, a collapsing time step, and fluid
// leaving the domain, each provoked on the 2D dam break (cases/dambreak2d.toml).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "case_runs.hpp"
#include "netsph/io/checkpoint_file.hpp"
#include "netsph/run/runner.hpp"

namespace netsph {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("netsph_instability_" + name);
  fs::remove_all(d);
  return d;
}

RunReport run_quietly(Simulation& sim, const fs::path& dir) {
  RunOptions o;
  o.out_dir = dir;
  o.progress = false;
  return run_simulation(sim, o);
}

nlohmann::json summary_of(const fs::path& dir) {
  std::ifstream in(dir / "summary.json");
  return nlohmann::json::parse(in);
}

TEST(Instability, NonFiniteStateStopsWithTheParticleAndKeepsTheOutputs) {
  Simulation sim(test::load_case("dambreak2d.toml"));
  for (int i = 0; i < 3; ++i) sim.step();
  std::size_t victim = 0;
  while (!is_fluid(sim.particles().kind[victim])) ++victim;
  sim.particles().vel[victim].x = std::numeric_limits<float>::quiet_NaN();
  const fs::path dir = fresh_dir("nan");
  const RunReport r = run_quietly(sim, dir);
  EXPECT_EQ(r.status, "unstable");
  EXPECT_NE(r.message.find("non-finite state at t = "), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("particle id "), std::string::npos) << r.message;
  EXPECT_LE(r.steps, 4);  // caught in the first step after the damage
  EXPECT_EQ(summary_of(dir)["status"], "unstable");
  EXPECT_GE(r.snapshots, 2);  // the one at the start and the final one
  EXPECT_TRUE(fs::exists(dir / "particles.xdmf"));
  EXPECT_TRUE(fs::exists(dir / "series.csv"));
}

TEST(Instability, CollapsingTimeStepNamesTheFastestParticle) {
  // A floor at half the dam break's first dt, then one fluid particle squeezed to three times
  // the reference density (as in a collision): its pressure, about 2000 B, throws its
  // neighbours apart and cuts the force limit of dt far below the floor.
  double first_dt = 0;
  {
    Simulation probe(test::load_case("dambreak2d.toml"));
    probe.step();
    first_dt = probe.last_dt();
  }
  Simulation sim(test::load_case("dambreak2d.toml",
                                 {fmt::format("simulation.dt_min={:.6g}", 0.5 * first_dt)}));
  for (int i = 0; i < 3; ++i) sim.step();
  std::size_t victim = 0;
  while (!is_fluid(sim.particles().kind[victim])) ++victim;
  sim.particles().rho[victim] *= 3;
  try {
    sim.step();
    FAIL() << "a dt below dt_min was accepted: dt " << sim.last_dt() << " s, floor "
           << 0.5 * first_dt << " s";
  } catch (const SimulationUnstable& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("time step collapsed at t = "), std::string::npos) << m;
    EXPECT_NE(m.find("(step 3)"), std::string::npos) << m;
    EXPECT_NE(m.find("the strongest acceleration: fluid particle id "), std::string::npos) << m;
  }
}

TEST(Instability, DtMinAboveTheFirstTimeStepIsTheCasesMistake) {
  // A floor above the dam break's first dt (about 1e-4 s) stops the first step, naming the
  // key and what dt was, not colliding particles.
  Simulation sim(test::load_case("dambreak2d.toml", {"simulation.dt_min=0.01"}));
  try {
    sim.step();
    FAIL() << "a dt_min above the first dt was accepted";
  } catch (const SimulationUnstable& e) {
    FAIL() << "reported as an instability: " << e.what();
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("dambreak2d.toml"), std::string::npos) << m;
    EXPECT_NE(m.find("simulation.dt_min = 0.01 s is larger than the first time step"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("set dt_min below"), std::string::npos) << m;
  }
}

TEST(Instability, ARestartTakesTheDtMinItIsGiven) {
  // The floor of a restart is the case's dt_min when it gives one (a restart may change it),
  // not the checkpoint's 1e-4 of the first step.
  Simulation first(test::load_case("dambreak2d.toml"));
  for (int i = 0; i < 3; ++i) first.step();
  CheckpointData saved;
  first.save_state(saved);
  Simulation resumed(test::load_case("dambreak2d.toml", {"simulation.dt_min=0.01"}));
  resumed.restore_state(saved);
  EXPECT_THROW(resumed.step(), SimulationUnstable);
  Simulation unchanged(test::load_case("dambreak2d.toml"));
  unchanged.restore_state(saved);
  EXPECT_NO_THROW(unchanged.step());
}

// Gravity upwards and a lid-less domain 0.2 m above the water: the column lifts out of the
// top. Checkpoints every 0.005 s: the last good one must survive the failure.
void expect_stop_naming_where_fluid_went(StepBackend backend, const std::string& name) {
  Simulation sim(
      test::load_case("dambreak2d.toml",
                      {"simulation.dp=0.04", "fluid.sound_speed=30", "fluid.gravity=[0,0,40]",
                       "domain.max=[4.5,0,2.2]", "wall.0.max=[4,0,2.1]",
                       "output.checkpoint_every=0.005", "output.snapshot_every=0.01"}),
      backend);
  const fs::path dir = fresh_dir(name);
  const RunReport r = run_quietly(sim, dir);
  ASSERT_EQ(r.status, "unstable");
  EXPECT_NE(r.message.find("fluid is leaving the domain at t = "), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("the last to leave: id "), std::string::npos) << r.message;
  EXPECT_GT(sim.diagnostics().lost_total, 0u);
  EXPECT_LT(r.sim_time, 0.5);
  std::printf("%s: stopped at t = %.4f s, step %lld: %s\n", name.c_str(), r.sim_time,
              static_cast<long long>(r.steps), r.message.c_str());
  ASSERT_TRUE(fs::exists(checkpoint_path(dir)));
  const CheckpointData c = read_checkpoint_file(checkpoint_path(dir));
  EXPECT_LT(c.real("sim.time"), r.sim_time);  // the last good state, not the failed one
  EXPECT_GT(c.real("sim.time"), 0.0);
  const auto summary = summary_of(dir);
  EXPECT_EQ(summary["status"], "unstable");
  // The summary names the last to leave, just past the face they crossed: the open top.
  const auto& last = summary["particles"]["last_lost"];
  ASSERT_FALSE(last.empty());
  EXPECT_LE(last.size(), kLostParticlesKept);
  for (const auto& l : last) {
    EXPECT_GT(l["position_m"][2].get<double>(), 2.2) << l.dump();
    EXPECT_LT(l["position_m"][2].get<double>(), 2.4) << l.dump();  // one step past the top
    EXPECT_GT(l["velocity_m_s"][2].get<double>(), 0.0) << l.dump();
  }
}

TEST(Instability, FluidLeavingTheDomainStopsWithWhereItWent) {
  expect_stop_naming_where_fluid_went(StepBackend::Cpu, "escape");
}

// The device step (its logic run on the host) names them the same way: it copies back the
// particles its sort drops, but not the outlets' removals.
TEST(Instability, FluidLeavingTheDomainOnTheDeviceStepStopsWithWhereItWent) {
  expect_stop_naming_where_fluid_went(StepBackend::HostDevice, "escape_device");
}

}  // namespace
}  // namespace netsph
