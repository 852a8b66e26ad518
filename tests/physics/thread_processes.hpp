#pragma once
// The processes of a distributed run as threads of one test, with in-process collectives
// (distributed/thread_collectives.hpp), so that the decomposition, halo and exchange are
// checked without mpirun.
#include <omp.h>

#include <exception>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "netsph/distributed/thread_collectives.hpp"

namespace netsph::test {

/// Runs body(collectives) on `processes` threads, each a process of the run with one OpenMP
/// thread; returns each process's error ("" where body returned).
inline std::vector<std::string> on_thread_processes(
    int processes, const std::function<void(ThreadCollectives&)>& body) {
  std::vector<std::string> errors(processes);
  ThreadTeam team(processes);
  std::vector<std::thread> threads;
  for (int r = 0; r < processes; ++r) {
    threads.emplace_back([&, r] {
      omp_set_num_threads(1);
      try {
        ThreadCollectives coll(team, r);
        body(coll);
      } catch (const std::exception& e) {
        errors[r] = e.what();
      }
    });
  }
  for (auto& t : threads) t.join();
  return errors;
}

}  // namespace netsph::test
