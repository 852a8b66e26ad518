// The [[body]] tables of a case file: rigid bodies made of boundary particles. Same conventions
// as case_reader.cpp: unknown keys first, then the keys in a fixed order (name, shape and its
// parameters, centre, orientation, motion, boundary model, Cd reference), then the rules that
// combine keys (parameters of the shape, keys of the motion, [domain], unique names).
// docs/case-reference.md documents every key; keep the two in step.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "netsph/case/case_reader_impl.hpp"
#include "netsph/core/error.hpp"

namespace netsph::case_detail {
namespace {

const std::vector<std::string_view> kRotationKeys = {"axis", "angle"};

/// The shapes as the case names them; several map to one BodyShape.
enum class ShapeKind { Box, Plate, SquarePlate, CircularPlate, Cylinder, Sphere, Cruciform };
constexpr std::array kShapeKindNames = {
    EnumName<ShapeKind>{"box", ShapeKind::Box},
    EnumName<ShapeKind>{"plate", ShapeKind::Plate},
    EnumName<ShapeKind>{"square_plate", ShapeKind::SquarePlate},
    EnumName<ShapeKind>{"circular_plate", ShapeKind::CircularPlate},
    EnumName<ShapeKind>{"cylinder", ShapeKind::Cylinder},
    EnumName<ShapeKind>{"sphere", ShapeKind::Sphere},
    EnumName<ShapeKind>{"cruciform", ShapeKind::Cruciform}};
static_assert(one_to_one(kShapeKindNames));
/// Which key orients the shape's local x axis.
enum class Orientation { None, Normal, Axis };

struct ShapeParameter {
  std::string_view key;
  std::string_view meaning;
};

struct ShapeInfo {
  ShapeKind kind;
  std::vector<ShapeParameter> parameters;
  Orientation orientation;
  std::string_view name() const { return name_of(kShapeKindNames, kind); }
};

const std::vector<ShapeInfo>& shapes() {
  static const std::vector<ShapeInfo> list = {
      {ShapeKind::Box, {{"size", "lengths [lx, ly, lz] along the local axes"}}, Orientation::None},
      {ShapeKind::Plate,
       {{"thickness", "plate thickness along the normal (local x)"},
        {"width", "plate width along local y"},
        {"height", "plate height along local z"}},
       Orientation::Normal},
      {ShapeKind::SquarePlate,
       {{"side", "edge length of the square face"},
        {"thickness", "plate thickness along the normal (local x)"}},
       Orientation::Normal},
      {ShapeKind::CircularPlate,
       {{"diameter", "disc diameter"}, {"thickness", "disc thickness along the normal (local x)"}},
       Orientation::Normal},
      {ShapeKind::Cylinder,
       {{"diameter", "cylinder diameter"}, {"length", "cylinder length along its axis (local x)"}},
       Orientation::Axis},
      {ShapeKind::Sphere, {{"diameter", "sphere diameter"}}, Orientation::None},
      {ShapeKind::Cruciform,
       {{"twine_length", "length of each of the two crossing twines"},
        {"twine_diameter", "twine diameter, < twine_length"}},
       Orientation::Normal},
  };
  return list;
}

/// Every shape parameter, in the order of the schema.
constexpr std::array<std::string_view, 9> kShapeKeys = {"size",   "thickness",    "width",
                                                        "height", "side",         "diameter",
                                                        "length", "twine_length", "twine_diameter"};

const ShapeInfo& shape_info(ShapeKind kind) {
  for (const ShapeInfo& s : shapes()) {
    if (s.kind == kind) return s;
  }
  return shapes().front();  // unreachable: every kind is listed
}

const ShapeInfo& shape_info(std::string_view name) {
  // The name was checked against the list.
  return shape_info(value_of(kShapeKindNames, name).value_or(ShapeKind::Box));
}

bool has_parameter(const ShapeInfo& s, std::string_view key) {
  return std::any_of(s.parameters.begin(), s.parameters.end(),
                     [&](const ShapeParameter& p) { return p.key == key; });
}

/// "diameter, length"
std::string parameter_list(const ShapeInfo& s) {
  std::vector<std::string_view> keys;
  for (const ShapeParameter& p : s.parameters) keys.push_back(p.key);
  return join(keys);
}

/// "\"plate\", \"square_plate\" and \"circular_plate\""
std::string owners_of(std::string_view key) {
  std::vector<std::string> owners;
  for (const ShapeInfo& s : shapes()) {
    if (has_parameter(s, key)) owners.push_back(toml_quote(s.name()));
  }
  std::string out;
  for (std::size_t i = 0; i < owners.size(); ++i) {
    if (i > 0) out += i + 1 == owners.size() ? " and " : ", ";
    out += owners[i];
  }
  return out;
}

/// Keys that belong to one motion only.
struct MotionKey {
  std::string_view key;
  BodyMotion owner;
};
constexpr std::array<MotionKey, 5> kMotionKeys = {{{"density", BodyMotion::Floating},
                                                   {"mass", BodyMotion::Floating},
                                                   {"initial_velocity", BodyMotion::Floating},
                                                   {"velocity", BodyMotion::Prescribed},
                                                   {"motion_history", BodyMotion::Prescribed}}};

/// The shortest rotation taking local x (1, 0, 0) to the unit vector `d`. Antiparallel
/// (d = -x): half a turn about y, which keeps local y and so stays in the 2D plane.
Quat align_x_to(const Vec3d& d) {
  // q = (1 + x.d, x cross d), normalised: half the angle between x and d. Near d = -x,
  // 1 + d.x cancels; (d.y^2 + d.z^2) / (1 - d.x) is the same for a unit d, without the loss.
  const double w = d.x >= 0 ? 1 + d.x : (d.y * d.y + d.z * d.z) / (1 - d.x);
  const double n = std::sqrt(w * w + d.y * d.y + d.z * d.z);
  if (!(n > 1e-150)) return Quat{0, 0, 1, 0};
  return Quat{w / n, 0, -d.z / n, d.y / n};
}

/// A shape's largest length and the key that sets it; in 2D (the x-z plane) lengths along y
/// do not count.
struct LongestLength {
  double length = 0;
  std::string_view key;
};
LongestLength longest_length(ShapeKind kind, const BodySpec& body, bool flat) {
  LongestLength l;
  const auto consider = [&](double length, std::string_view key) {
    if (length > l.length) l = {length, key};
  };
  switch (kind) {
    case ShapeKind::Box:
      consider(body.lengths.x, "size");
      if (!flat) consider(body.lengths.y, "size");
      consider(body.lengths.z, "size");
      break;
    case ShapeKind::Plate:
      consider(body.lengths.x, "thickness");
      if (!flat) consider(body.lengths.y, "width");
      consider(body.lengths.z, "height");
      break;
    case ShapeKind::SquarePlate:
      consider(body.lengths.x, "thickness");
      consider(body.lengths.z, "side");
      break;
    case ShapeKind::CircularPlate:
      consider(body.diameter, "diameter");
      consider(body.length, "thickness");
      break;
    case ShapeKind::Cylinder:
      consider(body.diameter, "diameter");
      if (!flat) consider(body.length, "length");
      break;
    case ShapeKind::Sphere:
      consider(body.diameter, "diameter");
      break;
    case ShapeKind::Cruciform:
      consider(body.length, "twine_length");
      break;
  }
  return l;
}

}  // namespace

// ---- [[body]] -----------------------------------------------------------------------------

void CaseReader::read_bodies() {
  const std::vector<const toml::table*> tables = find_array_of_tables("body");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const int number = static_cast<int>(i) + 1;
    BodySpec body = read_body(*tables[i], number);
    register_body_name(*tables[i], body, number);
    spec_.bodies.push_back(std::move(body));
  }
}

