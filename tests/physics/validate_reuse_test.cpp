// `netsph validate --reuse`: a run folder holding a completed summary.json of the same built-in
// case and overrides is kept instead of run again (an interrupted validation picks up where it
// stopped); a different override, or a run that did not complete, is run again.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "netsph/case/builtin_cases.hpp"
#include "netsph/case/case_reader.hpp"
#include "netsph/run/runner.hpp"
#include "netsph/validation/validation.hpp"

namespace netsph {
namespace {

nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

void write_json(const std::filesystem::path& file, const nlohmann::json& j) {
  std::ofstream(file) << j.dump(2);
}

TEST(ValidateReuse, KeepsACompletedRunOfTheSameCaseAndOverrides) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "netsph_reuse_test";
  std::filesystem::remove_all(dir);
  ValidationContext ctx{dir, false, true};
  const std::vector<std::string> short_run = {"simulation.end_time=0.004",
                                              "output.snapshot_every=0.004"};
  const nlohmann::json first = ctx.run_case("hydrostatic2d", short_run, "run");
  ASSERT_EQ(first.at("status"), "completed");
  EXPECT_EQ(first.at("case").at("overrides").size(), 2u);

  // Mark the summary: a reused run returns the mark, a new run overwrites it.
  nlohmann::json marked = read_json(dir / "run" / "summary.json");
  marked["reuse_mark"] = 1;
  write_json(dir / "run" / "summary.json", marked);
  EXPECT_TRUE(ctx.run_case("hydrostatic2d", short_run, "run").contains("reuse_mark"));

  // Another override: run again.
  std::vector<std::string> other = short_run;
  other.push_back("simulation.cfl=0.1");
  EXPECT_FALSE(ctx.run_case("hydrostatic2d", other, "run").contains("reuse_mark"));

  // A run that did not complete: run again.
  nlohmann::json failed = read_json(dir / "run" / "summary.json");
  failed["status"] = "unstable";
  failed["reuse_mark"] = 1;
  write_json(dir / "run" / "summary.json", failed);
  const nlohmann::json again = ctx.run_case("hydrostatic2d", other, "run");
  EXPECT_FALSE(again.contains("reuse_mark"));
  EXPECT_EQ(again.at("status"), "completed");

  // Without --reuse nothing is kept.
  write_json(dir / "run" / "summary.json", marked);
  const ValidationContext fresh{dir, false, false};
  EXPECT_FALSE(fresh.run_case("hydrostatic2d", short_run, "run").contains("reuse_mark"));
  std::filesystem::remove_all(dir);
}

// A validation run that stopped part-way (here at a step limit; killed or interrupted runs leave
// the same checkpoint) is continued from its checkpoint with --reuse and ends where the
// uninterrupted run ends; a checkpoint of other overrides, or without --reuse, is not used.
TEST(ValidateReuse, ContinuesAStoppedRunFromItsCheckpoint) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "netsph_resume_test";
  std::filesystem::remove_all(dir);
  const std::vector<std::string> overrides = {"simulation.end_time=0.006",
                                              "output.snapshot_every=0.003"};
  const std::string name = "hydrostatic2d";
  const ValidationContext ctx{dir, false, true};
  const nlohmann::json whole = ctx.run_case(name, overrides, "whole");
  ASSERT_EQ(whole.at("status"), "completed");
  EXPECT_FALSE(whole.at("time").contains("restarted_from_s"));

  // The same case, run as validate runs it, stopped after a third of its steps.
  const std::int64_t steps = whole.at("time").at("steps").get<std::int64_t>();
  ASSERT_GT(steps, 6);
  const auto stopped_run = [&](const std::vector<std::string>& o) -> void {
    std::filesystem::remove_all(dir / "split");
    Simulation sim(read_case_string(builtin_case_text(name), "builtin:" + name, o));
    RunOptions opt;
    opt.out_dir = dir / "split";
    opt.progress = false;
    opt.max_steps = steps / 3;
    opt.case_record = case_record(std::string(builtin_case_text(name)), "builtin:" + name, o);
    const RunReport r = run_simulation(sim, opt);
    ASSERT_EQ(r.status, "step limit");
  };
  stopped_run(overrides);
  std::filesystem::remove(dir / "split" / "summary.json");  // as a killed run leaves it
  const nlohmann::json continued = ctx.run_case(name, overrides, "split");
  ASSERT_EQ(continued.at("status"), "completed");
  ASSERT_TRUE(continued.at("time").contains("restarted_from_s"));
  EXPECT_GT(continued.at("time").at("restarted_from_s").get<double>(), 0.0);
  EXPECT_EQ(continued.at("time").at("steps"), whole.at("time").at("steps"));
  EXPECT_EQ(continued.at("final_state").at("kinetic_energy_J"),
            whole.at("final_state").at("kinetic_energy_J"));

  // Stopped with other overrides: the checkpoint is not this run's, so it runs from the start.
  std::vector<std::string> other = overrides;
  other.push_back("simulation.cfl=0.1");
  stopped_run(other);  // leaves summary.json with status "step limit"
  EXPECT_FALSE(ctx.run_case(name, overrides, "split").at("time").contains("restarted_from_s"));

  // Without --reuse a stopped run is run again from the start.
  stopped_run(overrides);
  const ValidationContext fresh{dir, false, false};
  EXPECT_FALSE(fresh.run_case(name, overrides, "split").at("time").contains("restarted_from_s"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace netsph
