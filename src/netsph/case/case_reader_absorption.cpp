// [waves] absorption = "active": the paddle absorbs the waves that come back to it
// (waves/active_absorption.hpp). The reader places the gauge that measures them and derives
// the absorber's gain and delay from the wave; the run measures and corrects the paddle's
// velocity every step (solver/paddle_absorption.cpp). Same conventions as case_reader.cpp.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "netsph/case/case_reader_impl.hpp"
#include "netsph/core/error.hpp"
#include "netsph/waves/wavemaker_theory.hpp"

namespace netsph::case_detail {

void CaseReader::read_absorption(const TomlTableReader& r) {
  WaveSpec& w = spec_.waves;
  if (r.choice("absorption", kWaveAbsorptionNames, WaveAbsorption::None) == WaveAbsorption::None)
    return;
  const toml::node& node = *r.find("absorption");
  const RegularWave* tallest = tallest_component(w.train);
  if (!tallest) r.fail_value("absorption", node, "the waves have no component to absorb");
  // The gauge stands in front of the paddle's travel, clear of its kernel (2h), and at least
  // half a depth out, where the paddle's evanescent modes (decaying as exp(-pi x / h) and
  // faster) have fallen to a fifth, so that the elevation there, less the target, is the
  // wave coming back rather than the paddle's own near field.
  const double support = 2 * spec_.simulation.h_over_dp * spec_.simulation.dp;
  const double distance = std::max(0.5 * w.depth, w.max_excursion + 2 * support);
  WaveAbsorptionSpec& a = w.absorption;
  a.active = true;
  a.gauge_x = w.paddle_x + w.direction * distance;
  double water = 0;
  for (const FillSpec& f : spec_.fills) water = std::max(water, f.box.max.x - f.box.min.x);
  if (distance > 0.5 * water) {
    r.fail_value("absorption", node,
                 fmt::format("needs its gauge {:.3g} m in front of the paddle (half the depth, "
                             "or the paddle's travel plus twice the kernel's reach), more than "
                             "half the water's length ({:.3g} m): lengthen the tank",
                             distance, water));
  }
  // The gain and the delay at the waves' (or the sea's tallest component's) frequency.
  const double kh = tallest->k * w.depth;
  a.gain = tallest->omega / piston_height_to_stroke(kh);
  a.delay = distance / (tallest->omega / tallest->k);
  a.drift_time = 10 * w.reference_period();
}

}  // namespace netsph::case_detail
