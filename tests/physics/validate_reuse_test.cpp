// `netsph validate --reuse`: a run folder holding a completed summary.json of the same built-in
// case and overrides is kept instead of run again (an interrupted validation picks up where it
// stopped); a different override, or a run that did not complete, is run again.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

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

}  // namespace
}  // namespace netsph
