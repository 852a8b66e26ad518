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
  if (w.paddle != PaddleType::Piston) {
    r.fail_value("absorption", node,
                 "active absorption is built for a piston paddle (its gain is the piston's "
                 "transfer function); absorb the waves at a flap's far end with a [[damping]] "
                 "zone instead");
  }
  const RegularWave* tallest = tallest_component(w.train);
  if (!tallest) r.fail_value("absorption", node, "the waves have no component to absorb");
  // The gauge stands in front of the paddle's travel, clear of its kernel (2h), and at least
  // half a depth out, where the paddle's evanescent modes (decaying as exp(-pi x / h) and
  // faster) have fallen to a fifth, so that the elevation there, less the target, is the
  // wave coming back rather than the paddle's own near field. The travel is bounded from the
  // strokes, not from the run's length, so that the gauge (and with it the run) does not
  // change when a restart extends the run: a regular wave's harmonics at most add up; a sea's
  // motion stays within four standard deviations.
  const PaddleMotion motion = train_paddle_motion(w.paddle, w.train, w.generation);
  double reach = 0, variance = 0;
  for (const PaddleHarmonic& h : motion.harmonics) {
    reach += 0.5 * std::fabs(h.stroke);
    variance += 0.125 * h.stroke * h.stroke;  // (S/2)^2 / 2
  }
  if (w.kind == WaveKind::Jonswap) reach = 4 * std::sqrt(variance);
  const double support = 2 * spec_.simulation.h_over_dp * spec_.simulation.dp;
  const double distance = std::max(0.5 * w.depth, reach + 2 * support);
  WaveAbsorptionSpec& a = w.absorption;
  a.active = true;
  a.gauge_x = w.paddle_x + w.direction * distance;
  double water = 0;
  const FillSpec* at_gauge = nullptr;
  for (const FillSpec& f : spec_.fills) {
    water = std::max(water, f.box.max.x - f.box.min.x);
    if (a.gauge_x >= f.box.min.x && a.gauge_x <= f.box.max.x) at_gauge = &f;
  }
  if (distance > 0.5 * water || !at_gauge) {
    r.fail_value("absorption", node,
                 fmt::format("needs its gauge {:.3g} m in front of the paddle (half the depth, "
                             "or the paddle's travel plus twice the kernel's reach), more than "
                             "half the water's length ({:.3g} m): lengthen the tank",
                             distance, water));
  }
  // Across the water, in its middle (in 3D the tank's width; in 2D y = 0).
  a.gauge_y = 0.5 * (at_gauge->box.min.y + at_gauge->box.max.y);
  check_absorber_gauge_clear(r, node);
  // The gain and the delay at the waves' (or the sea's tallest component's) frequency.
  const double kh = tallest->k * w.depth;
  a.gain = tallest->omega / piston_height_to_stroke(kh);
  a.delay = distance / (tallest->omega / tallest->k);
  a.drift_time = 10 * w.reference_period();
  a.mean_time = 3 * w.reference_period();
}

void CaseReader::check_absorber_gauge_clear(const TomlTableReader& r,
                                            const toml::node& node) const {
  // A wall's x face (its particle layers, and the kernel's reach in front of them) across the
  // gauge's line would make the coverage there read no water, or a wall's: the absorber would
  // act on nothing, or on a wrong level.
  const WaveSpec& w = spec_.waves;
  const WaveAbsorptionSpec& a = w.absorption;
  const double dp = spec_.simulation.dp;
  const double support = 2 * spec_.simulation.h_over_dp * dp;
  for (std::size_t i = 0; i < spec_.walls.size(); ++i) {
    const WallSpec& wall = spec_.walls[i];
    if (i == w.wall) continue;
    if (!is_2d() && (a.gauge_y < wall.box.min.y || a.gauge_y > wall.box.max.y)) continue;
    if (wall.box.min.z >= w.still_level || wall.box.max.z <= w.still_level - w.depth) continue;
    const double thick = wall.layers * dp;
    for (const int side : {0, 1}) {
      if (!wall.faces[static_cast<std::size_t>(side)]) continue;  // kXMin, kXMax
      const double face = side == 0 ? wall.box.min.x : wall.box.max.x;
      const double lo = side == 0 ? face - thick - support : face - support;
      const double hi = side == 0 ? face + support : face + thick + support;
      if (a.gauge_x <= lo || a.gauge_x >= hi) continue;
      r.fail_value("absorption", node,
                   fmt::format("measures the water at x = {:.4g} m (in front of the paddle), "
                               "within reach of wall '{}' ({}) and its {} face at x = {}: the "
                               "gauge reads the wall, not the waves; keep walls at least {:.3g} "
                               "m clear of it",
                               a.gauge_x, wall.name, wall.where.str(), side == 0 ? "xmin" : "xmax",
                               format_number(face), support));
    }
  }
}

}  // namespace netsph::case_detail
