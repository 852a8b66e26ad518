#pragma once
// The results a run prints at its end, from its summary.json: per force group the mean force
// and Cd over the force window; per net the deflection and largest tension; per probe the mean
// velocity and, with a uniform inlet, the velocity reduction behind the net.
#include <nlohmann/json.hpp>

namespace netsph::app {

void log_run_results(const nlohmann::json& summary);

}  // namespace netsph::app
