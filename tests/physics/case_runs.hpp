#pragma once
// Helpers for the physics tests: load a case from cases/ (with overrides) and step it.
#include <string>
#include <vector>

#include "netsph/case/case_reader.hpp"
#include "netsph/solver/simulation.hpp"

namespace netsph::test {

inline CaseSpec load_case(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return read_case_file(std::string(NETSPH_CASES_DIR) + "/" + name, overrides);
}

/// Steps until the simulation time reaches t (the last step may pass it by less than dt).
inline void run_until(Simulation& sim, double t) {
  while (sim.time() < t) sim.step();
}

}  // namespace netsph::test
