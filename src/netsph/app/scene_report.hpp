#pragma once
// Human-readable description of a built scene: particle counts per source, model constants,
// domain and memory. Shared by `run` (logged) and `check` (printed).
#include "netsph/solver/simulation.hpp"

namespace netsph::app {

/// setup_seconds: how long the case took to build (not shown when negative).
void log_scene(const Simulation& sim, double setup_seconds = -1);

}  // namespace netsph::app
