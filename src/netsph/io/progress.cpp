#include "netsph/io/progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace netsph {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kBarWidth = 30;
constexpr auto kRedrawInterval = std::chrono::milliseconds(200);  // at most 5 redraws/s

double seconds_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// Enough decimals to show the end time with about 4 significant digits: "2.000" for 2 s,
// "0.05000" for 50 ms, so that a short run still shows its time advancing.
int time_decimals(double end_time) {
  if (!(end_time > 0) || !std::isfinite(end_time)) return 3;
  const int magnitude = static_cast<int>(std::floor(std::log10(end_time)));
  return std::clamp(3 - magnitude, 3, 9);
}

// Fewer digits for fast runs ("1520"), some for slow ones ("0.25"), never "0".
std::string format_rate(double steps_per_s) {
  if (steps_per_s >= 100) return fmt::format("{:.0f}", steps_per_s);
  return fmt::format("{:.3g}", steps_per_s);
}

// h:mm:ss, hours unbounded; "--" for an unknown or absurd (> ~3 years) estimate.
std::string format_eta(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0 || seconds > 1e8) return "--";
  const auto total = static_cast<long long>(std::llround(seconds));
  return fmt::format("{}:{:02d}:{:02d}", total / 3600, (total / 60) % 60, total % 60);
}

std::string bar(double fraction) {
  const double f = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
  const auto filled = static_cast<std::size_t>(std::lround(f * kBarWidth));
  // Appended piecewise: GCC 12 gives a false -Wrestrict for "[" + std::string(...) chains.
  std::string text;
  text.reserve(kBarWidth + 2);
  text += '[';
  text.append(filled, '#');
  text.append(kBarWidth - filled, '-');
  text += ']';
  return text;
}

// Columns of the terminal behind `stream`; 80 when it cannot be asked.
std::size_t terminal_width(std::FILE* stream) {
  winsize ws{};
  if (::ioctl(fileno(stream), TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) return ws.ws_col;
  return 80;
}

// "\r" + the line, cut to the terminal width and padded with spaces to it: a line that
// wrapped could not be overwritten by "\r", and the padding erases a longer previous line.
// One column is left free because some terminals wrap when the last column is written.
std::string terminal_line(const std::string& bar_text, const std::string& status,
                          std::size_t width) {
  const std::size_t room = width > 1 ? width - 1 : width;
  std::string line = bar_text + " " + status;
  if (line.size() > room) line = status;  // a narrow terminal keeps the numbers, not the bar
  if (line.size() > room) line.resize(room);
  line.append(room - line.size(), ' ');
  return "\r" + line;
}

}  // namespace

ProgressReporter::ProgressReporter(double end_time, std::FILE* stream, bool plain,
                                   double plain_interval_s)
    : end_time_(end_time),
      stream_(stream),
      tty_(!plain && stream != nullptr && ::isatty(fileno(stream)) == 1),
      plain_interval_s_(plain_interval_s),
      start_(Clock::now()),
      last_print_(start_) {}

void ProgressReporter::update(double time, std::int64_t step, std::size_t particles) {
  if (stream_ == nullptr) return;
  const Clock::time_point now = Clock::now();
  if (first_step_ < 0) {
    // Rates are measured from the first update, so that set-up time does not count.
    first_step_ = step;
    start_ = now;
  }
  const bool due = tty_ ? now - last_print_ >= kRedrawInterval
                        : seconds_between(last_print_, now) >= plain_interval_s_;
  if (printed_any_ && !due) return;

  const std::string status = status_line(time, step, particles, seconds_between(start_, now));
  if (tty_) {
    const std::string line =
        terminal_line(bar(end_time_ > 0 ? time / end_time_ : 1.0), status, terminal_width(stream_));
    std::fputs(line.c_str(), stream_);
  } else {
    std::fprintf(stream_, "%s\n", status.c_str());
  }
  std::fflush(stream_);
  last_print_ = now;
  printed_any_ = true;
}

void ProgressReporter::finish(double time, std::int64_t step, std::size_t particles) {
  if (stream_ == nullptr) return;
  const Clock::time_point now = Clock::now();
  if (first_step_ < 0) {
    first_step_ = step;
    start_ = now;
  }
  const std::string status = status_line(time, step, particles, seconds_between(start_, now));
  if (tty_) {
    const std::string line =
        terminal_line(bar(end_time_ > 0 ? time / end_time_ : 1.0), status, terminal_width(stream_));
    std::fprintf(stream_, "%s\n", line.c_str());
  } else {
    std::fprintf(stream_, "%s\n", status.c_str());
  }
  std::fflush(stream_);
  last_print_ = now;
  printed_any_ = true;
}

std::string ProgressReporter::status_line(double time, std::int64_t step, std::size_t particles,
                                          double elapsed_s) const {
  const int decimals = time_decimals(end_time_);
  const double percent = end_time_ > 0 ? 100.0 * time / end_time_ : 100.0;
  std::string line = fmt::format("t = {:.{}f} / {:.{}f} s ({:.1f}%)  step {}", time, decimals,
                                 end_time_, decimals, percent, step);

  // Before the first update() (tests, or finish() without updates) steps count from 0.
  const std::int64_t steps_done = step - std::max<std::int64_t>(first_step_, 0);
  if (elapsed_s > 0 && steps_done > 0) {
    const double steps_per_s = static_cast<double>(steps_done) / elapsed_s;
    line += fmt::format("  {} steps/s  {:.2e} particle-steps/s", format_rate(steps_per_s),
                        steps_per_s * static_cast<double>(particles));
  } else {
    line += "  -- steps/s  -- particle-steps/s";
  }

  // The time step changes during a run, so the ETA follows physical time, not steps. The
  // run is assumed to start at t = 0 (the reporter does not record the first update's time).
  double eta = -1;
  if (time >= end_time_) {
    eta = 0;
  } else if (elapsed_s > 0 && time > 0) {
    eta = (end_time_ - time) / (time / elapsed_s);
  }
  line += "  ETA " + format_eta(eta);
  return line;
}

}  // namespace netsph
