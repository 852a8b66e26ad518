// The device-shaped step (backend/device/, the CUDA backend's kernels) against the CPU
// backend: the same case advanced the same number of steps must give the same particles and
// time steps up to float round-off (the two sum a particle's pairs in different orders: the
// CPU in vector lanes, the device one pair after another).
//
// The host executor runs the device kernels' logic on the CPU, so these tests check it on
// every machine; the CUDA tests run the same comparison on the GPU and skip, saying why, when
// netsph was built without CUDA or the machine has no usable device.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "case_runs.hpp"
#include "netsph/io/checkpoint_file.hpp"
#include "netsph/run/output_particles.hpp"
#include "netsph/run/runner.hpp"
#include "netsph/sph/kernels.hpp"
#include "netsph/sph/shepard.hpp"
#include "state_difference.hpp"

#include <nlohmann/json.hpp>
#if defined(NETSPH_HAVE_CUDA)
#include "netsph/backend/cuda/cuda_runtime_info.hpp"
#endif

namespace netsph {
namespace {

using test::Difference;
using test::expect_parity;

/// Sets an environment variable for its scope (the device step reads its knobs when it is
/// built), then puts back what was there.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (old_) {
      setenv(name_, old_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

Difference compare(const std::string& name, const std::vector<std::string>& overrides, int steps,
                   StepBackend backend) {
  const CaseSpec spec = test::load_case(name, overrides);
  Simulation cpu(spec);
  Simulation dev(spec, backend);
  double dt = 0;
  for (int s = 0; s < steps; ++s) {
    cpu.step();
    dev.step();
    dt = std::max(dt, std::fabs(dev.last_dt() / cpu.last_dt() - 1));
  }
  EXPECT_EQ(dev.diagnostics().open.created, cpu.diagnostics().open.created);
  EXPECT_EQ(dev.diagnostics().open.removed, cpu.diagnostics().open.removed);
  Difference d = test::state_difference(cpu, dev);
  d.dt = dt;
  return d;
}

// DBC walls, Wendland kernel, Fourtakas diffusion, artificial viscosity, a free surface.
const std::vector<std::string> kDamBreak2D = {"simulation.dp=0.04"};
// Periodic x, mDBC no-slip walls (mirrored velocities), laminar viscosity, Molteni diffusion.
const std::vector<std::string> kPoiseuille = {"simulation.dp=0.01"};
// 3D, mDBC walls, cubic spline kernel, shifting.
const std::vector<std::string> kDamBreak3D = {
    "simulation.dp=0.03", "simulation.kernel=\"cubic_spline\"", "wall.0.model=\"mdbc\"",
    "wall.0.layers=3", "fluid.shifting={model=\"fickian\"}"};

TEST(DeviceParity, HostDamBreak2DMatchesTheCpuBackend) {
  expect_parity(compare("dambreak2d.toml", kDamBreak2D, 200, StepBackend::HostDevice));
}

TEST(DeviceParity, HostPoiseuilleMatchesTheCpuBackend) {
  expect_parity(compare("poiseuille2d.toml", kPoiseuille, 200, StepBackend::HostDevice));
}

TEST(DeviceParity, HostDamBreak3DWithMdbcAndShiftingMatchesTheCpuBackend) {
  expect_parity(compare("dambreak3d.toml", kDamBreak3D, 40, StepBackend::HostDevice));
}

// A wall moving at constant speed, periodic x, mDBC no-slip mirrors.
const std::vector<std::string> kCouette = {};
// A floating mDBC box (6 degrees of freedom reduced to 3 in 2D), heaving.
const std::vector<std::string> kFloatingBox = {"simulation.dp=0.04"};
// A dense box resting on the floor from the start: body-wall contact forces.
const std::vector<std::string> kBoxOnFloor = {"simulation.dp=0.02",
                                              "body.0.center=[0.5, 0.0, 0.049]"};
// A fixed thin plate hit by a dam-break surge.
const std::vector<std::string> kThinPlate = {};

TEST(DeviceParity, HostCouetteWithAMovingWallMatchesTheCpuBackend) {
  expect_parity(compare("couette2d.toml", kCouette, 200, StepBackend::HostDevice));
}

TEST(DeviceParity, HostFloatingBoxMatchesTheCpuBackend) {
  expect_parity(compare("floating_box2d.toml", kFloatingBox, 200, StepBackend::HostDevice));
}

TEST(DeviceParity, HostBoxOnTheFloorWithContactsMatchesTheCpuBackend) {
  expect_parity(compare("sinking_box2d.toml", kBoxOnFloor, 200, StepBackend::HostDevice));
}

TEST(DeviceParity, HostFixedThinPlateMatchesTheCpuBackend) {
  expect_parity(compare("thin_plate_leak2d.toml", kThinPlate, 100, StepBackend::HostDevice));
}

// Open boundaries: a 2D channel with an inlet and an outlet buffer (particles created and
// removed every few steps), shifting.
TEST(DeviceParity, HostOpenChannelMatchesTheCpuBackend) {
  expect_parity(compare("channel2d.toml", {}, 300, StepBackend::HostDevice));
}

// A parabolic inflow profile and a fixed cylinder (the DFG benchmark).
TEST(DeviceParity, HostDfgCylinderMatchesTheCpuBackend) {
  expect_parity(
      compare("dfg_cylinder2d.toml", {"simulation.dp=0.01"}, 100, StepBackend::HostDevice));
}

// A coupled net: a knot tethered by one twine in a duct with an inlet and an outlet, shifting
// on (the bodies and the knot-spring solver on the host, their particles on the device).
TEST(DeviceParity, HostCoupledNetMatchesTheCpuBackend) {
  expect_parity(compare("net_tethered_knot.toml", {}, 40, StepBackend::HostDevice));
}

// A wave flume: a piston paddle (a wall whose velocity history [waves] sets), moving at full
// speed from the first step (no ramp), and a damping zone over the tank from 0.1 m in front of
// the paddle on, relaxing the fluid particles' velocities each step.
const std::vector<std::string> kWaveFlume = {"simulation.dp=0.04", "waves.ramp=0.0",
                                             "damping.0.from=0.1", "damping.0.rate=20.0"};

TEST(DeviceParity, HostWaveFlumeWithPaddleAndDampingMatchesTheCpuBackend) {
  expect_parity(compare("waves/regular_piston2d.toml", kWaveFlume, 200, StepBackend::HostDevice));
}

// Waves on a current: an inlet and an outlet, and a relaxation zone whose target velocity (the
// current plus the wave's orbital velocity) moves with the particle's place and the time, at
// full height from the first step (no ramp), and a damping zone back to the current.
const std::vector<std::string> kWavesOnACurrent = {"simulation.dp=0.04", "waves.ramp=0.0"};

TEST(DeviceParity, HostWavesOnACurrentFromARelaxationZoneMatchesTheCpuBackend) {
  expect_parity(
      compare("waves/current_following2d.toml", kWavesOnACurrent, 200, StepBackend::HostDevice));
}

// A paddle with active absorption: the elevation at its gauge (sampled on the device, or by the
// CPU's probe pass) corrects its velocity every step, at full height from the first step; 400
// steps take it past the gauge-to-paddle delay (0.15 s), when the correction starts.
TEST(DeviceParity, HostAbsorbingPaddleMatchesTheCpuBackend) {
  expect_parity(compare("waves/absorbing_piston2d.toml", {"simulation.dp=0.04", "waves.ramp=0.0"},
                        400, StepBackend::HostDevice));
}

// A flap paddle: a prescribed body turning about its hinge (the host advances it for both
// steps; the device places its particles, their rigid velocity and mDBC ghosts from its state),
// without a ramp so that it turns from the first step.
TEST(DeviceParity, HostFlapPaddleMatchesTheCpuBackend) {
  expect_parity(compare("waves/regular_flap2d.toml", {"simulation.dp=0.04", "waves.ramp=0.0"}, 300,
                        StepBackend::HostDevice));
}

// The same comparisons with every launch's threads visited in reverse and in shuffled order
// (and, always, uninitialised device memory as 0xFF bytes: host_exec.hpp), as a GPU runs them
// in no fixed order: a kernel in which one particle reads what another writes in the same
// launch would differ here, where the parallel forward loop above happens to agree.
TEST(DeviceParity, HostInReverseAndShuffledOrderMatchesTheCpuBackend) {
  for (const char* order : {"reverse", "shuffle"}) {
    SCOPED_TRACE(order);
    const ScopedEnv scoped("NETSPH_HOST_EXEC_ORDER", order);
    // Open boundaries (creation, removal, the scans), mDBC walls, a body and the knot-spring
    // coupling, periodic walls: the kernels a GPU runs, each in a case that needs it.
    expect_parity(compare("net_tethered_knot.toml", {}, 15, StepBackend::HostDevice));
    expect_parity(compare("channel2d.toml", {}, 100, StepBackend::HostDevice));
    expect_parity(compare("sinking_box2d.toml", kBoxOnFloor, 60, StepBackend::HostDevice));
    expect_parity(compare("poiseuille2d.toml", kPoiseuille, 60, StepBackend::HostDevice));
  }
}

// The rates pass gathers a batch of neighbours before summing them (device_rates_particle,
// for a GPU warp's sake); the neighbours, their order and so the sums must be the same for
// every batch size, bit for bit, as for the loop that sums each pair where it finds it
// (batch 0). A batch that ends inside a range, on a range's last candidate or across a
// periodic boundary (x in Poiseuille, y in the 3D channel) each resume the scan differently.
void expect_same_for_every_batch(const std::string& name, const std::vector<std::string>& overrides,
                                 int steps) {
  SCOPED_TRACE(name);
  const CaseSpec spec = test::load_case(name, overrides);
  std::optional<Simulation> plain;
  {
    const ScopedEnv batch("NETSPH_RATES_BATCH", "0");
    plain.emplace(spec, StepBackend::HostDevice);
  }
  for (int s = 0; s < steps; ++s) plain->step();
  for (const char* size : {"1", "3", "12", "16", "32"}) {
    SCOPED_TRACE(std::string("batch ") + size);
    const ScopedEnv batch("NETSPH_RATES_BATCH", size);
    Simulation batched(spec, StepBackend::HostDevice);
    for (int s = 0; s < steps; ++s) batched.step();
    const Difference d = test::state_difference(*plain, batched);
    EXPECT_EQ(d.pos, 0.0);
    EXPECT_EQ(d.vel, 0.0);
    EXPECT_EQ(d.rho, 0.0);
    EXPECT_EQ(d.body_force, 0.0);
  }
}

TEST(DeviceParity, HostRatesAreTheSameForEveryBatchSize) {
  expect_same_for_every_batch("poiseuille2d.toml", kPoiseuille, 30);
  // Periodic in x and z, no walls, two layers sliding past each other: fluid pairs with
  // different velocities across both periodic boundaries (a uniform state would sum to zero
  // whatever pairs were missed).
  expect_same_for_every_batch("poiseuille2d.toml",
                              {"domain.periodic=[\"x\", \"z\"]", "domain.min=[0, 0, 0]",
                               "domain.max=[0.1, 0, 0.1]", "wall=[]",
                               "fill=[{min=[0, 0, 0], max=[0.1, 0, 0.05], velocity=[0.1, 0, 0]},"
                               " {min=[0, 0, 0.05], max=[0.1, 0, 0.1], velocity=[-0.1, 0, 0.05]}]"},
                              30);
  expect_same_for_every_batch("channel3d.toml", {}, 10);
  expect_same_for_every_batch("net_tethered_knot.toml", {}, 10);
}

void expect_environment_error(const char* name, const char* value, const std::string& message) {
  const CaseSpec spec = test::load_case("poiseuille2d.toml", kPoiseuille);
  const ScopedEnv scoped(name, value);
  try {
    Simulation sim(spec, StepBackend::HostDevice);
    ADD_FAILURE() << name << "=" << value << " was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

TEST(DeviceParity, RatesKernelSettingsOutsideTheirRangeAreAClearError) {
  expect_environment_error("NETSPH_RATES_BATCH", "33",
                           "NETSPH_RATES_BATCH is '33': it must be a whole number from 0 (no "
                           "batches) to 32");
  expect_environment_error("NETSPH_RATES_BATCH", "8x", "NETSPH_RATES_BATCH is '8x'");
  expect_environment_error("NETSPH_RATES_MAX_REGISTERS", "48",
                           "NETSPH_RATES_MAX_REGISTERS is '48': it must be a whole number 0 (no "
                           "cap), 64 or 80");
  expect_environment_error("NETSPH_CUDA_FAST_MATH", "yes", "NETSPH_CUDA_FAST_MATH is 'yes'");
  expect_environment_error("NETSPH_RATES_TRIM", "1",
                           "NETSPH_RATES_TRIM is '1': the trimmed rates scan was removed");
}

// The whole run on the device step: outputs (snapshots, series, probes, nets, summary.json)
// written from particles copied back on demand, the same as the CPU run's; and a run continued
// from a checkpoint restarts the device step where it stopped.
nlohmann::json run_summary(StepBackend backend, const std::string& folder) {
  const CaseSpec spec =
      read_case_file(std::string(NETSPH_TEST_CASES_DIR) + "/good/plot_smoke.toml", {});
  Simulation sim(spec, backend);
  RunOptions opt;
  opt.out_dir = std::filesystem::temp_directory_path() / folder;
  opt.progress = false;
  std::filesystem::remove_all(opt.out_dir);
  const RunReport report = run_simulation(sim, opt);
  EXPECT_EQ(report.status, "completed");
  std::ifstream in(opt.out_dir / "summary.json");
  return nlohmann::json::parse(in);
}

TEST(DeviceParity, DeviceStepOfTheBenchmarkCaseHoldsAtMost150BytesAParticle) {
  // Issue 8's memory target, on the benchmark case (DBC, no shifting, no bodies) as `netsph
  // bench` runs it: every device buffer at its capacity, the work area and the cell table
  // (docs/PERFORMANCE.md lists the parts). The persistent state alone is 81 B.
  Simulation dev(test::load_case("dambreak3d.toml", {"simulation.dp=0.02"}),
                 StepBackend::HostDevice);
  dev.step();
  std::printf("device memory: %.1f B/particle for %zu particles\n", dev.bytes_per_particle(),
              dev.particles().size());
  EXPECT_LE(dev.bytes_per_particle(), 150.0);
  EXPECT_GE(dev.bytes_per_particle(), 81.0);
}

TEST(DeviceParity, HostDeviceRunWritesTheOutputsOfTheCpuRun) {
  const nlohmann::json a = run_summary(StepBackend::Cpu, "netsph_device_run_cpu");
  const nlohmann::json b = run_summary(StepBackend::HostDevice, "netsph_device_run_dev");
  EXPECT_EQ(a["outputs"]["snapshots"], b["outputs"]["snapshots"]);
  EXPECT_EQ(a["time"]["steps"], b["time"]["steps"]);
  const auto rel = [](double x, double y) {
    return std::fabs(x - y) / std::max(std::fabs(x), 1e-12);
  };
  const nlohmann::json& na = a["nets"][0];
  const nlohmann::json& nb = b["nets"][0];
  EXPECT_LT(rel(na["mean_max_tension_N"], nb["mean_max_tension_N"]), 1e-5);
  EXPECT_LT(rel(na["mean_max_deflection_m"], nb["mean_max_deflection_m"]), 1e-5);
  ASSERT_EQ(a["probes"].size(), b["probes"].size());
  for (std::size_t k = 0; k < a["probes"].size(); ++k) {
    if (!a["probes"][k].contains("mean_ux_m_s")) continue;
    EXPECT_LT(rel(a["probes"][k]["mean_ux_m_s"], b["probes"][k]["mean_ux_m_s"]), 1e-5)
        << a["probes"][k]["name"];
  }
}

// The series rows' measures and the probes are computed on the device (Exec::reduce with the
// CPU's tally formula; the sinker bars' sampling kernel), so a run copies its particles back
// only for snapshots and checkpoints. Both must equal what the CPU code computes from the
// particles copied back, and must not copy them.
/// The Shepard sums at `at` over every fluid particle of `p` (nearest periodic image), without
/// the grid: the reference for the device's samples, independent of its cell table.
ShepardValue brute_force_sample(const Simulation& sim, const ParticleSet& p, const Vec3d& at) {
  const FluidModel& m = sim.model();
  const auto& domain = sim.spec().domain;
  ShepardSums sums;
  with_kernel(m.kernel_type, [&](auto kernel) {
    using K = decltype(kernel);
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (p.kind[j] != ParticleKind::Fluid) continue;
      Vec3d d = at - p.pos[j];
      for (int axis = 0; axis < 3; ++axis) {
        if (const double period = domain.period(axis); period > 0)
          d[axis] -= period * std::round(d[axis] / period);
      }
      const double r2 = norm2(d);
      if (!(r2 < m.support2)) continue;
      shepard_accumulate_fluid(sums, kernel_value<K>(m.kernel, static_cast<Real>(std::sqrt(r2))),
                               m.mass, p.rho[j], p.vel[j], m.eos);
    }
    return 0;
  });
  return shepard_value(sums);
}

// `tolerance`: of the samples, relative to 1 (coverage) or to the value; the reference sums
// the same terms in another order, the GPU may also contract them differently.
// `overrides` that make the particles move past the grid's skin within a step test the
// samples on the cell table of the half step's re-sort.
void expect_measures_and_samples_where_they_are(StepBackend backend, double tolerance,
                                                const std::vector<std::string>& overrides,
                                                bool resorts) {
  const CaseSpec spec =
      read_case_file(std::string(NETSPH_TEST_CASES_DIR) + "/good/plot_smoke.toml", overrides);
  Simulation dev(spec, backend);
  std::vector<Vec3d> points;
  for (int k = 0; k <= 40; ++k) {
    // Across the duct (fluid, its walls, the knots) and out of the fluid and the grid.
    points.push_back({-0.1 + 0.009 * k, 0.0, -0.14 + 0.006 * k});
    points.push_back({0.02, -0.2 + 0.01 * k, 0.0});
  }
  std::vector<ShepardValue> on_device(points.size());
  // Before its first step the device has no cell table: the host samples.
  EXPECT_FALSE(dev.sample_on_device(points, on_device));
  for (int s = 0; s < 25; ++s) dev.step();
  if (resorts) {
    EXPECT_GT(dev.diagnostics().resorts, 0);
  }
  const std::optional<ParticleTally> t = dev.tally_on_device();
  ASSERT_TRUE(t.has_value());
  ASSERT_TRUE(dev.sample_on_device(points, on_device));
  EXPECT_EQ(dev.device_downloads(), 0);

  const ParticleSet& p = dev.particles();  // the one copy back
  EXPECT_EQ(dev.device_downloads(), 1);
  const GlobalMeasures host = measure_particles(p, dev.model().mass);
  const GlobalMeasures device = measures_of(*t, dev.model().mass);
  EXPECT_GT(host.fluid, 0u);
  EXPECT_GT(host.walls, 0u);
  EXPECT_EQ(device.fluid, host.fluid);
  EXPECT_EQ(device.walls, host.walls);
  EXPECT_EQ(device.buffer, host.buffer);
  EXPECT_GT(host.kinetic_energy, 0.0);
  EXPECT_NEAR(device.kinetic_energy, host.kinetic_energy, 1e-12 * host.kinetic_energy);
  EXPECT_EQ(device.max_speed, host.max_speed);
  EXPECT_EQ(device.min_density, host.min_density);
  EXPECT_EQ(device.max_density, host.max_density);

  const double pressure_scale =
      spec.fluid.density * dev.scene().sound_speed * dev.scene().sound_speed;
  int wet = 0, dry = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    SCOPED_TRACE(k);
    const ShepardValue a = brute_force_sample(dev, p, points[k]);
    const ShepardValue& b = on_device[k];
    EXPECT_NEAR(b.coverage, a.coverage, tolerance);
    wet += a.coverage > 0.5, dry += a.coverage == 0;
    // At a tiny coverage one particle at the support's edge, in or out by a rounding, moves
    // the normalised values by its own: the coverage above has already compared it.
    if (!(a.coverage > 1e-3)) continue;
    EXPECT_LT(norm(b.velocity - a.velocity), tolerance * (0.3 + norm(a.velocity)));
    // Gauge pressures are small differences of the equation of state's large terms: their
    // scale is rho0 c0^2.
    EXPECT_NEAR(b.pressure, a.pressure, tolerance * pressure_scale);
    EXPECT_NEAR(b.density, a.density, tolerance * a.density);
  }
  EXPECT_GT(wet, 20);  // the points cross the fluid ...
  EXPECT_GT(dry, 5);   // ... and leave it
  EXPECT_EQ(dev.device_downloads(), 1);

  // A restart rebuilds the device step, which has no cell table until it steps again.
  CheckpointData saved;
  dev.save_state(saved);
  dev.restore_state(saved);
  EXPECT_FALSE(dev.sample_on_device(points, on_device));
  dev.step();
  EXPECT_TRUE(dev.sample_on_device(points, on_device));
}

// The plot_smoke duct at 1.5 m/s and cfl 0.6: the particles outrun the grid's skin in every
// half step (cell table of the re-sort).
const std::vector<std::string> kFastDuct = {"simulation.cfl=0.6", "fill.0.velocity=[1.5, 0, 0]",
                                            "wall.0.velocity=[1.5, 0, 0]", "inlet.0.velocity=1.5"};

TEST(DeviceParity, HostDeviceMeasuresAndSamplesTheParticlesWhereTheyAre) {
  expect_measures_and_samples_where_they_are(StepBackend::HostDevice, 1e-6, {}, false);
  expect_measures_and_samples_where_they_are(StepBackend::HostDevice, 1e-6, kFastDuct, true);
}

// A whole run without snapshots: its series rows and probes are measured on the device, and
// the particles come back once, for the checkpoint at the end.
TEST(DeviceParity, HostDeviceRunCopiesParticlesBackOnlyForCheckpoints) {
  const CaseSpec spec = read_case_file(std::string(NETSPH_TEST_CASES_DIR) + "/good/plot_smoke.toml",
                                       {"output.snapshots=false", "output.checkpoint_every=1.0"});
  Simulation sim(spec, StepBackend::HostDevice);
  RunOptions opt;
  opt.out_dir = std::filesystem::temp_directory_path() / "netsph_device_downloads";
  opt.progress = false;
  std::filesystem::remove_all(opt.out_dir);
  const RunReport report = run_simulation(sim, opt);
  EXPECT_EQ(report.status, "completed");
  EXPECT_GT(sim.steps(), 20);
  EXPECT_EQ(sim.device_downloads(), 1);
  std::ifstream in(opt.out_dir / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_GT(j["probes"].size(), 0u);
  EXPECT_GT(j["final_state"]["kinetic_energy_J"].get<double>(), 0.0);
}

TEST(DeviceParity, HostDeviceRunContinuesFromACheckpoint) {
  const CaseSpec spec =
      read_case_file(std::string(NETSPH_TEST_CASES_DIR) + "/good/plot_smoke.toml", {});
  Simulation whole(spec, StepBackend::HostDevice);
  for (int i = 0; i < 20; ++i) whole.step();
  CheckpointData saved;
  whole.save_state(saved);
  for (int i = 0; i < 20; ++i) whole.step();
  Simulation resumed(spec, StepBackend::HostDevice);
  resumed.restore_state(saved);
  for (int i = 0; i < 20; ++i) resumed.step();
  EXPECT_EQ(resumed.steps(), 40);
  EXPECT_NEAR(resumed.time(), whole.time(), 1e-12);
  const ParticleSet& p = whole.particles();
  const ParticleSet& q = resumed.particles();
  ASSERT_EQ(p.size(), q.size());
  double worst = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.id[i], q.id[i]);
    worst = std::max(worst, norm(p.pos[i] - q.pos[i]));
  }
  // Float sums over the same particles in the same order; the body sums use atomics, whose
  // order may differ: round-off only.
  EXPECT_LT(worst / spec.simulation.dp, 1e-5);
}

/// Skips the calling test unless a CUDA device is usable.
#define SKIP_WITHOUT_GPU()                                                            \
  do {                                                                                \
    if (const std::string why = gpu_unavailable(); !why.empty()) GTEST_SKIP() << why; \
  } while (0)

std::string gpu_unavailable() {
#if defined(NETSPH_HAVE_CUDA)
  const cuda::RuntimeInfo info = cuda::runtime_info();
  return info.devices > 0 ? "" : "no usable CUDA device: " + info.error;
#else
  return "netsph was built without CUDA";
#endif
}

// The rates kernel's variants a GPU session measures (device_rates_particle's batches,
// the register caps, fast math): each must match the CPU as the default does.
// Poiseuille: periodic x.
TEST(DeviceParity, CudaRatesKernelVariantsMatchTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  for (const auto& [name, value] :
       {std::pair{"NETSPH_RATES_BATCH", "0"}, std::pair{"NETSPH_RATES_BATCH", "1"},
        std::pair{"NETSPH_RATES_BATCH", "8"}, std::pair{"NETSPH_RATES_BATCH", "32"},
        std::pair{"NETSPH_RATES_MAX_REGISTERS", "80"}, std::pair{"NETSPH_RATES_MAX_REGISTERS", "0"},
        std::pair{"NETSPH_CUDA_FAST_MATH", "1"}}) {
    SCOPED_TRACE(std::string(name) + "=" + value);
    const ScopedEnv scoped(name, value);
    expect_parity(compare("poiseuille2d.toml", kPoiseuille, 100, StepBackend::Cuda));
  }
}

TEST(DeviceParity, CudaDamBreak2DMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(compare("dambreak2d.toml", kDamBreak2D, 200, StepBackend::Cuda));
}

TEST(DeviceParity, CudaPoiseuilleMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(compare("poiseuille2d.toml", kPoiseuille, 200, StepBackend::Cuda));
}

TEST(DeviceParity, CudaDamBreak3DWithMdbcAndShiftingMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(compare("dambreak3d.toml", kDamBreak3D, 40, StepBackend::Cuda));
}

TEST(DeviceParity, CudaCouetteWithAMovingWallMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(compare("couette2d.toml", kCouette, 200, StepBackend::Cuda));
}

TEST(DeviceParity, CudaFloatingBoxMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(compare("floating_box2d.toml", kFloatingBox, 200, StepBackend::Cuda));
}

TEST(DeviceParity, CudaCoupledNetMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(compare("net_tethered_knot.toml", {}, 40, StepBackend::Cuda));
}

TEST(DeviceParity, CudaOpenChannelMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(compare("channel2d.toml", {}, 300, StepBackend::Cuda));
}

TEST(DeviceParity, CudaDfgCylinderMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(compare("dfg_cylinder2d.toml", {"simulation.dp=0.01"}, 100, StepBackend::Cuda));
}

// Without a usable device the CUDA run is refused with the reason and the way out, never a
// crash (CI builds with nvcc and has no GPU).
TEST(DeviceParity, CudaWaveFlumeWithPaddleAndDampingMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(compare("waves/regular_piston2d.toml", kWaveFlume, 200, StepBackend::Cuda));
}

TEST(DeviceParity, CudaWavesOnACurrentFromARelaxationZoneMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(
      compare("waves/current_following2d.toml", kWavesOnACurrent, 200, StepBackend::Cuda));
}

TEST(DeviceParity, CudaFlapPaddleMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(compare("waves/regular_flap2d.toml", {"simulation.dp=0.04", "waves.ramp=0.0"}, 300,
                        StepBackend::Cuda));
}

TEST(DeviceParity, CudaWithoutADeviceIsAClearError) {
  if (gpu_unavailable().empty()) GTEST_SKIP() << "a CUDA device is present";
  try {
    Simulation sim(test::load_case("dambreak2d.toml", kDamBreak2D), StepBackend::Cuda);
    FAIL() << "a CUDA run was made without a device";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--backend cpu"), std::string::npos) << e.what();
  }
}

TEST(DeviceParity, CudaMeasuresAndSamplesTheParticlesWhereTheyAre) {
  SKIP_WITHOUT_GPU();
  expect_measures_and_samples_where_they_are(StepBackend::Cuda, 1e-5, {}, false);
  expect_measures_and_samples_where_they_are(StepBackend::Cuda, 1e-5, kFastDuct, true);
}

TEST(DeviceParity, CudaBoxOnTheFloorWithContactsMatchesTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  expect_parity(compare("sinking_box2d.toml", kBoxOnFloor, 200, StepBackend::Cuda));
}

}  // namespace
}  // namespace netsph
