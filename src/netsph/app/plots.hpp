#pragma once
// PNG plots of a run folder (tools/plot_results.py, compiled in and piped to Debian's Python).
// A missing Python or matplotlib is a warning, never a failure: the run's results stand
// without their pictures.
#include <filesystem>
#include <string>

namespace netsph::app {

/// Writes DIR/plots/*.png; returns false (after a warning saying why and what to install)
/// when they could not be made.
/// `shape_times`: the moments (s) at which to draw the nets' shapes, "t1,t2,..." (empty: five
/// moments spread over the run).
bool make_plots(const std::filesystem::path& run_dir, const std::string& shape_times = "");

}  // namespace netsph::app
