#include <omp.h>

#include <fstream>
#include <sstream>

#include <spdlog/spdlog.h>

#include "netsph/app/commands.hpp"
#include "netsph/case/builtin_cases.hpp"
#include "netsph/case/case_reader.hpp"
#include "netsph/core/error.hpp"
#if defined(NETSPH_HAVE_CUDA)
#include "netsph/backend/cuda/cuda_runtime_info.hpp"
#endif

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

namespace {
/// Empty when a CUDA device is usable, else why not.
std::string cuda_unavailable() {
#if defined(NETSPH_HAVE_CUDA)
  const cuda::RuntimeInfo info = cuda::runtime_info();
  return info.devices > 0 ? "" : "no usable CUDA device (" + info.error + ")";
#else
  return "this netsph was built without CUDA (no nvcc at configure time)";
#endif
}
}  // namespace

std::string resolve_backend(const std::string& requested) {
  // "auto" stays on the CPU until the CUDA backend's parity tests have passed on a GPU
  // (docs/PERFORMANCE.md, "CUDA"): a default must not be a path no one has seen run.
  if (requested == "cpu" || requested == "auto" || requested == "host-device")
    return requested == "auto" ? "cpu" : requested;
  if (requested == "cuda") {
    if (const std::string why = cuda_unavailable(); !why.empty())
      throw Error("--backend cuda", why + "; use --backend cpu");
    return "cuda";
  }
  throw Error("--backend",
              "unknown backend '" + requested + "'; allowed: auto, cpu, cuda, host-device");
}

StepBackend step_backend(const std::string& resolved) {
  if (resolved == "cuda") return StepBackend::Cuda;
  if (resolved == "host-device") return StepBackend::HostDevice;
  return StepBackend::Cpu;
}

}  // namespace netsph::app
