// The boundary tables of a case file: [[wall]], [[inlet]] and [[outlet]]. Same conventions as
// case_reader.cpp: unknown keys first, then the keys in a fixed order, then the rules that
// combine keys (mDBC layers, buffers, faces of [domain], unique names).
// docs/case-reference.md documents every key; keep the two in step.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "netsph/case/case_reader_impl.hpp"
#include "netsph/core/error.hpp"

namespace netsph::case_detail {
namespace {

const std::vector<std::string_view> kProfileKeys = {"z", "u"};

/// A wall's slip words, in the order [[wall]] has always listed them in its messages (its
/// default, wall_velocity, last).
constexpr auto kWallSlips =
    reordered(kWallSlipNames, {WallSlip::NoSlip, WallSlip::FreeSlip, WallSlip::WallVelocity});
/// The faces a wall can have in 2D, in kFaceNames' order.
constexpr std::array<std::string_view, 4> kFaceNames2D = {name_of(kXMin), name_of(kXMax),
                                                          name_of(kZMin), name_of(kZMax)};

/// The name of face number `face` (0..5, kFaceNames' order).
std::string_view face_name(std::size_t face) {
  return name_of(static_cast<Face>(face));
}

}  // namespace

// ---- names --------------------------------------------------------------------------------

void CaseReader::register_name(const toml::table& table, const std::string& name,
                               std::string_view kind, const std::string& label,
                               const SourceLocation& where) {
  for (const NamedEntry& other : names_) {
    if (other.name != name) continue;
    const toml::node* name_node = table.get("name");
    throw Error(source_.where(name_node ? name_node->source() : table.source()),
                fmt::format("{} name \"{}\" is used twice: by {} ({}) and {}; names must be "
                            "unique among walls, inlets and outlets",
                            kind, name, other.label, other.where.str(), label));
  }
  names_.push_back({name, label, where});
}

// ---- [[wall]] -----------------------------------------------------------------------------

void CaseReader::read_walls() {
  const std::vector<const toml::table*> tables = find_array_of_tables("wall");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    WallSpec wall = read_wall(*tables[i], static_cast<int>(i) + 1);
    register_name(*tables[i], wall.name, "wall", fmt::format("wall[{}]", i + 1), wall.where);
    spec_.walls.push_back(std::move(wall));
  }
}

WallSpec CaseReader::read_wall(const toml::table& table, int number) const {
  const std::string name = fmt::format("wall[{}]", number);
  TomlTableReader r(table, name, name, keys_of("wall"), source_, home_hint);
  WallSpec wall;
  wall.where = r.location();
  wall.name = r.string("name", fmt::format("wall{}", number));
  if (wall.name.empty()) r.fail_value("name", *r.find("name"), "must not be empty");
  wall.box = read_box(r, "the wall's fluid side");
  check_box_fits_lattice(r, wall.box);
  wall.faces = read_faces(r);
  // Default: enough layers to cover the kernel support 2h (3 at h = 1.5 dp).
  wall.layers = static_cast<int>(r.integer("layers", IntRule{1, 10}, support_layers()));
  wall.model = r.choice("model", kWallModelNames, wall.model);
  if (const toml::node* slip = r.find("slip"); slip && wall.model == WallModel::Dbc) {
    r.fail_value("slip", *slip,
                 "slip applies to mdbc walls only (dbc wall particles always carry the wall's "
                 "own velocity); remove slip or set model = \"mdbc\"");
  }
  wall.slip = r.choice("slip", kWallSlips, wall.slip);
  wall.motion = read_velocity_history(r, "velocity", "motion");
  check_wall_layers(r, wall);
  check_wall_seamless(r, wall);
  return wall;
}

