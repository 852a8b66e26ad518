#pragma once
// PNG plots of a run folder (tools/plot_results.py, compiled in and piped to Debian's Python).
// A missing Python or matplotlib is a warning, never a failure: the run's results stand
// without their pictures.
#include <filesystem>

namespace netsph::app {

/// Writes DIR/plots/*.png; returns false (after a warning saying why and what to install)
/// when they could not be made.
bool make_plots(const std::filesystem::path& run_dir);

}  // namespace netsph::app
