// [waves] paddle = "flap": the paddle is a [[body]], a box hinged at the bed under its face
// to the water, that the reader sets turning about the hinge (BodySpec::angular_velocity,
// solver/body_motion.cpp). A piston is a [[wall]] that translates (case_reader_waves.cpp);
// the two share the wave, the water's levels and the tank's checks. Same conventions as
// case_reader.cpp; docs/case-reference.md documents the keys.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "netsph/case/case_reader_impl.hpp"
#include "netsph/core/error.hpp"

namespace netsph::case_detail {

void CaseReader::read_wave_flap_body(const TomlTableReader& r, const toml::node& maker) {
  WaveSpec& w = spec_.waves;
  std::vector<std::string_view> names;
  BodySpec* body = nullptr;
  for (std::size_t i = 0; i < spec_.bodies.size(); ++i) {
    names.push_back(spec_.bodies[i].name);
    if (spec_.bodies[i].name == w.wavemaker) body = &spec_.bodies[i], w.body = i;
  }
  if (!body) {
    for (const NamedEntry& other : names_) {
      if (other.name != w.wavemaker) continue;
      r.fail_value("wavemaker", maker,
                   fmt::format("names {} ({}), not a [[body]]: a flap paddle is a box body that "
                               "turns about a hinge at the bed (a piston is a [[wall]]); the "
                               "bodies are: {}",
                               other.label, other.where.str(),
                               names.empty() ? std::string("none") : join(names)));
    }
    r.fail_value("wavemaker", maker,
                 names.empty()
                     ? std::string("names no [[body]]: this case has none; a flap paddle is a "
                                   "[[body]] with shape = \"box\" standing on the bed")
                     : fmt::format("names no [[body]]{}; the bodies are: {}",
                                   did_you_mean(w.wavemaker, names), join(names)));
  }
  const std::string what = fmt::format("the flap body '{}' ({})", body->name, body->where.str());
  if (body->shape != BodyShape::Box) {
    r.fail_value(
        "wavemaker", maker,
        fmt::format("{} has shape = \"{}\": a flap paddle is a box", what, body->shape_name));
  }
  // An upright box: its faces along the axes, so that one x face is the paddle's.
  const Vec3d ex = rotate(body->orientation, Vec3d{1, 0, 0});
  const Vec3d ez = rotate(body->orientation, Vec3d{0, 0, 1});
  if (std::fabs(ex.x - 1) > 1e-9 || std::fabs(ez.z - 1) > 1e-9) {
    r.fail_value("wavemaker", maker,
                 fmt::format("{} is turned (its normal or rotation): a flap paddle stands "
                             "upright with its faces along x, y and z at rest",
                             what));
  }
  if (body->motion != BodyMotion::Fixed) {
    r.fail_value("wavemaker", maker,
                 fmt::format("{} has motion = \"{}\": [waves] sets the flap's motion (it turns "
                             "about its hinge), so remove motion and its keys from the body",
                             what, name_of(kBodyMotionNames, body->motion)));
  }
  // The face with water in front of it is the paddle's.
  const double dp = spec_.simulation.dp;
  const double low = body->center.x - 0.5 * body->lengths.x;
  const double high = body->center.x + 0.5 * body->lengths.x;
  bool in_front_of_high = false, in_front_of_low = false;
  for (const FillSpec& f : spec_.fills) {
    in_front_of_high =
        in_front_of_high || (high + 0.5 * dp >= f.box.min.x && high + 0.5 * dp <= f.box.max.x);
    in_front_of_low =
        in_front_of_low || (low - 0.5 * dp >= f.box.min.x && low - 0.5 * dp <= f.box.max.x);
  }
  if (in_front_of_high == in_front_of_low) {
    r.fail_value("wavemaker", maker,
                 fmt::format("{} spans x from {:.4g} to {:.4g} m, and {}: a flap has water on "
                             "one side only (put a [[fill]] against one of its x faces)",
                             what, low, high,
                             in_front_of_high ? "water lies against both its x faces"
                                              : "no [[fill]] lies against either of its x faces"));
  }
  w.direction = in_front_of_high ? 1 : -1;
  w.paddle_x = in_front_of_high ? high : low;
  body->motion = BodyMotion::Prescribed;
}

void CaseReader::set_flap_motion(const TomlTableReader& r, const SampledPaddle& s) {
  WaveSpec& w = spec_.waves;
  BodySpec& body = spec_.bodies[w.body];
  // Hinged at the bed under the face: the flap's excursion X at the still-water level, a depth
  // above the hinge, is depth * angle (small angles, as flap wavemaker theory has it; Dean &
  // Dalrymple 1991, sec. 6.3), so the rate is dX/dt / depth. A positive turn about +y takes
  // the top towards +x.
  const double bed = w.still_level - w.depth;
  body.hinge = {w.paddle_x, body.center.y, bed};
  body.angular_velocity.times = s.times;
  body.angular_velocity.velocities.clear();
  for (const double v : s.velocities)
    body.angular_velocity.velocities.push_back({0, w.direction * v / w.depth, 0});
  // The angle stays small (the theory is linear in it) and the flap's top, which travels
  // farthest, stays in [domain].
  const double angle = std::atan(w.max_excursion / w.depth);
  const toml::node& maker = *r.find("wavemaker");
  if (angle > 0.35) {
    r.fail_value("wavemaker", maker,
                 fmt::format("the flap turns {:.3g} degrees either side of upright over the run "
                             "(its excursion {:.4g} m at the still-water level, {:.4g} m above "
                             "the hinge): more than 20 degrees, past the small angles of flap "
                             "wavemaker theory; lower the wave height",
                             angle * 180 / M_PI, w.max_excursion, w.depth));
  }
  // The tank's bottom runs under the flap (under its whole thickness, at the bed), and the
  // back corner, which dips by thickness sin(angle) as the flap turns back about the front
  // foot, stays within the bottom's particle layers.
  const double dp = spec_.simulation.dp;
  const double back_x = w.paddle_x - w.direction * body.lengths.x;
  const double lo = std::min(back_x, w.paddle_x), hi = std::max(back_x, w.paddle_x);
  const WallSpec* bottom = nullptr;
  for (const WallSpec& wall : spec_.walls) {
    if (!wall.faces[kZMin] || std::fabs(wall.box.min.z - bed) > 0.5 * dp) continue;
    if (wall.box.min.x <= lo + 0.5 * dp && wall.box.max.x >= hi - 0.5 * dp) bottom = &wall;
  }
  if (!bottom) {
    r.fail_value("wavemaker", maker,
                 fmt::format("no wall's bottom (a zmin face at the bed, z = {}) runs under the "
                             "flap (x from {:.4g} to {:.4g} m): the water would leak under its "
                             "hinge; extend the tank's bottom under and behind the flap",
                             format_number(bed), lo, hi));
  }
  const double dip = body.lengths.x * std::sin(angle);
  if (dip > bottom->layers * dp) {
    r.fail_value("wavemaker", maker,
                 fmt::format("the flap is {:.4g} m thick, so its back corner dips {:.4g} m below "
                             "the bed as it turns {:.3g} degrees back, through the {:.4g} m of the "
                             "bottom's particle layers (wall '{}'): make the flap at most {:.4g} m "
                             "thick",
                             body.lengths.x, dip, angle * 180 / M_PI, bottom->layers * dp,
                             bottom->name, bottom->layers * dp / std::sin(angle)));
  }
  const double top = body.center.z + 0.5 * body.lengths.z;
  const double reach = (top - bed) * std::sin(angle) + body.lengths.x;
  const DomainSpec& d = spec_.domain;
  const double far = w.paddle_x - w.direction * reach;
  if (d.given && (far < d.min.x || far > d.max.x)) {
    r.fail_value("wavemaker", maker,
                 fmt::format("the flap's top swings {:.4g} m either side of upright, so its back "
                             "(at rest x = {:.4g} m) reaches x = {:.4g} m, outside [domain] (x "
                             "from {} to {} m): widen the domain behind the flap",
                             (top - bed) * std::sin(angle), back_x, far, format_number(d.min.x),
                             format_number(d.max.x)));
  }
  double water = 0;
  for (const FillSpec& f : spec_.fills) water = std::max(water, f.box.max.x - f.box.min.x);
  if (2 * w.max_excursion > 0.5 * water) {
    r.fail_value("wavemaker", maker,
                 fmt::format("the flap travels {:.4g} m either side of upright at the still-water "
                             "level, more than a quarter of the length of the water ({:.4g} m): "
                             "a tank that short cannot take this wave; lower the height or "
                             "lengthen the tank",
                             w.max_excursion, water));
  }
}

}  // namespace netsph::case_detail
