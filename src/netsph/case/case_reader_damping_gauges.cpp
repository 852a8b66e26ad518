// The [[damping]] and [[gauge]] tables: the zones that absorb waves (a numerical beach) and the
// gauges that measure the surface. Same conventions as case_reader.cpp; docs/case-reference.md
// documents every key.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "netsph/case/case_reader_impl.hpp"
#include "netsph/core/error.hpp"

namespace netsph::case_detail {
namespace {

/// The highest top (surface_z, else the box top) and the lowest bottom of the fills.
struct FillLevels {
  double top = -std::numeric_limits<double>::infinity();
  double bottom = std::numeric_limits<double>::infinity();
};
FillLevels fill_levels(const CaseSpec& spec) {
  FillLevels l;
  for (const FillSpec& f : spec.fills) {
    l.top = std::max(l.top, f.surface_z.value_or(f.box.max.z));
    l.bottom = std::min(l.bottom, f.box.min.z);
  }
  return l;
}

}  // namespace

// ---- [[damping]] ---------------------------------------------------------------------------

void CaseReader::read_damping() {
  const std::vector<const toml::table*> tables = find_array_of_tables("damping");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const int number = static_cast<int>(i) + 1;
    const std::string label = fmt::format("damping[{}]", number);
    TomlTableReader r(*tables[i], label, label, keys_of("damping"), source_, home_hint);
    DampingSpec z;
    z.where = r.location();
    if (spec_.fills.empty())
      r.fail_table("a damping zone acts on the SPH fluid, and this case has none");
    z.name = r.string("name", fmt::format("damping{}", number));
    z.from = r.required_number("from", NumberRule::any("m"), "x where the damping starts, m");
    z.to = r.required_number("to", NumberRule::any("m"),
                             "x where the damping reaches its full rate (and beyond), m");
    if (z.to == z.from) {
      r.fail_value("to", *r.find("to"),
                   "must differ from `from`: the damping grows from `from` to `to` (to > from "
                   "for waves travelling in +x)");
    }
    check_x_in_domain(r, "from", z.from);
    check_x_in_domain(r, "to", z.to);
    for (const DampingSpec& other : spec_.damping) {
      if (other.name != z.name) continue;
      const toml::node* name = r.find("name");
      const std::string message =
          fmt::format("damping zone name \"{}\" is used twice: by {} and {}; names must be unique",
                      z.name, other.where.str(), label);
      if (name) r.fail_value("name", *name, message);
      r.fail_table(message);
    }
    z.velocity = read_in_plane_vector(r, "velocity", NumberRule::any("m/s"), {});
    const double length = std::fabs(z.to - z.from);
    if (const auto rate = r.optional_number("rate", NumberRule::positive("1/s"))) {
      z.rate = *rate;
    } else if (spec_.waves.given) {
      z.rate = default_damping_rate(spec_.waves, length, -spec_.fluid.gravity.z);
    } else {
      r.fail_table(
          fmt::format("{} needs its rate (1/s): without [waves] there is no wave to "
                      "derive it from",
                      label));
    }
    check_damping_clear_of_paddle(r, z);
    spec_.damping.push_back(z);
  }
}

