#include "netsph/waves/wave_record.hpp"

#include <algorithm>
#include <functional>

namespace netsph {

WaveRecordSummary zero_upcrossing_waves(std::span<const double> times, std::span<const double> eta,
                                        double t_from) {
  WaveRecordSummary s;
  const std::size_t n = std::min(times.size(), eta.size());
  std::size_t first = 0;
  while (first < n && times[first] < t_from) ++first;
  if (n - first < 3) return s;
  double sum = 0;
  for (std::size_t i = first; i < n; ++i) sum += eta[i];
  s.mean_level = sum / static_cast<double>(n - first);
  const auto d = [&](std::size_t i) { return eta[i] - s.mean_level; };
  // Up-crossings: d goes from < 0 to >= 0 between samples i - 1 and i; the time by linear
  // interpolation.
  std::vector<std::size_t> at;
  std::vector<double> when;
  for (std::size_t i = first + 1; i < n; ++i) {
    if (d(i - 1) < 0 && d(i) >= 0) {
      at.push_back(i);
      when.push_back(times[i - 1] + (times[i] - times[i - 1]) * (-d(i - 1)) / (d(i) - d(i - 1)));
    }
  }
  for (std::size_t w = 0; w + 1 < at.size(); ++w) {
    RecordWave rw;
    rw.start = when[w];
    rw.period = when[w + 1] - when[w];
    for (std::size_t i = at[w]; i < at[w + 1]; ++i) {
      rw.crest = std::max(rw.crest, d(i));
      rw.trough = std::max(rw.trough, -d(i));
    }
    s.waves.push_back(rw);
  }
  if (s.waves.empty()) return s;
  const auto count = static_cast<double>(s.waves.size());
  for (const RecordWave& w : s.waves) {
    s.mean_height += w.height() / count;
    s.mean_period += w.period / count;
    s.mean_crest += w.crest / count;
    s.mean_trough += w.trough / count;
  }
  std::vector<double> heights;
  for (const RecordWave& w : s.waves) heights.push_back(w.height());
  std::sort(heights.begin(), heights.end(), std::greater<>());
  const std::size_t third = std::max<std::size_t>(1, heights.size() / 3);
  for (std::size_t i = 0; i < third; ++i) s.h_third += heights[i] / static_cast<double>(third);
  return s;
}

}  // namespace netsph
