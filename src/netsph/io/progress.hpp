#pragma once
// Progress of a run: on a terminal, one self-overwriting line with a bar, physical time,
// steps/s and ETA; otherwise (a log file, CI) a plain line every `plain_interval_s` seconds.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace netsph {

class ProgressReporter {
 public:
  /// `stream` is usually stderr; the terminal mode is used when it is a TTY, unless `plain`.
  ProgressReporter(double end_time, std::FILE* stream, bool plain = false,
                   double plain_interval_s = 10.0);

  /// Called every step; cheap when nothing is printed (terminal redraws at most 5 per second).
  void update(double time, std::int64_t step, std::size_t particles);

  /// Prints the final state and ends the terminal line.
  void finish(double time, std::int64_t step, std::size_t particles);

  /// The text of the status line (without bar control characters); exposed for tests.
  std::string status_line(double time, std::int64_t step, std::size_t particles,
                          double elapsed_s) const;

 private:
  double end_time_;
  std::FILE* stream_;
  bool tty_;
  double plain_interval_s_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  std::int64_t first_step_ = -1;
  bool printed_any_ = false;
};

}  // namespace netsph
