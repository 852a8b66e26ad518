#include "netsph/app/plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "netsph/core/error.hpp"

namespace netsph::app {

extern const char* const kPlotScript;  // plot_script_data.cpp (generated)

namespace {

constexpr const char* kPython = "/usr/bin/python3";  // Debian's, which sees python3-matplotlib

/// Single quotes for a POSIX shell.
std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// --times: comma-separated times in s, each finite and >= 0; checked here so that a typo is
/// one line naming the option, not a Python traceback in plots.log.
void check_shape_times(const std::string& times) {
  std::size_t start = 0;
  while (start <= times.size()) {
    const std::size_t comma = std::min(times.find(',', start), times.size());
    const std::string item = times.substr(start, comma - start);
    char* end = nullptr;
    const double t = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(t) || t < 0) {
      throw Error("--times", fmt::format("'{}' is not a time: give times in s, >= 0, separated "
                                         "by commas (e.g. 0.5,1,2.5)",
                                         item));
    }
    start = comma + 1;
  }
}

}  // namespace

bool make_plots(const std::filesystem::path& run_dir, const std::string& shape_times) {
  if (!shape_times.empty()) check_shape_times(shape_times);
  const std::string probe =
      fmt::format("{} -c 'import matplotlib, numpy' > /dev/null 2>&1", kPython);
  if (std::system(probe.c_str()) != 0) {
    spdlog::warn(
        "plots skipped: {} cannot import matplotlib and numpy (install "
        "python3-matplotlib and python3-numpy, then run `netsph plot {}`)",
        kPython, run_dir.string());
    return false;
  }
  const std::string command =
      fmt::format("{} - {} {} > {} 2>&1", kPython, shell_quote(run_dir.string()),
                  shell_quote(shape_times), shell_quote((run_dir / "plots.log").string()));
  std::FILE* pipe = popen(command.c_str(), "w");
  if (!pipe) {
    spdlog::warn("plots skipped: could not start {}", kPython);
    return false;
  }
  std::fputs(kPlotScript, pipe);
  const int status = pclose(pipe);
  if (status != 0) {
    spdlog::warn("plots failed (see {}); the run's results are unaffected",
                 (run_dir / "plots.log").string());
    return false;
  }
  spdlog::info("plots: {}", (run_dir / "plots").string());
  return true;
}

}  // namespace netsph::app
