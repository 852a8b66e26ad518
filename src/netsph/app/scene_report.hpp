#pragma once
// Human-readable description of a built scene: particle counts per source, model constants,
// domain and memory. Shared by `run` (logged) and `check` (printed).
#include "netsph/solver/simulation.hpp"

namespace netsph::app {

void log_scene(const Simulation& sim);

}  // namespace netsph::app
