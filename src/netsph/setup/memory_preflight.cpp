#include "netsph/setup/memory_preflight.hpp"

#include <fstream>
#include <sstream>
#include <string>

#include "netsph/geometry/box_lattice.hpp"

namespace netsph {

MemoryEstimate estimate_case_memory(const CaseSpec& spec, double bytes_per_particle) {
  const double dp = spec.simulation.dp;
  const int dims = spec.simulation.dimensions;
  MemoryEstimate e;
  for (const FillSpec& f : spec.fills) {
    const auto n = lattice_counts({f.box.min, f.box.max, dims}, dp);
    e.particles += static_cast<double>(n[0]) * n[1] * n[2];
  }
  // Each chosen face: its lattice cross-section times the layers (edges and corners left out:
  // the estimate errs low, so that it refuses only what cannot fit).
  for (const WallSpec& w : spec.walls) {
    const auto n = lattice_counts({w.box.min, w.box.max, dims}, dp);
    for (int face = 0; face < 6; ++face) {
      if (!w.faces[static_cast<std::size_t>(face)] || (dims == 2 && face / 2 == 1)) continue;
      const int axis = face / 2;
      double cross = 1;
      for (int a = 0; a < 3; ++a)
        if (a != axis) cross *= n[static_cast<std::size_t>(a)];
      e.particles += cross * w.layers;
    }
  }
  e.bytes = e.particles * bytes_per_particle;
  return e;
}

std::optional<double> available_memory() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream fields(line.substr(13));
    double kb = 0;
    if (fields >> kb) return kb * 1024;
  }
  return std::nullopt;
}

}  // namespace netsph
