#include <omp.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "netsph/app/commands.hpp"
#include "netsph/case/builtin_cases.hpp"
#include "netsph/case/case_reader.hpp"
#include "netsph/core/error.hpp"
#include "netsph/distributed/memory_share.hpp"
#include "netsph/setup/memory_preflight.hpp"
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
  return {read_file_text(choice.path), choice.path};
}

int apply_threads(int threads) {
  if (threads < 0) throw Error("--threads", "must be >= 0 (0: all cores)");
  // More threads than cores only makes OpenMP's threads wait for each other at every barrier,
  // and far more than the system allows ends in a crash inside the OpenMP runtime before any
  // message of ours: at most 8 threads per core this process may use.
  const int cores = omp_get_num_procs();
  const int most = 8 * (cores > 0 ? cores : 1);
  if (threads > most) {
    throw Error("--threads", fmt::format("{} is more than 8 per core: this machine gives the run "
                                         "{} core{}, so at most {} (0: all cores)",
                                         threads, cores, cores == 1 ? "" : "s", most));
  }
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

std::string resolve_backend(const std::string& requested, bool distributed) {
  // "auto": the CUDA backend where a device is usable (its parity tests passed on an H200 on
  // 2026-12-04, docs/PERFORMANCE.md, "CUDA"), except in a distributed run (one GPU per process
  // is not supported yet); otherwise the CPU.
  if (requested == "auto") return !distributed && cuda_unavailable().empty() ? "cuda" : "cpu";
  if (requested == "cpu" || requested == "host-device") return requested;
  if (requested == "cuda") {
    if (const std::string why = cuda_unavailable(); !why.empty())
      throw Error("--backend cuda", why + "; use --backend cpu");
    return "cuda";
  }
  throw Error("--backend",
              "unknown backend '" + requested + "'; allowed: auto, cpu, cuda, host-device");
}

void check_case_fits_memory(const CaseSpec& spec, const std::string& backend, Collectives* coll) {
  const char* skip = std::getenv("NETSPH_SKIP_MEMORY_CHECK");
  const std::optional<double> available =
      skip && skip[0] == '1' ? std::nullopt : available_memory();
  // What a run holds per particle on the host: about 215-230 B on the CPU backend (measured:
  // docs/PERFORMANCE.md, "Memory"; a process of a distributed run 260-300 B per particle of
  // its own, with its halo); a device run keeps the particle state (61 B) and what the
  // outputs copy back. Taken low, so that only a case that cannot fit is refused.
  const double per_particle = backend == "cpu" ? 200.0 : 80.0;
  const MemoryEstimate e = estimate_case_memory(spec, per_particle);
  if (coll) {
    // Every process takes part, also one told to skip the check (the others would wait).
    check_processes_fit_memory(spec.source, e, per_particle,
                               {available, coll->processes_on_this_machine()}, *coll);
    return;
  }
  if (!available) return;
  const auto gb = [](double b) { return b / 1e9; };
  if (e.bytes > *available) {
    throw Error(spec.source,
                fmt::format("the case has about {:.2g} particles (fills and walls) and needs about "
                            "{:.1f} GB of memory on the {} backend ({:.0f} B a particle), but "
                            "this machine has {:.1f} GB available. Use a larger simulation.dp "
                            "(memory falls as dp^-{}), a smaller domain, the case's reduced "
                            "version, or several machines (mpirun -n N netsph run: each process "
                            "holds its slab of the case and a halo, about 300 B per particle of "
                            "its own). NETSPH_SKIP_MEMORY_CHECK=1 skips this check",
                            e.particles, gb(e.bytes), backend, per_particle, gb(*available),
                            spec.simulation.dimensions));
  }
  if (e.bytes > 0.8 * *available) {
    spdlog::warn(
        "the case needs about {:.1f} GB of memory ({:.2g} particles), close to the "
        "{:.1f} GB available",
        gb(e.bytes), e.particles, gb(*available));
  }
}

StepBackend step_backend(const std::string& resolved) {
  if (resolved == "cuda") return StepBackend::Cuda;
  if (resolved == "host-device") return StepBackend::HostDevice;
  return StepBackend::Cpu;
}

}  // namespace netsph::app
