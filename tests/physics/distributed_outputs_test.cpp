// The outputs of a run on three processes against those of the same run on one. A distributed
// run's outputs read the processes' own particles where they are (distributed_stepper.hpp):
// series rows and the summary from measures summed over the processes, probes from Shepard
// sums added up over them, snapshots and checkpoints written from one process's particles at a
// time. The split run's particles are those of the run on one process to the bit (each sums
// its pairs in the same order: distributed_test.cpp), so snapshots and checkpoints must be the
// same, and every file of numbers the same but for the round-off of the processes' other
// summation order in double (kPrinted below), compared over the first 0.06 s of the 2D dam
// break; and the distributed checkpoint must continue as one process.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "case_runs.hpp"
#include "hdf5_read.hpp"
#include "netsph/distributed/distributed_stepper.hpp"
#include "netsph/distributed/scene_parts.hpp"
#include "netsph/io/checkpoint_file.hpp"
#include "netsph/run/runner.hpp"
#include "thread_processes.hpp"

namespace netsph {
namespace {

namespace fs = std::filesystem;

CaseSpec outputs_case() {
  CaseSpec spec = test::load_case(
      "dambreak2d.toml",
      {"simulation.dp=0.04", "simulation.end_time=0.06", "output.snapshot_every=0.02",
       "output.series_every=0.005", "output.checkpoint_every=0.03",
       "output.snapshot_region={ min = [-0.2, 0, -0.2], max = [1.5, 0, 1.0] }"});
  ProbeSpec line;  // across the collapsing column's foot, into the dry tank
  line.name = "line";
  line.type = ProbeType::Line;
  line.a = {0.1, 0, 0.2};
  line.b = {1.4, 0, 0.2};
  line.points = 14;
  line.every = 0.01;
  spec.probes.push_back(line);
  return spec;
}

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() /
                     ("netsph_distributed_outputs_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  return d;
}

RunOptions quiet_run(const fs::path& dir) {
  RunOptions o;
  o.out_dir = dir;
  o.progress = false;
  return o;
}

/// The run on `processes` threads, each a process of the run with one OpenMP thread; returns
/// each process's error ("" when it ran through).
/// `resumes`: each process's checkpoint to continue from (its part of the file, as `netsph run
/// --restart` reads it under mpirun), or null.
std::vector<std::string> try_run_on(const CaseSpec& spec, int processes, const fs::path& dir,
                                    const std::vector<CheckpointData>* resumes = nullptr) {
  return test::on_thread_processes(processes, [&](ThreadCollectives& coll) {
    const CheckpointData* resume = resumes ? &(*resumes)[coll.rank()] : nullptr;
    DistributedStepper stepper(spec, coll, resume);
    stepper.set_output_block_rows(97);  // each process's particles reach the files in blocks
    RunOptions opt = quiet_run(dir);
    opt.resume = resume;
    run_stepped(stepper, opt);
  });
}

void run_on(const CaseSpec& spec, int processes, const fs::path& dir,
            const std::vector<CheckpointData>* resumes = nullptr) {
  const std::vector<std::string> errors = try_run_on(spec, processes, dir, resumes);
  for (int r = 0; r < processes; ++r) EXPECT_EQ(errors[r], "") << "process " << r;
}

/// A CSV file of numbers: its header's names and its rows.
struct Csv {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
};

Csv read_csv(const fs::path& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in) << file;
  Csv csv;
  std::string line, cell;
  std::getline(in, line);
  for (std::istringstream h(line); std::getline(h, cell, ',');)
    csv.names.push_back(cell.substr(0, cell.find(' ')));
  while (std::getline(in, line)) {
    std::vector<double>& row = csv.rows.emplace_back();
    for (std::istringstream r(line); std::getline(r, cell, ',');)
      row.push_back(std::strtod(cell.c_str(), nullptr));
  }
  return csv;
}

/// Every column of `b` within rel of `a`'s largest magnitude in that column (NaN where `a`
/// has NaN); the wall time is the one column allowed to differ.
void expect_csv_close(const fs::path& a_file, const fs::path& b_file, double rel) {
  const Csv a = read_csv(a_file), b = read_csv(b_file);
  ASSERT_EQ(a.names, b.names) << a_file;
  ASSERT_EQ(a.rows.size(), b.rows.size()) << a_file;
  ASSERT_GT(a.rows.size(), 2u) << a_file;
  for (std::size_t c = 0; c < a.names.size(); ++c) {
    if (a.names[c] == "wall_time") continue;
    double scale = 0;
    for (const auto& row : a.rows)
      if (std::isfinite(row.at(c))) scale = std::max(scale, std::fabs(row[c]));
    for (std::size_t r = 0; r < a.rows.size(); ++r) {
      const double x = a.rows[r].at(c), y = b.rows[r].at(c);
      if (std::isnan(x)) {
        EXPECT_TRUE(std::isnan(y)) << a_file.filename() << " row " << r << " " << a.names[c];
        continue;
      }
      EXPECT_LE(std::fabs(x - y), rel * scale)
          << a_file.filename() << " row " << r << " " << a.names[c] << ": " << x << " vs " << y;
    }
  }
}

/// Positions by particle id.
std::map<std::uint32_t, Vec3d> positions_by_id(std::span<const std::uint32_t> id,
                                               std::span<const double> pos) {
  std::map<std::uint32_t, Vec3d> out;
  for (std::size_t k = 0; k < id.size(); ++k)
    out[id[k]] = {pos[3 * k], pos[3 * k + 1], pos[3 * k + 2]};
  return out;
}

/// The same particles (ids), at positions within tol of each other.
void expect_same_particles(const std::map<std::uint32_t, Vec3d>& a,
                           const std::map<std::uint32_t, Vec3d>& b, double tol,
                           const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  double worst = 0;
  for (auto ia = a.begin(), ib = b.begin(); ia != a.end(); ++ia, ++ib) {
    ASSERT_EQ(ia->first, ib->first) << what << ": particle ids differ";
    worst = std::max(worst, norm(ia->second - ib->second));
  }
  EXPECT_LE(worst, tol) << what;
}

/// How far apart two CSV files of the same particles may print a value, relative to the
/// largest magnitude in its column. Maxima and minima over the processes (speed, density, the
/// dt limits) do not round and print the same. Sums over the processes (kinetic energy, fluid
/// mass, a probe's Shepard sums) are added in double in another order: at most n u sum|x_k|
/// apart (Higham 2002, eq. 4.4; u = 1.1e-16) with n < 1e4 terms whose magnitudes add up to no
/// more than the column's scale for energy and mass (positive terms) and a Shepard average
/// (weights w_k >= 0 over their sum: sum |w_k v_k| / sum w_k <= max |v|): 1.1e-12. Printed with
/// 9 significant digits (csv_series.cpp, %.9g), two values that close can still print a unit
/// of the 9th digit apart, at most 1e-8 of the value. 2e-8 covers both.
constexpr double kPrinted = 2e-8;

TEST(DistributedOutputs, ThreeProcessesWriteTheFilesOfOne) {
  const CaseSpec spec = outputs_case();
  const fs::path one = temp_dir("one"), three = temp_dir("three");
  {
    Simulation sim(spec);
    run_simulation(sim, quiet_run(one));
  }
  run_on(spec, 3, three);

  expect_csv_close(one / "series.csv", three / "series.csv", kPrinted);
  expect_csv_close(one / "probes" / "line.csv", three / "probes" / "line.csv", kPrinted);
  expect_csv_close(one / "probes" / "line_mean.csv", three / "probes" / "line_mean.csv", kPrinted);

  // Every snapshot: the particles inside the region, at the same places.
  std::vector<std::string> snapshots;
  for (const auto& e : fs::directory_iterator(one / "snapshots"))
    snapshots.push_back(e.path().filename().string());
  std::sort(snapshots.begin(), snapshots.end());
  ASSERT_EQ(snapshots.size(), 4u);  // t = 0, 0.02, 0.04, 0.06
  std::size_t shown = 0;
  for (const std::string& s : snapshots) {
    const auto read = [&](const fs::path& dir) {
      const fs::path f = dir / "snapshots" / s;
      return positions_by_id(test::read_dataset<std::uint32_t>(f, "id", H5T_NATIVE_UINT32, 1),
                             test::read_dataset<double>(f, "position", H5T_NATIVE_DOUBLE, 3));
    };
    const auto a = read(one);
    expect_same_particles(a, read(three), 0.0, s);
    shown = a.size();
  }
  const CheckpointData ca = read_checkpoint_file(checkpoint_path(one));
  const CheckpointData cb = read_checkpoint_file(checkpoint_path(three));
  const auto whole = positions_by_id(ca.u32.at("particles.id"), ca.f64.at("particles.pos"));
  EXPECT_LT(shown, whole.size() / 2) << "the snapshot region holds most particles: test nothing";
  EXPECT_GT(shown, 200u);
  // The checkpoint: every particle, and the rest of the state.
  expect_same_particles(whole,
                        positions_by_id(cb.u32.at("particles.id"), cb.f64.at("particles.pos")), 0.0,
                        "checkpoint");
  EXPECT_EQ(ca.u32.at("particles.next_id"), cb.u32.at("particles.next_id"));
  EXPECT_EQ(ca.real("sim.steps"), cb.real("sim.steps"));
  EXPECT_EQ(ca.reals("outputs.next"), cb.reals("outputs.next"));
  for (const char* array : {"particles.vel", "particles.rho", "particles.ghost"})
    EXPECT_EQ(ca.f32.at(array).size(), cb.f32.at(array).size()) << array;

  // The distributed run's checkpoint continues as one process, and on three that each read
  // only the rows of their part of the case.
  CaseSpec longer = spec;
  longer.simulation.end_time = 0.08;
  const fs::path again = temp_dir("again");
  fs::copy(three, again, fs::copy_options::recursive);
  Simulation continued(longer);
  continued.restore_state(cb);
  RunOptions opt = quiet_run(three);
  opt.resume = &cb;
  const RunReport r = run_simulation(continued, opt);
  EXPECT_EQ(r.status, "completed");
  EXPECT_NEAR(continued.time(), 0.08, 1e-3);
  EXPECT_EQ(continued.particles().size(), whole.size());
  std::vector<CheckpointData> parts;
  std::size_t read = 0;
  for (int rank = 0; rank < 3; ++rank) {
    parts.push_back(read_checkpoint_file(
        checkpoint_path(again), Simulation::particle_rows(set_up_region(longer, 3, rank))));
    read += parts.back().u32.at("particles.id").size();
  }
  EXPECT_EQ(read, whole.size()) << "the parts read do not make up the checkpoint";
  run_on(longer, 3, again, &parts);
  const CheckpointData c1 = read_checkpoint_file(checkpoint_path(three));
  const CheckpointData c3 = read_checkpoint_file(checkpoint_path(again));
  EXPECT_EQ(c1.real("sim.steps"), c3.real("sim.steps"));
  expect_same_particles(positions_by_id(c1.u32.at("particles.id"), c1.f64.at("particles.pos")),
                        positions_by_id(c3.u32.at("particles.id"), c3.f64.at("particles.pos")), 0.0,
                        "continued on one process and on three");
  expect_csv_close(three / "series.csv", again / "series.csv", kPrinted);
  fs::remove_all(one);
  fs::remove_all(three);
  fs::remove_all(again);
}

TEST(DistributedOutputs, AnOutputThatFailsStopsEveryProcess) {
  // The second snapshot's file cannot be created (a folder holds its name): process 0 stops
  // with the error, and the others with its message instead of waiting for it.
  const fs::path dir = temp_dir("failing");
  fs::create_directories(dir / "snapshots" / "particles_000001.h5");
  const std::vector<std::string> errors = try_run_on(outputs_case(), 3, dir);
  for (int r = 0; r < 3; ++r) {
    EXPECT_NE(errors[r].find("particles_000001.h5"), std::string::npos)
        << "process " << r << ": " << errors[r];
  }
  fs::remove_all(dir);
}

TEST(DistributedOutputs, ABodyInsideAWallIsNamedWhicheverProcessesHoldIt) {
  // The sinking box sunk half its height into the tank's floor, across the middle of the
  // tank: on four processes (slabs along x) it lies outside process 0's slab and across two
  // others. The view must word the overlap as the one-process scene does, counts included.
  const CaseSpec spec = read_case_file(std::string(NETSPH_CASES_DIR) + "/sinking_box2d.toml",
                                       {"simulation.dp=0.02", "body.0.center=[0.5, 0.0, 0.0]"});
  const auto overlap = [](const std::vector<std::string>& warnings) {
    std::vector<std::string> found;
    for (const std::string& w : warnings)
      if (w.find("starts inside") != std::string::npos) found.push_back(w);
    return found;
  };
  const std::vector<std::string> one = overlap(build_scene(spec).warnings);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_NE(one[0].find("body 'box' starts inside wall 'tank'"), std::string::npos) << one[0];
  std::vector<std::string> four;
  std::vector<std::size_t> holding(4, 0);  // the box's overlapping particles each counted
  const std::vector<std::string> errors = test::on_thread_processes(4, [&](ThreadCollectives& c) {
    DistributedStepper stepper(spec, c, nullptr);
    const SolidOverlaps& own = stepper.simulation().local().scene().solid_overlaps;
    for (const auto& [body, by_solid] : own.hits)
      for (const auto& [solid, count] : by_solid) holding[c.rank()] += count;
    if (c.rank() == 0) four = overlap(stepper.view()->scene().warnings);
  });
  for (const std::string& e : errors) EXPECT_EQ(e, "");
  EXPECT_EQ(holding[0], 0u) << "the test wants the box outside process 0's slab";
  EXPECT_GE(std::count_if(holding.begin(), holding.end(), [](std::size_t n) { return n > 0; }), 2)
      << "the test wants the box across two slabs";
  EXPECT_EQ(four, one);
}

}  // namespace
}  // namespace netsph