void CaseReader::check_damping_clear_of_paddle(const TomlTableReader& r,
                                               const DampingSpec& zone) const {
  const WaveSpec& w = spec_.waves;
  if (!w.given) return;
  // Where the zone damps: s = (x - from) / (to - from) > 0. It must not reach where the wave
  // is made: the paddle's face over its travel, or the relaxation zone (forced fully from
  // x_full back to the water's end).
  const double e = w.max_excursion;
  const std::array<double, 2> made = w.relaxation ? std::array{w.relaxation_full, w.relaxation_end}
                                                  : std::array{w.paddle_x - e, w.paddle_x + e};
  for (const double x : made) {
    if ((x - zone.from) / (zone.to - zone.from) <= 0) continue;
    const std::string maker =
        w.relaxation ? fmt::format(
                           "the relaxation zone that makes the waves (x from {} to {} m, [waves] "
                           "relaxation_zone)",
                           format_number(w.relaxation_full), format_number(w.relaxation_end))
                     : fmt::format("the paddle at x = {} m", format_number(w.paddle_x));
    const std::string start =
        w.relaxation ? fmt::format("start past x = {} m", format_number(w.relaxation_end))
                     : std::string("start in front of it");
    r.fail_value("to", *r.find("to"),
                 fmt::format("the zone damps from x = {} m towards x = {} m and on beyond it, "
                             "which takes in {}: it would damp the wave where it is made. The "
                             "zone must grow away from {} (to {} from for waves travelling in "
                             "{}x) and {}",
                             format_number(zone.from), format_number(zone.to), maker,
                             w.relaxation ? "it" : "the paddle", w.direction > 0 ? ">" : "<",
                             w.direction > 0 ? "+" : "-", start));
  }
}

double default_damping_rate(const WaveSpec& w, double length, double g) {
  // The zone relaxes the velocity at rate beta(x) = rate s^2 (s from 0 to 1 across it). A wave
  // loses energy at rate beta (its kinetic half at 2 beta), so its amplitude decays as
  // exp(-integral beta / (2 c_g) dx): over the zone and back, after reflection at its end,
  // exp(-rate L / (3 c_g)). The rate that brings that round trip to 1%: 3 c_g ln(100) / L.
  const double cg = w.train.front_speed > 0 ? w.train.front_speed : std::sqrt(g * w.depth);
  return 3 * cg * std::log(100.0) / length;
}

// ---- [[gauge]] -----------------------------------------------------------------------------

void CaseReader::read_gauges() {
  const std::vector<const toml::table*> tables = find_array_of_tables("gauge");
  const FillLevels fills = fill_levels(spec_);
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const int number = static_cast<int>(i) + 1;
    const std::string label = fmt::format("gauge[{}]", number);
    TomlTableReader r(*tables[i], label, label, keys_of("gauge"), source_, home_hint);
    GaugeSpec gauge;
    gauge.where = r.location();
    if (spec_.fills.empty())
      r.fail_table("a wave gauge measures the SPH fluid, and this case has none");
    gauge.name = r.string("name", fmt::format("gauge{}", number));
    if (!plain_file_name(gauge.name)) {
      r.fail_value("name", *r.find("name"),
                   "must be a plain name: letters, digits, '_', '-' and '.' (it heads a column "
                   "of gauges.csv)");
    }
    // gauges.csv's columns: time, then <name> and <name>_target per gauge.
    if (const toml::node* name = r.find("name");
        name && (gauge.name == "time" || gauge.name.ends_with("_target"))) {
      r.fail_value("name", *name,
                   "is a name gauges.csv gives its own columns (\"time\", \"<gauge>_target\"); "
                   "choose another");
    }
    for (const GaugeSpec& other : spec_.gauges) {
      if (other.name != gauge.name) continue;
      const std::string message = fmt::format(
          "gauge name \"{}\" is used twice: by {} and {}{}; gauge names must be "
          "unique (each heads a column of gauges.csv)",
          gauge.name, other.where.str(), label, r.has("name") ? "" : " (its default)");
      if (const toml::node* name = r.find("name")) r.fail_value("name", *name, message);
      r.fail_table(message);
    }
    gauge.x = r.required_number("x", NumberRule::any("m"), "the gauge's x, m");
    if (is_2d()) {
      if (const toml::node* y = r.find("y"))
        r.fail_value("y", *y, fmt::format("is not allowed {}", kNotIn2D));
    } else {
      gauge.y = r.required_number("y", NumberRule::any("m"), "the gauge's y, m");
    }
    check_gauge_position(r, gauge);
    gauge.z_min = fills.bottom;
    const double above =
        spec_.waves.given ? 2 * spec_.waves.reference_height() : 0.5 * (fills.top - fills.bottom);
    gauge.z_max = spec_.domain.given ? spec_.domain.max.z : fills.top + above;
    spec_.gauges.push_back(gauge);
  }
}