BodySpec CaseReader::read_body(const toml::table& table, int number) const {
  const std::string label = fmt::format("body[{}]", number);
  TomlTableReader r(table, label, label, keys_of("body"), source_, home_hint);
  BodySpec body;
  body.where = r.location();
  body.name = r.string("name", fmt::format("body{}", number));
  if (body.name.empty()) r.fail_value("name", *r.find("name"), "must not be empty");
  body.group = r.string("group", body.name);
  if (body.group.empty()) {
    r.fail_value("group", *r.find("group"),
                 "must not be empty (leave group out to use the body's name)");
  }
  read_body_shape(r, body);
  body.center = read_position(r, "center", "position [x, y, z] of the body's centre, m");
  check_in_domain(r, "center", body.center);
  body.orientation = read_body_orientation(r, body);
  read_body_motion(r, body);
  read_body_boundary(r, body);
  read_body_reference(r, body);
  return body;
}

void CaseReader::register_body_name(const toml::table& table, const BodySpec& body, int number) {
  const std::string label = fmt::format("body[{}]", number);
  for (const NamedEntry& other : names_) {
    if (other.name != body.name) continue;
    const toml::node* name_node = table.get("name");
    throw Error(source_.where(name_node ? name_node->source() : table.source()),
                fmt::format("body name \"{}\" is used twice: by {} ({}) and {}; names must be "
                            "unique among walls, inlets, outlets and bodies",
                            body.name, other.label, other.where.str(), label));
  }
  names_.push_back({body.name, label, body.where});
}