// A wall's particles lie on its own lattice, dp apart from its box's min. Along a periodic axis
// that the wall spans, its last particle and the first one's image are then period - (n - 1) dp
// apart, n = round(period / dp): not dp when the period is not a whole number of dp. Fluid
// leaks through a gap wider than dp, and through a moving wall's the whole time, the gap
// travelling with the fluid beside it: the Bi 2014 flume at dp = 6 mm (0.8 m = 133.3 dp) had 848
// particles through its walls by t = 1.44 s, all from the gap (docs/VALIDATION.md). So it is an
// error, not a warning.
void CaseReader::check_wall_seamless(const TomlTableReader& r, const WallSpec& wall) const {
  const DomainSpec& d = spec_.domain;
  const double dp = spec_.simulation.dp;
  if (!d.given || !(dp > 0)) return;
  for (const int axis : used_axes()) {
    const auto a = static_cast<std::size_t>(axis);
    if (!d.periodic[a]) continue;
    const double period = d.max[axis] - d.min[axis];
    const bool spans = wall.box.min[axis] <= d.min[axis] + 0.5 * dp &&
                       wall.box.max[axis] >= d.max[axis] - 0.5 * dp;
    // Only its faces along the axis have particles all along it.
    bool along = false;
    for (std::size_t f = 0; f < 6; ++f) along = along || (wall.faces[f] && f / 2 != a);
    if (!spans || !along) continue;
    const double spacings = period / dp;
    const double whole = std::round(spacings);
    // The seam's spacing within 0.1% of dp: a dp given to a few digits passes.
    if (std::fabs(spacings - whole) <= 1e-3) continue;
    const double below = std::max(std::floor(spacings), 1.0);
    r.fail_table(fmt::format(
        "{} spans the periodic axis {}, whose period ([domain] max - min = {} m) is {:.4g} "
        "particle spacings of simulation.dp = {} m: where the period closes, the wall's last "
        "particle and the first one's image would be {:.3g} dp apart instead of 1 (a gap lets "
        "the fluid through, crowded particles disturb it); use a dp that divides the period, "
        "such as {} m ({} spacings) or {} m ({}), or a period of a whole number of dp",
        r.title(), "xyz"[axis], format_number(period), spacings, format_number(dp),
        spacings - (whole - 1), fmt::format("{:.9g}", period / (below + 1)), below + 1,
        fmt::format("{:.9g}", period / below), below));
  }
}

std::array<bool, 6> CaseReader::read_faces(const TomlTableReader& r) const {
  std::array<bool, 6> faces{};
  constexpr auto kAll = names_of(kFaceNames);
  const std::vector<std::string_view> allowed =
      is_2d() ? std::vector<std::string_view>(kFaceNames2D.begin(), kFaceNames2D.end())
              : std::vector<std::string_view>(kAll.begin(), kAll.end());
  const toml::node* node = r.find("faces");
  if (!node) {
    for (const std::string_view face : allowed) {
      faces[static_cast<std::size_t>(*value_of(kFaceNames, face))] = true;
    }
    return faces;
  }
  // to_word_list() returns indices into `known`: kFaceNames is in face order, so they are faces.
  const WordListRule rule{
      .noun = "face",
      .known = std::vector<std::string_view>(kAll.begin(), kAll.end()),
      .allowed = allowed,
      .not_allowed_reason = kNotIn2D,
      .example = "[\"xmin\", \"xmax\", \"zmin\"]",
  };
  for (const std::size_t face : r.to_word_list("faces", *node, rule)) faces[face] = true;
  return faces;
}

/// mDBC extrapolates the fluid state to each boundary particle from a ghost point mirrored
/// into the fluid, and fluid particles next to the wall need wall particles over their whole
/// kernel: the wall must be at least 2h thick.
void CaseReader::check_wall_layers(const TomlTableReader& r, const WallSpec& wall) const {
  if (wall.model != WallModel::Mdbc) return;
  const int needed = support_layers();
  if (wall.layers >= needed) return;
  const double thickness = wall.layers * spec_.simulation.dp;
  const std::string dbc =
      r.has("model") ? "model = \"dbc\"" : "model = \"dbc\" (mdbc is the default)";
  const std::string why =
      fmt::format("mDBC needs the wall layers to cover the kernel support {}", support_text());
  // The default layers always suffice, so `layers` was given.
  r.fail_value("layers", *r.find("layers"),
               fmt::format("{}, but layers * dp = {} m; use layers >= {}, or {}", why,
                           format_derived(thickness), needed, dbc));
}

// ---- [[inlet]] and [[outlet]] -------------------------------------------------------------

