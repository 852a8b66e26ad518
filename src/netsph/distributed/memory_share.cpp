#include "netsph/distributed/memory_share.hpp"

#include <limits>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "netsph/core/error.hpp"

namespace netsph {

MemoryShare memory_share(const MemoryEstimate& whole, const MachineMemory& here,
                         Collectives& coll) {
  MemoryShare s;
  s.per_process = whole.bytes / coll.size();
  const double fraction = here.available && *here.available > 0
                              ? here.processes * s.per_process / *here.available
                              : 0.0;
  s.worst_fraction = coll.max(fraction);
  // The figures of one machine that has it (the lowest rank's), so that they belong together.
  const int worst_rank =
      coll.min(fraction == s.worst_fraction ? coll.rank() : std::numeric_limits<int>::max());
  const bool mine = coll.rank() == worst_rank;
  s.worst_processes = static_cast<int>(coll.max(mine ? here.processes : 0));
  s.worst_available = coll.max(mine ? here.available.value_or(0.0) : 0.0);
  return s;
}

void check_processes_fit_memory(const std::string& source, const MemoryEstimate& whole,
                                double bytes_per_particle, const MachineMemory& here,
                                Collectives& coll) {
  const MemoryShare s = memory_share(whole, here, coll);
  const auto gb = [](double b) { return b / 1e9; };
  const double machine_need = s.worst_processes * s.per_process;
  if (s.worst_fraction > 1) {
    const std::string machine =
        s.worst_processes == coll.size()
            ? fmt::format("this machine runs all {} and needs", s.worst_processes)
            : fmt::format("the most loaded machine runs {} of them and needs", s.worst_processes);
    throw Error(source,
                fmt::format("the case has about {:.2g} particles (fills and walls); each of the "
                            "{} processes holds about {:.1f} GB ({:.0f} B a particle of its own, "
                            "more with its halo); {} about {:.1f} GB, but it has {:.1f} GB "
                            "available. Run fewer processes on a machine and more machines, or "
                            "use a larger simulation.dp or a smaller domain. "
                            "NETSPH_SKIP_MEMORY_CHECK=1 skips this check",
                            whole.particles, coll.size(), gb(s.per_process), bytes_per_particle,
                            machine, gb(machine_need), gb(s.worst_available)));
  }
  if (s.worst_fraction > 0.8 && coll.rank() == 0) {
    spdlog::warn(
        "the {} processes on the most loaded machine need about {:.1f} GB of memory, "
        "close to the {:.1f} GB available",
        s.worst_processes, gb(machine_need), gb(s.worst_available));
  }
}

}  // namespace netsph
