// The memory check of a distributed run: each process's share of the case, summed over the
// processes of each machine, against that machine's available memory; every process reaches
// the same verdict, so none is left waiting in a collective.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../physics/thread_processes.hpp"
#include "netsph/distributed/memory_share.hpp"

namespace netsph {
namespace {

constexpr double kGB = 1e9;

// A case of 1.5e8 particles at 200 B: 30 GB in all.
MemoryEstimate thirty_gigabytes() {
  return {1.5e8, 30 * kGB};
}

// Runs the check on three thread-processes, rank r seeing machines[r]; returns each error.
std::vector<std::string> check_on_three(const std::vector<MachineMemory>& machines) {
  return test::on_thread_processes(3, [&](ThreadCollectives& coll) {
    check_processes_fit_memory("case.toml", thirty_gigabytes(), 200, machines[coll.rank()], coll);
  });
}

TEST(MemoryShare, ThreeProcessesOnOneMachineEachHoldAThirdOfTheCase) {
  // 10 GB a process, 30 GB for the machine: fits in 40 GB, not in 25 GB, and the whole case
  // (what one process would hold) is not what is compared.
  for (const std::string& e : check_on_three({{40 * kGB, 3}, {40 * kGB, 3}, {40 * kGB, 3}}))
    EXPECT_EQ(e, "");
  const std::vector<std::string> errors =
      check_on_three({{25 * kGB, 3}, {25 * kGB, 3}, {25 * kGB, 3}});
  for (const std::string& e : errors) {
    EXPECT_EQ(e, errors[0]);  // every process stops, with the same message
    EXPECT_NE(e.find("case.toml: "), std::string::npos) << e;
    EXPECT_NE(e.find("each of the 3 processes holds about 10.0 GB"), std::string::npos) << e;
    EXPECT_NE(e.find("this machine runs all 3 and needs about 30.0 GB, but it has 25.0 GB"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("NETSPH_SKIP_MEMORY_CHECK=1"), std::string::npos) << e;
  }
}

TEST(MemoryShare, OneMachineShortStopsEveryProcessAndIsNamed) {
  // Ranks 0 and 1 share a large machine, rank 2 runs alone on one with 8 GB: it cannot hold
  // its 10 GB, and the processes on the large machine stop too.
  const std::vector<std::string> errors =
      check_on_three({{100 * kGB, 2}, {100 * kGB, 2}, {8 * kGB, 1}});
  for (const std::string& e : errors) {
    EXPECT_EQ(e, errors[0]);
    EXPECT_NE(
        e.find("the most loaded machine runs 1 of them and needs about 10.0 GB, but it has 8.0 GB"),
        std::string::npos)
        << e;
  }
  // 12 GB there fits, and two processes on 24 GB (20 GB needed) fit too.
  for (const std::string& e : check_on_three({{24 * kGB, 2}, {24 * kGB, 2}, {12 * kGB, 1}}))
    EXPECT_EQ(e, "");
}

TEST(MemoryShare, TheFiguresAreThoseOfTheMostLoadedMachine) {
  std::vector<MemoryShare> shares(3);
  const std::vector<MachineMemory> machines{{50 * kGB, 2}, {50 * kGB, 2}, {std::nullopt, 1}};
  test::on_thread_processes(3, [&](ThreadCollectives& coll) {
    shares[coll.rank()] = memory_share(thirty_gigabytes(), machines[coll.rank()], coll);
  });
  for (const MemoryShare& s : shares) {
    EXPECT_DOUBLE_EQ(s.per_process, 10 * kGB);
    EXPECT_DOUBLE_EQ(s.worst_fraction, 0.4);  // 20 GB of 50; the unknown machine counts as fitting
    EXPECT_EQ(s.worst_processes, 2);
    EXPECT_DOUBLE_EQ(s.worst_available, 50 * kGB);
  }
  // Nowhere known (NETSPH_SKIP_MEMORY_CHECK=1 on every process): nothing is refused.
  for (const std::string& e :
       check_on_three({{std::nullopt, 3}, {std::nullopt, 3}, {std::nullopt, 3}}))
    EXPECT_EQ(e, "");
}

}  // namespace
}  // namespace netsph
