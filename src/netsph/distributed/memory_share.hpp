#pragma once
// The memory check of a distributed run (one process: app/case_loading.cpp). Each process
// holds its slab of the particles and a halo, and the processes on one machine share its
// memory: a run whose share fits one process may still not fit a machine that runs several
// of them. Checked before anything is built, on every process alike, so that no process is
// killed by the kernel's out-of-memory handler while the others wait for it in a collective.
#include <optional>
#include <string>

#include "netsph/distributed/collectives.hpp"
#include "netsph/setup/memory_preflight.hpp"

namespace netsph {

/// A machine of the run as one of its processes sees it.
struct MachineMemory {
  std::optional<double> available;  ///< bytes (MemAvailable); none where unknown or not checked
  int processes = 1;                ///< the run's processes on this machine
};

/// How the most loaded machine of a distributed run stands.
struct MemoryShare {
  double per_process = 0;      ///< bytes: an equal share of the case's particles
  double worst_fraction = 0;   ///< of its available memory, what the most loaded machine needs
  int worst_processes = 0;     ///< that machine's processes
  double worst_available = 0;  ///< bytes
};

/// Collective: each process needs an equal share of `whole.bytes` (the slabs are cut at equal
/// work), each machine the sum of its processes'. The same answer on every process; machines
/// whose memory is unknown count as fitting.
MemoryShare memory_share(const MemoryEstimate& whole, const MachineMemory& here, Collectives& coll);

/// Collective: throws netsph::Error (where: `source`, the case), on every process alike, when
/// the most loaded machine cannot hold its processes' shares; warns (process 0) above 80%.
void check_processes_fit_memory(const std::string& source, const MemoryEstimate& whole,
                                double bytes_per_particle, const MachineMemory& here,
                                Collectives& coll);

}  // namespace netsph