void CaseReader::check_gauge_position(const TomlTableReader& r, const GaugeSpec& gauge) const {
  const Vec3d at{gauge.x, gauge.y, 0};
  const std::array<std::string_view, 2> keys = {"x", "y"};
  const DomainSpec& d = spec_.domain;
  if (d.given) {
    for (const int axis : {0, 1}) {
      if (axis == 1 && is_2d()) continue;
      if (at[axis] >= d.min[axis] && at[axis] <= d.max[axis]) continue;
      const std::string_view k = keys[static_cast<std::size_t>(axis)];
      r.fail_value(k, *r.find(k),
                   fmt::format("lies outside [domain] ({} from {} to {} m)", k,
                               format_number(d.min[axis]), format_number(d.max[axis])));
    }
  }
  // In a wall, or so close to its face that the kernel (2h) reaches into it: the fluid volume
  // sum there stays under one half at any height and the gauge would read nothing.
  const double dp = spec_.simulation.dp;
  const double support = 2 * spec_.simulation.h_over_dp * dp;
  for (const WallSpec& w : spec_.walls) {
    const bool paddle = spec_.waves.paddle_is_wall() && &w == &spec_.walls[spec_.waves.wall];
    const double travel = paddle ? spec_.waves.max_excursion : 0.0;
    for (const int axis : {0, 1}) {
      if (axis == 1 && is_2d()) continue;
      const int other = 1 - axis;
      const bool across =
          is_2d() || (at[other] >= w.box.min[other] && at[other] <= w.box.max[other]);
      if (!across) continue;
      const double thick = w.layers * dp;
      const std::string_view k = keys[static_cast<std::size_t>(axis)];
      for (const int side : {0, 1}) {
        if (!w.faces[static_cast<std::size_t>(2 * axis + side)]) continue;
        const double face = side == 0 ? w.box.min[axis] : w.box.max[axis];
        const double out = side == 0 ? face - at[axis] : at[axis] - face;  // > 0: in the layers
        if (out > 0 && out < thick) {
          r.fail_value(
              k, *r.find(k),
              fmt::format("lies in wall '{}' ({}): its particle layers span {} from {:.4g} "
                          "to {:.4g} m; put the gauge in the water",
                          w.name, w.where.str(), k, side == 0 ? face - thick : face,
                          side == 0 ? face : face + thick));
        }
        if (out <= 0 && -out < support + travel) {
          r.fail_value(k, *r.find(k),
                       fmt::format("is {:.4g} m from the face of wall '{}' ({}) at {} = {} m{}: "
                                   "closer than {:.4g} m ({}the kernel's reach 2h), the fluid "
                                   "volume sum stays under one half and the gauge reads nothing; "
                                   "move it into the water",
                                   -out, w.name, w.where.str(), k, format_number(face),
                                   paddle ? " (the paddle)" : "", support + travel,
                                   paddle ? "the paddle's travel plus " : ""));
        }
      }
    }
  }
  // Over water: x within a fill first, then (3D) x and y within the same one.
  for (const int axis : {0, 1}) {
    if (axis == 1 && is_2d()) continue;
    bool over_water = false;
    for (const FillSpec& f : spec_.fills) {
      bool inside = at.x >= f.box.min.x && at.x <= f.box.max.x;
      if (axis == 1) inside = inside && at.y >= f.box.min.y && at.y <= f.box.max.y;
      over_water = over_water || inside;
    }
    if (!over_water) {
      const std::string_view k = keys[static_cast<std::size_t>(axis)];
      r.fail_value(k, *r.find(k),
                   "lies over no [[fill]]: a gauge measures the water below it, and there is "
                   "none there");
    }
  }
}

}  // namespace netsph::case_detail