// ---- shape --------------------------------------------------------------------------------

void CaseReader::read_body_shape(const TomlTableReader& r, BodySpec& body) const {
  constexpr auto kNames = names_of(kShapeKindNames);
  const toml::node& node = r.require(
      "shape", "the body's solid: " +
                   join(std::vector<std::string_view>(kNames.begin(), kNames.end()), ", "));
  const ShapeKind kind = r.to_choice("shape", node, kShapeKindNames);
  const ShapeInfo& info = shape_info(kind);
  body.shape_name = std::string(info.name());

  // A parameter of another shape would otherwise be silently ignored.
  for (const std::string_view key : kShapeKeys) {
    const toml::node* foreign = r.find(key);
    if (!foreign || has_parameter(info, key)) continue;
    r.fail_value(key, *foreign,
                 fmt::format("is not a parameter of shape \"{}\" ({} is a parameter of {}); "
                             "shape \"{}\" takes {}",
                             info.name(), key, owners_of(key), info.name(), parameter_list(info)));
  }
  const auto length = [&](std::string_view key) {
    std::string_view meaning;
    for (const ShapeParameter& p : info.parameters) {
      if (p.key == key) meaning = p.meaning;
    }
    return r.required_number(key, NumberRule::positive("m"),
                             fmt::format("{}, m, > 0; shape \"{}\" takes {}", meaning, info.name(),
                                         parameter_list(info)));
  };
  switch (kind) {
    case ShapeKind::Box:
      body.shape = BodyShape::Box;
      body.lengths = r.required_vec3(
          "size", NumberRule::positive("m"),
          "lengths [lx, ly, lz] along the local axes, m, > 0; shape \"box\" takes size");
      break;
    case ShapeKind::Plate:
      body.shape = BodyShape::Box;
      body.lengths.x = length("thickness");
      body.lengths.y = length("width");
      body.lengths.z = length("height");
      break;
    case ShapeKind::SquarePlate:
      body.shape = BodyShape::Box;
      body.lengths.y = body.lengths.z = length("side");
      body.lengths.x = length("thickness");
      break;
    case ShapeKind::CircularPlate:
      body.shape = BodyShape::Cylinder;
      body.diameter = length("diameter");
      body.length = length("thickness");
      break;
    case ShapeKind::Cylinder:
      body.shape = BodyShape::Cylinder;
      body.diameter = length("diameter");
      body.length = length("length");
      break;
    case ShapeKind::Sphere:
      body.shape = BodyShape::Sphere;
      body.diameter = length("diameter");
      break;
    case ShapeKind::Cruciform:
      body.shape = BodyShape::Cruciform;
      body.length = length("twine_length");
      body.diameter = length("twine_diameter");
      if (body.diameter >= body.length) {
        r.fail_value("twine_diameter", *r.find("twine_diameter"),
                     fmt::format("must be < {} = {} m: the twines are thinner than they are long",
                                 r.key_path("twine_length"), format_number(body.length)));
      }
      break;
  }
  const LongestLength longest = longest_length(kind, body, is_2d());
  check_body_fits_domain(r, longest.length, longest.key);
}

/// A body longer than [domain]'s diagonal has particles outside it whatever its centre and
/// orientation; said here, at its size, before its particles are built (a box 1e6 m long at
/// dp = 0.02 m took gigabytes and minutes to reach the particle check, or ran out of memory).
/// Its particles span at least its largest length less dp along that length.
void CaseReader::check_body_fits_domain(const TomlTableReader& r, double longest,
                                        std::string_view key) const {
  const DomainSpec& d = spec_.domain;
  if (!d.given) return;
  const bool flat = is_2d();
  const Vec3d span = d.max - d.min;
  const double diagonal =
      std::sqrt(span.x * span.x + span.z * span.z + (flat ? 0.0 : span.y * span.y));
  if (key.empty() || !(longest - spec_.simulation.dp > diagonal)) return;
  r.fail_value(key, *r.find(key),
               fmt::format("makes the body {} m long, but [domain] (min {}, max {}) is {} m "
                           "across its diagonal: the body cannot lie inside it; make the body "
                           "smaller or the domain larger",
                           format_number(longest), format_vec3(d.min), format_vec3(d.max),
                           format_derived(diagonal)));
}

// ---- orientation --------------------------------------------------------------------------

