#include "netsph/run/output_schedule.hpp"

namespace netsph {

double snapshot_interval(const CaseSpec& spec) {
  return spec.output.snapshot_every > 0 ? spec.output.snapshot_every
                                        : spec.simulation.end_time / 50;
}

double series_interval(const CaseSpec& spec) {
  return spec.output.series_every > 0 ? spec.output.series_every : snapshot_interval(spec) / 10;
}

std::array<double, 2> force_window(const CaseSpec& spec) {
  if (spec.output.force_window) return *spec.output.force_window;
  return {0.5 * spec.simulation.end_time, spec.simulation.end_time};
}

}  // namespace netsph