void CaseReader::read_open_boundaries(bool inlet) {
  const std::string_view kind = inlet ? "inlet" : "outlet";
  std::vector<OpenBoundarySpec>& list = inlet ? spec_.inlets : spec_.outlets;
  const std::vector<const toml::table*> tables = find_array_of_tables(kind);
  for (std::size_t i = 0; i < tables.size(); ++i) {
    OpenBoundarySpec ob = read_open_boundary(*tables[i], inlet, static_cast<int>(i) + 1);
    register_name(*tables[i], ob.name, kind, fmt::format("{}[{}]", kind, i + 1), ob.where);
    list.push_back(std::move(ob));
  }
}

OpenBoundarySpec CaseReader::read_open_boundary(const toml::table& table, bool inlet, int number) {
  const std::string_view kind = inlet ? "inlet" : "outlet";
  const std::string label = fmt::format("{}[{}]", kind, number);
  TomlTableReader r(table, label, label, keys_of(kind), source_, home_hint);
  OpenBoundarySpec ob;
  ob.where = r.location();
  ob.name = r.string("name", fmt::format("{}{}", kind, number));
  if (ob.name.empty()) r.fail_value("name", *r.find("name"), "must not be empty");
  ob.face = read_open_face(r, kind);
  check_face_free(r, ob, label);
  // Default: 4 layers as in the paper, more if the kernel support needs them.
  ob.layers =
      static_cast<int>(r.integer("layers", IntRule{1, 20}, std::max(ob.layers, support_layers())));
  check_buffer(r, ob);
  check_buffer_clear_of_walls(r, ob, kind);
  read_open_velocity(r, inlet, ob);
  ob.density = r.choice("density", kBufferDensityNames, ob.density);
  if (ob.density == BufferDensity::Hydrostatic && spec_.fluid.gravity.z == 0) {
    r.fail_value("density", *r.find("density"),
                 fmt::format("needs gravity along z for the hydrostatic pressure, but "
                             "fluid.gravity = {} has z = 0; use \"extrapolated\" or \"reference\"",
                             format_vec3(spec_.fluid.gravity)));
  }
  ob.surface_z = r.optional_number("surface_z", coordinate_rule());
  return ob;
}

Face CaseReader::read_open_face(const TomlTableReader& r, std::string_view kind) const {
  const toml::node& node =
      r.require("face", "the face of [domain] it lies on: xmin, xmax, ymin, ymax, zmin or zmax");
  const Face face = r.to_choice("face", node, kFaceNames);
  if (is_2d() && (face == kYMin || face == kYMax)) {
    r.fail_value("face", node,
                 fmt::format("face \"{}\" is not allowed {}; allowed: xmin, xmax, zmin, zmax",
                             name_of(face), kNotIn2D));
  }
  if (!spec_.domain.given) {
    r.fail_value(
        "face", node,
        fmt::format("an [[{}]] lies on a face of [domain]: give [domain] min and max", kind));
  }
  // An open boundary may sit on a periodic axis: the paper's flumes make the moving walls
  // periodic along the flow so their particles wrap around, while the fluid enters and leaves
  // through buffers. The buffers cover the kernel support, so no fluid particle interacts
  // across the period.
  return face;
}

void CaseReader::check_periodic_open_faces() const {
  for (std::size_t face = 0; face < 6; ++face) {
    const std::optional<NamedEntry>& here = open_faces_[face];
    const int axis = static_cast<int>(face) / 2;
    if (!here || !spec_.domain.periodic[static_cast<std::size_t>(axis)] || open_faces_[face ^ 1])
      continue;
    // The fluid would wrap through the opposite face into the buffer: an inlet then only adds
    // water, an outlet takes what the period brings back.
    throw Error(here->where.str(),
                fmt::format("{} lies on face \"{}\" of the periodic axis {}, and face \"{}\" "
                            "has no open boundary: the fluid would wrap through it into the "
                            "buffer. Put an [[inlet]] or [[outlet]] on \"{}\" too (as the "
                            "paper's flumes do), or take {} out of domain.periodic",
                            here->label, face_name(face), "xyz"[axis], face_name(face ^ 1),
                            face_name(face ^ 1), "xyz"[axis]));
  }
}