Quat CaseReader::read_body_orientation(const TomlTableReader& r, const BodySpec& body) const {
  const ShapeInfo& info = shape_info(body.shape_name);
  if (const toml::node* normal = r.find("normal");
      normal && info.orientation != Orientation::Normal) {
    r.fail_value("normal", *normal,
                 info.orientation == Orientation::Axis
                     ? fmt::format("does not apply to shape \"{}\": give its axis = [x, y, z] "
                                   "instead (the direction of the cylinder's axis)",
                                   info.name())
                     : fmt::format("does not apply to shape \"{}\" (normal orients plates, "
                                   "circular plates and cruciforms); turn a {} with "
                                   "rotation = {{ axis = [x, y, z], angle = <degrees> }}",
                                   info.name(), info.name()));
  }
  if (const toml::node* axis = r.find("axis"); axis && info.orientation != Orientation::Axis) {
    r.fail_value("axis", *axis,
                 info.orientation == Orientation::Normal
                     ? fmt::format("does not apply to shape \"{}\": give its normal = [x, y, z] "
                                   "instead (the direction of the local x axis)",
                                   info.name())
                     : fmt::format("does not apply to shape \"{}\" (axis orients cylinders); "
                                   "turn a {} with rotation = {{ axis = [x, y, z], angle = "
                                   "<degrees> }}",
                                   info.name(), info.name()));
  }
  Quat q{};
  if (info.orientation == Orientation::Normal) {
    if (const toml::node* normal = r.find("normal")) {
      q = align_x_to(read_direction(r, "normal", *normal, false, {}));
    }
  } else if (info.orientation == Orientation::Axis) {
    const toml::node* axis = r.find("axis");
    q = align_x_to(axis ? read_direction(r, "axis", *axis, true,
                                         "a cylinder in 2D is a circle in the x-z plane, its "
                                         "axis along y")
                        : Vec3d{0, 1, 0});
  }
  if (r.has("rotation")) q = normalized(read_rotation(r) * q);
  return q;
}

Vec3d CaseReader::read_direction(const TomlTableReader& r, std::string_view key,
                                 const toml::node& node, bool along_y_in_2d,
                                 std::string_view along_y_reason) const {
  const Vec3d v = r.to_vec3(key, node, NumberRule::any(""));
  // Scale by the largest component first, so that huge components do not overflow.
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (largest == 0) r.fail_value(key, node, "must be a non-zero direction (it is normalised)");
  if (is_2d()) {
    if (!along_y_in_2d) {
      check_in_plane(r, key, node, v);
    } else if (v.x != 0 || v.z != 0) {
      r.fail_value(key, node, fmt::format("must be along y ([0, 1, 0]) in 2D: {}", along_y_reason));
    }
  }
  const Vec3d scaled = v / largest;
  return scaled / norm(scaled);
}

Quat CaseReader::read_rotation(const TomlTableReader& r) const {
  const toml::node& node = *r.find("rotation");
  const toml::table& table = r.nested_table("rotation", node,
                                            "must be a table such as { axis = [0, 0, 1], angle = "
                                            "30 } (a turn in degrees about a world axis)");
  const std::string path = r.key_path("rotation");
  TomlTableReader t(table, path, path, kRotationKeys, source_);
  const Vec3d axis = read_direction(
      t, "axis", t.require("axis", "the world axis [x, y, z] to turn about, non-zero"), true,
      "a rotation in 2D turns about y so that the body stays in the x-z plane");
  const double degrees = t.required_number("angle", NumberRule::any("degrees"),
                                           "the turn about axis in degrees, right-handed");
  return Quat::from_axis_angle(axis, degrees * std::numbers::pi / 180);
}

// ---- motion -------------------------------------------------------------------------------

