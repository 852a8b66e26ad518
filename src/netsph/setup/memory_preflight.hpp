#pragma once
// A case's particle count and memory, estimated from its boxes before anything is built: a
// case too large for the machine is refused with a message naming its size and the memory
// available, instead of being killed by the kernel's out-of-memory handler minutes into its
// set-up (the paper's full-resolution net, 1.35e8 particles, needs about 30 GB on the CPU).
#include <optional>

#include "netsph/case/case_spec.hpp"

namespace netsph {

struct MemoryEstimate {
  double particles = 0;  ///< fills (with their buffers) and wall layers; bodies are few
  double bytes = 0;      ///< at bytes_per_particle
};

/// The particles of the fills and walls; `bytes_per_particle` as the backend's run reports it.
MemoryEstimate estimate_case_memory(const CaseSpec& spec, double bytes_per_particle);

/// MemAvailable of /proc/meminfo, bytes (none where it cannot be read).
std::optional<double> available_memory();

}  // namespace netsph