void CaseReader::check_face_free(const TomlTableReader& r, const OpenBoundarySpec& ob,
                                 const std::string& label) {
  std::optional<NamedEntry>& slot = open_faces_[static_cast<std::size_t>(ob.face)];
  if (slot) {
    r.fail_value("face", *r.find("face"),
                 fmt::format("face \"{}\" already has an open boundary, {} ({}); a face takes at "
                             "most one [[inlet]] or [[outlet]]",
                             name_of(ob.face), slot->label, slot->where.str()));
  }
  slot = NamedEntry{ob.name, label, ob.where};
}

// A wall face on the plane of an open face (a box spanning the channel, with the default of all
// six faces) would put the wall's layers across the buffer, or outside [domain]: caught here, on
// the open boundary, with the wall to change, before the scene reports a particle outside the
// domain without saying why it is there.
void CaseReader::check_buffer_clear_of_walls(const TomlTableReader& r, const OpenBoundarySpec& ob,
                                             std::string_view kind) const {
  const int axis = ob.face / 2;
  const bool at_min = ob.face % 2 == 0;
  const DomainSpec& d = spec_.domain;
  const double dp = spec_.simulation.dp;
  const double width = ob.layers * dp;
  const double buffer_lo = at_min ? d.min[axis] : d.max[axis] - width;
  const double buffer_hi = at_min ? d.min[axis] + width : d.max[axis];
  for (const WallSpec& wall : spec_.walls) {
    if (!wall.faces[static_cast<std::size_t>(ob.face)]) continue;
    // That face's layers lie on the box's outer side of its plane.
    const double plane = at_min ? wall.box.min[axis] : wall.box.max[axis];
    const double layers = wall.layers * dp;
    const double lo = at_min ? plane - layers : plane;
    const double hi = at_min ? plane : plane + layers;
    // Across the buffer, or beyond the open face (outside [domain], where the inflow comes from).
    const double inf = std::numeric_limits<double>::infinity();
    const double reach_lo = at_min ? -inf : buffer_lo, reach_hi = at_min ? buffer_hi : inf;
    if (std::min(hi, reach_hi) - std::max(lo, reach_lo) <= 0.25 * dp) continue;
    bool across = true;  // the wall's face and the open face overlap across the other axes
    for (int b = 0; b < 3; ++b) {
      if (b == axis || (is_2d() && b == 1)) continue;
      across = across && wall.box.min[b] < d.max[b] && wall.box.max[b] > d.min[b];
    }
    if (!across) continue;
    r.fail_value(
        "face", *r.find("face"),
        fmt::format("wall \"{}\" ({}) has face \"{}\" at {} = {} m: its particle layers ({} .. {} "
                    "m) would lie across this {}'s buffer ({} .. {} m) and close it; remove \"{}\" "
                    "from that wall's faces (without a faces key a wall has all of them)",
                    wall.name, wall.where.str(), name_of(ob.face), "xyz"[axis],
                    format_number(plane), format_derived(lo), format_derived(hi), kind,
                    format_derived(buffer_lo), format_derived(buffer_hi), name_of(ob.face)));
  }
}