void CaseReader::read_body_motion(const TomlTableReader& r, BodySpec& body) const {
  body.motion = r.choice("motion", kBodyMotionNames, body.motion);
  const std::string_view motion = name_of(body.motion);
  for (const MotionKey& k : kMotionKeys) {
    const toml::node* node = r.find(k.key);
    if (!node || k.owner == body.motion) continue;
    r.fail_value(k.key, *node,
                 fmt::format("applies to motion = \"{}\" only, but this body's motion is \"{}\"{}; "
                             "set motion = \"{}\" or remove {}",
                             name_of(k.owner), motion, r.has("motion") ? "" : " (the default)",
                             name_of(k.owner), k.key));
  }
  const std::string_view mass_unit = is_2d() ? "kg/m" : "kg";
  if (body.motion == BodyMotion::Floating) {
    const toml::node* density = r.find("density");
    const toml::node* mass = r.find("mass");
    if (density && mass) {
      r.fail_value("mass", *mass,
                   fmt::format("cannot be combined with {}: give either density (kg/m^3) or "
                               "mass ({}), not both",
                               r.key_path("density"), mass_unit));
    }
    if (!density && !mass) {
      r.fail_table(
          fmt::format("{} has motion = \"floating\" and needs its inertia: give "
                      "density = <kg/m^3> or mass = <{}>",
                      r.title(), mass_unit));
    }
    if (density) {
      body.density =
          r.to_number("density", *density, NumberRule::left_open(0, kMostDensity, "kg/m^3"));
    } else {
      body.mass = r.to_number("mass", *mass, NumberRule::positive(mass_unit));
    }
    body.initial_velocity =
        read_in_plane_vector(r, "initial_velocity", velocity_rule(), body.initial_velocity);
  } else if (body.motion == BodyMotion::Prescribed) {
    body.velocity = read_velocity_history(r, "velocity", "motion_history");
    if (!body.velocity.moving()) {
      r.fail_table(
          fmt::format("{} has motion = \"prescribed\" and needs its velocity: give "
                      "velocity = [u, v, w] (constant, m/s) or motion_history = "
                      "{{ times = [...], velocities = [[u, v, w], ...] }}",
                      r.title()));
    }
  }
}

// ---- boundary model and Cd reference --------------------------------------------------------

void CaseReader::read_body_boundary(const TomlTableReader& r, BodySpec& body) const {
  body.model = r.choice("model", kWallModelNames, body.model);
  if (const toml::node* slip = r.find("slip"); slip && body.model == WallModel::Dbc) {
    r.fail_value("slip", *slip,
                 "slip applies to mdbc bodies only (dbc body particles always carry the body's "
                 "own velocity); remove slip or set model = \"mdbc\"");
  }
  body.slip = r.choice("slip", kWallSlipNames, body.slip);
  const toml::node* layers = r.find("layers");
  if (!layers) return;
  constexpr std::string_view kAllowed =
      "-1 (solid), 0 (automatic: a shell as thick as the kernel support 2h) or a number of "
      "layers in [1, 20]";
  const auto* integer = layers->as_integer();
  if (!integer) {
    r.fail_value("layers", *layers,
                 fmt::format("must be an integer, {}, not {}", kAllowed, type_name(*layers)));
  }
  if (integer->get() < -1 || integer->get() > 20) {
    r.fail_value("layers", *layers, fmt::format("must be {}", kAllowed));
  }
  body.layers = static_cast<int>(integer->get());
}

void CaseReader::read_body_reference(const TomlTableReader& r, BodySpec& body) const {
  const std::string_view area_unit = is_2d() ? "m" : "m^2";
  body.reference_velocity = r.optional_number("reference_velocity", NumberRule::positive("m/s"));
  body.reference_area = r.optional_number("reference_area", NumberRule::positive(area_unit));
  const auto missing = [&](std::string_view given, std::string_view other, std::string_view unit) {
    r.fail_value(given, *r.find(given),
                 fmt::format("needs {} ({}, > 0) too: Cd = F / (0.5 rho U^2 A) uses both the "
                             "reference velocity U and the reference area A",
                             r.key_path(other), unit));
  };
  if (body.reference_velocity && !body.reference_area) {
    missing("reference_velocity", "reference_area", area_unit);
  }
  if (body.reference_area && !body.reference_velocity) {
    missing("reference_area", "reference_velocity", "m/s");
  }
}

void CaseReader::check_in_domain(const TomlTableReader& r, std::string_view key,
                                 const Vec3d& center) const {
  const DomainSpec& d = spec_.domain;
  if (!d.given) return;
  for (const int axis : used_axes()) {
    const char name = "xyz"[axis];
    std::string problem;
    if (center[axis] < d.min[axis]) {
      problem = fmt::format("{} = {} < domain min {} = {}", name, format_number(center[axis]), name,
                            format_number(d.min[axis]));
    } else if (center[axis] > d.max[axis]) {
      problem = fmt::format("{} = {} > domain max {} = {}", name, format_number(center[axis]), name,
                            format_number(d.max[axis]));
    }
    if (problem.empty()) continue;
    r.fail_value(key, *r.find(key),
                 fmt::format("must lie inside [domain] (min {}, max {}): {}", format_vec3(d.min),
                             format_vec3(d.max), problem));
  }
}

void CaseReader::check_x_in_domain(const TomlTableReader& r, std::string_view key, double x) const {
  // The other coordinates at the domain's middle: only x is the key's.
  Vec3d p = 0.5 * (spec_.domain.min + spec_.domain.max);
  p.x = x;
  check_in_domain(r, key, p);
}

}  // namespace netsph::case_detail
