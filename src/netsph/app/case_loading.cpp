#include <omp.h>

#include <fstream>
#include <sstream>

#include <spdlog/spdlog.h>

#include "netsph/app/commands.hpp"
#include "netsph/case/builtin_cases.hpp"
#include "netsph/case/case_reader.hpp"
#include "netsph/core/error.hpp"

namespace netsph::app {

CaseSpec load_case(const CaseChoice& choice) {
  std::string_view builtin;
  std::string name;
  if (choice.path.empty()) {
    name = std::string(kDefaultCase);
  } else if (choice.path.rfind("builtin:", 0) == 0) {
    name = choice.path.substr(8);
  } else {
    return read_case_file(choice.path, choice.overrides);
  }
  builtin = builtin_case_text(name);
  if (builtin.empty()) {
    std::string names;
    for (const auto& c : builtin_cases())
      names += (names.empty() ? "" : ", ") + std::string(c.name);
    throw Error("builtin:" + name, "no such built-in case; built-in cases: " + names);
  }
  return read_case_string(builtin, "builtin:" + name, choice.overrides);
}

std::pair<std::string, std::string> case_text(const CaseChoice& choice) {
  if (choice.path.empty() || choice.path.rfind("builtin:", 0) == 0) {
    const std::string name =
        choice.path.empty() ? std::string(kDefaultCase) : choice.path.substr(8);
    return {std::string(builtin_case_text(name)), "builtin:" + name};
  }
  std::ifstream in(choice.path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return {text.str(), choice.path};
}

int apply_threads(int threads) {
  if (threads < 0) throw Error("--threads", "must be >= 0 (0: all cores)");
  if (threads > 0) omp_set_num_threads(threads);
  return omp_get_max_threads();
}

std::string resolve_backend(const std::string& requested) {
  if (requested == "cpu" || requested == "auto") return "cpu";
  if (requested == "cuda") {
    throw Error("--backend cuda",
                "the CUDA backend is not implemented yet (issue: CUDA backend); use --backend cpu");
  }
  throw Error("--backend", "unknown backend '" + requested + "'; allowed: auto, cpu, cuda");
}

}  // namespace netsph::app