void CaseReader::check_buffer(const TomlTableReader& r, const OpenBoundarySpec& ob) {
  const double width = ob.layers * spec_.simulation.dp;
  const toml::node* layers = r.find("layers");
  const int needed = support_layers();
  if (ob.layers < needed) {
    const std::string why = fmt::format(
        "the buffer must cover the kernel support {} so that the fluid next to it sees a full "
        "kernel",
        support_text());
    // The default layers always suffice, so `layers` was given.
    r.fail_value("layers", *layers,
                 fmt::format("{}, but layers * dp = {} m; use layers >= {}", why,
                             format_derived(width), needed));
  }
  const int axis = ob.face / 2;
  const DomainSpec& d = spec_.domain;
  const double extent = d.max[axis] - d.min[axis];
  const std::size_t opposite = static_cast<std::size_t>(ob.face ^ 1);
  if (width < extent && width + open_widths_[opposite] >= extent) {
    const std::string message = fmt::format(
        "this buffer ({} m) and the one of {} on the opposite face ({} m) together span the "
        "whole domain along {} ({} m): no fluid would lie between them; use fewer layers or a "
        "longer domain",
        format_derived(width), open_faces_[opposite]->label, format_derived(open_widths_[opposite]),
        "xyz"[axis], format_derived(extent));
    if (layers) r.fail_value("layers", *layers, message);
    r.fail_value("face", *r.find("face"), message);
  }
  open_widths_[static_cast<std::size_t>(ob.face)] = width;
  if (width < extent) return;
  const std::string message = fmt::format(
      "the buffer ({} layers x simulation.dp = {} m: {} m) must be narrower than the domain "
      "along {}, which is {} m from [domain] min to max; use a smaller dp or fewer layers",
      ob.layers, format_number(spec_.simulation.dp), format_derived(width), "xyz"[axis],
      format_derived(extent));
  if (layers) r.fail_value("layers", *layers, message);
  r.fail_value("face", *r.find("face"), message);
}

void CaseReader::read_open_velocity(const TomlTableReader& r, bool inlet,
                                    OpenBoundarySpec& ob) const {
  const toml::node* velocity = r.find("velocity");
  const toml::node* profile = inlet ? r.find("profile") : nullptr;
  if (velocity && profile) {
    r.fail_value("profile", *profile,
                 fmt::format("cannot be combined with {}: give a uniform velocity or a profile "
                             "over z, not both",
                             r.key_path("velocity")));
  }
  if (velocity) {
    const double u = r.to_number("velocity", *velocity, velocity_rule());
    if (u <= 0) {
      r.fail_value("velocity", *velocity,
                   inlet ? "must be > 0 m/s: it is the inflow speed normal to the face, into "
                           "the domain (give |u|; the face sets the direction)"
                         : "must be > 0 m/s: it is the outflow speed normal to the face, out of "
                           "the domain (give |u|; leave velocity out to extrapolate it from the "
                           "fluid)");
    }
    ob.velocity = u;
  } else if (profile) {
    read_profile(r, ob);
  } else if (inlet) {
    r.fail_table(
        fmt::format("{} needs an inflow velocity: give velocity = <m/s> (uniform, > 0) "
                    "or profile = {{ z = [...], u = [...] }}",
                    r.title()));
  }
}

void CaseReader::read_profile(const TomlTableReader& r, OpenBoundarySpec& ob) const {
  const toml::node& node = *r.find("profile");
  const toml::table& table = r.nested_table(
      "profile", node,
      "must be a table such as { z = [0, 0.3], u = [0.4, 0.6] } (heights in m, speeds in m/s)");
  if (ob.face == kZMin || ob.face == kZMax) {
    r.fail_value(
        "profile", node,
        fmt::format("a profile over z needs a vertical face ({}), not \"{}\"; give a "
                    "uniform velocity on a horizontal face",
                    is_2d() ? "xmin or xmax" : "xmin, xmax, ymin or ymax", name_of(ob.face)));
  }
  const std::string path = r.key_path("profile");
  TomlTableReader p(table, path, path, kProfileKeys, source_);
  const toml::node& z = p.require("z", "heights in m, at least 2, strictly increasing");
  ob.profile_z = p.to_number_array("z", z, coordinate_rule(), 2);
  check_increasing(p, "z", z, ob.profile_z);
  const toml::node& u = p.require("u", "inflow speeds in m/s, >= 0, one per height");
  ob.profile_u = p.to_number_array("u", u, NumberRule::closed(0, kMostSpeed, "m/s"), 2);
  if (ob.profile_u.size() != ob.profile_z.size()) {
    p.fail_value("u", u,
                 fmt::format("must hold one speed per height: {}.z has {} elements, u has {}", path,
                             ob.profile_z.size(), ob.profile_u.size()));
  }
  if (*std::max_element(ob.profile_u.begin(), ob.profile_u.end()) == 0) {
    p.fail_value("u", u, "must have at least one speed > 0: the inlet lets fluid in");
  }
}

}  // namespace netsph::case_detail
