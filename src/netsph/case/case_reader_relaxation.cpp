// [waves] with relaxation_zone: a relaxation wavemaker instead of a paddle. Over the zone the
// fluid's velocity is relaxed towards the current plus the wave's orbital velocity
// (sph/damping_zone.hpp), fully at x_full and not at all at x_end, where the waves leave it
// travelling from x_full towards x_end. It needs no moving wall, so the water can come in
// through an [[inlet]] on an x face: the waves then ride its current, and their wave number
// solves the Doppler-shifted dispersion relation (omega - k U)^2 = g k tanh kh for the given,
// earth-frame period. Same conventions as case_reader.cpp; docs/case-reference.md documents the
// keys.
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "netsph/case/case_reader_impl.hpp"
#include "netsph/core/error.hpp"
#include "netsph/waves/dispersion.hpp"

namespace netsph::case_detail {

void CaseReader::read_relaxation_wavemaker(const TomlTableReader& r) {
  WaveSpec& w = spec_.waves;
  w.relaxation = true;
  for (const std::string_view key : {"wavemaker", "paddle", "generation", "absorption"}) {
    if (const toml::node* node = r.find(key)) {
      r.fail_value(key, *node,
                   "applies to a paddle, and this [waves] makes its waves with a relaxation "
                   "zone (relaxation_zone): give one or the other");
    }
  }
  if (w.kind != WaveKind::Regular) {
    r.fail_value("relaxation_zone", *r.find("relaxation_zone"),
                 fmt::format("a relaxation zone makes regular waves only, and this is type = "
                             "\"{}\": use a paddle (wavemaker) for an irregular sea",
                             name_of(w.kind)));
  }
  const toml::node& node = *r.find("relaxation_zone");
  const std::vector<double> xs =
      r.to_number_array("relaxation_zone", node, NumberRule::any("m"), 2);
  if (xs.size() != 2 || xs[0] == xs[1]) {
    r.fail_value("relaxation_zone", node,
                 "must be [x_full, x_end], two different x positions (m): the fluid follows the "
                 "wave fully at x_full, and the waves leave the zone at x_end, travelling from "
                 "x_full towards x_end");
  }
  for (const double x : xs) check_x_in_domain(r, "relaxation_zone", x);
  // The zone drives the fluid over its length, and it must be longer than the kernel's reach to
  // drive anything (set-up warns below half a wavelength, as for a damping zone).
  const double support = 2 * spec_.simulation.h_over_dp * spec_.simulation.dp;
  if (std::fabs(xs[1] - xs[0]) < support) {
    r.fail_value("relaxation_zone", node,
                 fmt::format("is {:.4g} m long, shorter than the kernel's reach 2h = {:.3g} m: it "
                             "cannot drive the fluid into a wave; make it one to two "
                             "wavelengths long",
                             std::fabs(xs[1] - xs[0]), support));
  }
  w.relaxation_full = xs[0];
  w.relaxation_end = xs[1];
  w.direction = xs[1] > xs[0] ? 1 : -1;
  w.paddle_x = w.relaxation_end;

  // The water: one fill holds the whole zone; its surface is the still-water level.
  const FillSpec* water = nullptr;
  const double lo = std::min(xs[0], xs[1]), hi = std::max(xs[0], xs[1]);
  for (const FillSpec& f : spec_.fills) {
    if (lo >= f.box.min.x && hi <= f.box.max.x) water = &f;
  }
  if (!water) {
    r.fail_value("relaxation_zone", node,
                 fmt::format("spans x from {} to {} m, and no [[fill]] holds it all: the zone "
                             "drives water that must be there from the start",
                             format_number(lo), format_number(hi)));
  }
  // The zone's rate is full at x_full and on behind it, to the water's end (sph/damping_zone.hpp):
  // x_full belongs at the end of the water (an inlet's or outlet's buffer, or the tank's end
  // wall), or the water behind it is forced into the wave too.
  const double water_end = w.direction > 0 ? water->box.min.x : water->box.max.x;
  const double behind = std::fabs(xs[0] - water_end);
  if (behind > hi - lo) {
    r.fail_value(
        "relaxation_zone", node,
        fmt::format("puts x_full = {} m, {} m from the end of the water at x = {} m (fill at {}), "
                    "farther than the zone is long ({} m): the zone drives the fluid fully from "
                    "x_full back to the water's end, so that water would be forced into the "
                    "wave too. Put x_full at the end of the water the waves come from (an "
                    "inlet's buffer, an end wall) and x_end towards where they go{}",
                    format_number(xs[0]), format_number(behind), format_number(water_end),
                    water->where.str(), format_number(hi - lo),
                    xs[1] < xs[0] ? " (here they would travel in -x)" : ""));
  }
  w.still_level = water->surface_z.value_or(water->box.max.z);
  w.depth = w.still_level - water->box.min.z;
  if (!(w.depth > 0)) {
    r.fail_table(fmt::format(
        "the water of the relaxation zone ({}) has no depth: its surface, "
        "z = {} m, is not above its bottom, z = {} m",
        water->where.str(), format_number(w.still_level), format_number(water->box.min.z)));
  }

  // The current: an inlet's uniform inflow along x (none: still water).
  if (spec_.inlets.size() > 1) {
    r.fail_table(
        fmt::format("a relaxation zone takes its current from one [[inlet]], and this "
                    "case has {}: keep one, on an x face",
                    spec_.inlets.size()));
  }
  if (spec_.inlets.empty()) {
    for (const OpenBoundarySpec& out : spec_.outlets) {
      if (!out.velocity) continue;
      r.fail_table(fmt::format(
          "outlet '{}' ({}) draws water out at {} m/s and no inlet brings it in: the tank "
          "drains while the waves are set up on still water; add an [[inlet]] for a current, "
          "or let the outlet's velocity follow the fluid (remove its velocity)",
          out.name, out.where.str(), format_number(*out.velocity)));
    }
  }
  double u = 0;
  if (!spec_.inlets.empty()) {
    const OpenBoundarySpec& in = spec_.inlets.front();
    if (in.face != kXMin && in.face != kXMax) {
      r.fail_table(
          fmt::format("the waves travel along x, and inlet '{}' ({}) is on the {} "
                      "face: put the inlet on the xmin or xmax face",
                      in.name, in.where.str(), name_of(in.face)));
    }
    if (!in.profile_z.empty()) {
      r.fail_table(
          fmt::format("inlet '{}' ({}) has a velocity profile, and the waves are set "
                      "up on a uniform current: give the inlet a uniform velocity",
                      in.name, in.where.str()));
    }
    u = (in.face == kXMin ? 1.0 : -1.0) * in.velocity.value_or(0.0);
  }
  w.current = w.direction * u;
  read_wave_train(r);

  // The default rate as a damping zone's, from the group velocity relative to the water: the
  // earth-frame one vanishes as an opposing current nears the blocking speed, and the zone
  // must still drive the wave within a fraction of its period there.
  const double length = hi - lo;
  const double g = -spec_.fluid.gravity.z;
  const RegularWave& c = w.train.components.front();
  const double relative = relative_group_velocity(c.k, w.depth, g);
  w.relaxation_rate = r.number("relaxation_rate", NumberRule::positive("1/s"),
                               3 * relative * std::log(100.0) / length);
  check_free_surface(r);
}

}  // namespace netsph::case_detail
