// The case-file schema: with case_reader_boundaries.cpp ([[wall]], [[inlet]], [[outlet]]) and
// case_reader_bodies.cpp ([[body]]), the only place that maps TOML keys to CaseSpec fields. Each
// table is read by a TomlTableReader that rejects unknown keys first, then reads and range-checks
// the keys in a fixed order; cross-key rules (boxes, 2D, domain) come after the keys they use.
// docs/case-reference.md documents every key; keep the two in step.
#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "netsph/case/case_overrides.hpp"
#include "netsph/case/case_reader.hpp"
#include "netsph/case/case_reader_impl.hpp"
#include "netsph/case/toml_table_reader.hpp"
#include "netsph/core/error.hpp"

namespace netsph {
namespace case_detail {

namespace {

const std::vector<std::string_view> kViscosityKeys = {"model", "alpha", "kinematic_viscosity"};
const std::vector<std::string_view> kDiffusionKeys = {"model", "delta"};
const std::vector<std::string_view> kShiftingKeys = {"model", "coefficient", "surface_threshold"};
const std::vector<std::string_view> kHistoryKeys = {"times", "velocities"};

}  // namespace

// ---- the reader ---------------------------------------------------------------------------

CaseSpec CaseReader::read(const std::string& default_name) {
  spec_.source = source_.name();
  check_top_level();
  read_simulation(default_name);
  reject_nets_in_2d();
  read_fluid();
  read_domain();
  read_fills();
  require_dp();
  read_walls();
  read_open_boundaries(true);
  read_open_boundaries(false);
  check_periodic_open_faces();
  read_bodies();
  read_nets();
  reject_fluid_tables_without_fluid();
  read_current();
  read_probes();
  read_waves();
  read_damping();
  read_gauges();
  // Shifting keeps the particle distribution regular where open boundaries add and remove
  // particles; a closed case does without unless asked.
  if (!shifting_given_ && (!spec_.inlets.empty() || !spec_.outlets.empty())) {
    spec_.fluid.shifting = ShiftingModel::Fickian;
  }
  read_output();
  return std::move(spec_);
}

int CaseReader::support_layers() const {
  // The tolerance keeps h_over_dp = 1.5 at 3 layers despite rounding.
  return static_cast<int>(std::ceil(2 * spec_.simulation.h_over_dp - 1e-9));
}

std::string CaseReader::support_text() const {
  const SimulationSpec& s = spec_.simulation;
  return fmt::format("2h = {} m ({} dp at h_over_dp = {})", format_derived(2 * s.h_over_dp * s.dp),
                     format_derived(2 * s.h_over_dp), format_number(s.h_over_dp));
}

void CaseReader::fail_root(const std::string& message) const {
  throw Error(source_.where(root_.source()), message);
}

void CaseReader::check_top_level() const {
  std::vector<std::string_view> allowed;
  std::vector<std::string> headers;
  for (const auto& t : schema()) {
    allowed.push_back(t.table);
    headers.push_back(header_of(t.table));
  }
  const auto [first, first_value] = first_unknown_key(root_, allowed);
  if (!first) return;
  const std::string_view name = first->str();
  std::string what;
  if (first_value->is_table()) {
    what = fmt::format("unknown table [{}]", name);
  } else if (first_value->is_array_of_tables()) {
    what = fmt::format("unknown table [[{}]]", name);
  } else {
    what = fmt::format("unknown top-level key '{}'", name);
  }
  std::string suggestion = did_you_mean(name, allowed);
  if (suggestion.empty()) {
    const std::string home = home_hint(name);
    if (!home.empty()) suggestion = " (" + home + ")";
  }
  throw Error(source_.where(key_region(*first, *first_value)),
              fmt::format("{}{}; allowed tables: {}", what, suggestion,
                          join(std::vector<std::string_view>(headers.begin(), headers.end()))));
}

const toml::table* CaseReader::find_table(std::string_view name) const {
  const toml::node* node = root_.get(name);
  if (!node) return nullptr;
  if (const auto* table = node->as_table()) return table;
  const std::string message =
      node->is_array_of_tables()
          ? fmt::format("[{}] must be a single table: write [{}], not [[{}]]", name, name, name)
          : fmt::format("{} must be a table: write [{}] followed by its keys, not {}", name, name,
                        type_name(*node));
  throw Error(source_.where(node->source()), message);
}

std::vector<const toml::table*> CaseReader::find_array_of_tables(std::string_view name) const {
  std::vector<const toml::table*> tables;
  const toml::node* node = root_.get(name);
  if (!node) return tables;
  const auto* array = node->as_array();
  if (!array || (!array->empty() && !array->is_array_of_tables())) {
    throw Error(source_.where(node->source()),
                fmt::format("{} must be an array of tables: write [[{}]] (double brackets) once "
                            "per entry, not {}",
                            name, name,
                            node->is_table() ? "[" + std::string(name) + "]"
                                             : std::string(type_name(*node))));
  }
  for (const toml::node& element : *array) tables.push_back(element.as_table());
  return tables;
}

// ---- [simulation] -------------------------------------------------------------------------

void CaseReader::read_simulation(const std::string& default_name) {
  const toml::table* table = find_table("simulation");
  if (!table) fail_root("missing required table [simulation] (it needs at least dp and end_time)");
  TomlTableReader r(*table, "simulation", "[simulation]", keys_of("simulation"), source_,
                    home_hint);
  SimulationSpec& s = spec_.simulation;
  s.name = r.string("name", default_name);
  if (r.has("name") && s.name.empty()) r.fail_value("name", *r.find("name"), "must not be empty");
  // The name is the default output folder (out/<name>): a path in it would write elsewhere.
  const bool escapes =
      s.name == "." || s.name == ".." || s.name.find_first_of("/\\:") != std::string::npos;
  if (r.has("name") && escapes) {
    r.fail_value("name", *r.find("name"),
                 "must not be a path: no '/', '\\' or ':', and not '.' or '..' (the run writes "
                 "to out/<name> unless -o names a folder)");
  }
  // The name becomes a folder name that users type, list and pass to scripts, so it is held to a
  // portable set (POSIX's portable file name characters): letters, digits, '_', '-' and '.',
  // not starting with '-' (read as an option) or '.' (a hidden folder). Anything else made
  // folders that fail or mislead: a control character (a NUL cuts the name short, a newline
  // splits it), a bidirectional override (U+202E shows "exe.txt" for "txt.exe"), a zero-width
  // or other format character, a blank at an end, a non-ASCII letter in another normalisation
  // (two names that look the same), a name longer than file systems allow.
  constexpr std::size_t kLongestName = 200;
  const auto portable = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) && static_cast<unsigned char>(c) < 0x80;
  };
  const bool safe = !s.name.empty() && s.name.size() <= kLongestName && s.name.front() != '-' &&
                    s.name.front() != '.' && std::all_of(s.name.begin(), s.name.end(), [&](char c) {
                      return portable(c) || c == '_' || c == '-' || c == '.';
                    });
  if (r.has("name") && !safe) {
    r.fail_value("name", *r.find("name"),
                 fmt::format("must be a folder name of ASCII letters, digits, '_', '-' and '.', "
                             "not starting with '-' or '.', at most {} bytes (the run writes to "
                             "out/<name> unless -o names a folder)",
                             kLongestName));
  }
  s.dimensions = static_cast<int>(r.integer("dimensions", IntRule{2, 3}, 3));
  s.dp = r.number("dp", NumberRule::closed(kSmallestDp, kLargestDp, "m"),
                  0.0);  // required unless net-only: require_dp
  s.h_over_dp = r.number("h_over_dp", NumberRule::closed(1, 3, ""), s.h_over_dp);
  s.kernel = r.choice("kernel", kKernelTypeNames, s.kernel);
  s.end_time = r.required_number("end_time", NumberRule::left_open(0, kLongestEndTime, "s"),
                                 "simulated time, s, > 0");
  s.cfl = r.number("cfl", NumberRule::left_open(0, 1, ""), s.cfl);
  s.dt_min = r.number("dt_min", NumberRule::non_negative("s"), s.dt_min);
  s.dt_max = r.number("dt_max", NumberRule::non_negative("s"), s.dt_max);
  s.max_lost_fraction =
      r.number("max_lost_fraction", NumberRule::closed(0, 1, ""), s.max_lost_fraction);
  if (s.dt_min > 0 && s.dt_max > 0 && s.dt_max <= s.dt_min) {
    r.fail_value("dt_max", *r.find("dt_max"),
                 fmt::format("must be > simulation.dt_min ({} s) when both are set",
                             format_number(s.dt_min)));
  }
}

void CaseReader::reject_fluid_tables_without_fluid() const {
  if (!spec_.net_only()) return;
  for (const std::string_view name : {"wall", "inlet", "outlet", "body"}) {
    const std::vector<const toml::table*> tables = find_array_of_tables(name);
    if (tables.empty()) continue;
    throw Error(source_.where(tables[0]->source()),
                fmt::format("[[{}]] acts on the SPH fluid, and this case has none (no [[fill]]: a "
                            "standalone net in a uniform [current]); add a [[fill]] or remove it",
                            name));
  }
}

void CaseReader::require_dp() const {
  if (spec_.simulation.dp > 0) return;
  if (spec_.fills.empty() && root_.contains("net")) return;  // a standalone net
  TomlTableReader r(*find_table("simulation"), "simulation", "[simulation]", keys_of("simulation"),
                    source_, home_hint);
  r.require("dp", "particle spacing, m, > 0");
}

// ---- [fluid] ------------------------------------------------------------------------------

void CaseReader::read_fluid() {
  const toml::table* table = find_table("fluid");
  if (!table) return;  // every key has a default
  TomlTableReader r(*table, "fluid", "[fluid]", keys_of("fluid"), source_, home_hint);
  FluidSpec& f = spec_.fluid;
  f.density = r.number("density", NumberRule::closed(1, 1e5, "kg/m^3"), f.density);
  f.sound_speed =
      r.number("sound_speed", NumberRule::left_open(0, kMostSoundSpeed, "m/s"), f.sound_speed);
  f.sound_speed_coef =
      r.number("sound_speed_coef", NumberRule::closed(1, 1000, ""), f.sound_speed_coef);
  if (r.has("sound_speed") && r.has("sound_speed_coef")) {
    r.fail_value("sound_speed_coef", *r.find("sound_speed_coef"),
                 "cannot be combined with fluid.sound_speed: give c0 either directly "
                 "(sound_speed, m/s) or as coef * sqrt(|g| H) (sound_speed_coef), not both");
  }
  f.gamma = r.number("gamma", NumberRule::closed(1, 10, ""), f.gamma);
  f.background_pressure =
      r.number("background_pressure", NumberRule::closed(0, 1e8, "Pa"), f.background_pressure);
  f.gravity = read_in_plane_vector(r, "gravity", gravity_rule(), f.gravity);
  if (const toml::node* node = r.find("structure_gravity")) {
    if (norm2(f.gravity) > 0) {
      r.fail_value("structure_gravity", *node,
                   fmt::format("needs fluid.gravity = [0, 0, 0] (it is {}): with gravity in the "
                               "fluid, bodies and nets feel their buoyancy through its pressure "
                               "and their weight from gravity itself",
                               format_vec3(f.gravity)));
    }
    f.structure_gravity = read_in_plane_vector(r, "structure_gravity", gravity_rule(), Vec3d{});
  }
  read_viscosity(r);
  read_density_diffusion(r);
  read_shifting(r);
}

void CaseReader::read_viscosity(const TomlTableReader& fluid) {
  const toml::node* node = fluid.find("viscosity");
  if (!node) return;
  FluidSpec& f = spec_.fluid;
  if (node->is_string()) {  // bare model name: default parameters
    f.viscosity = fluid.to_choice("viscosity", *node, kViscosityModelNames);
    return;
  }
  const toml::table& table =
      fluid.nested_table("viscosity", *node,
                         "must be \"artificial\", \"laminar\" or a table such as { model = "
                         "\"laminar\", kinematic_viscosity = 1e-6 }");
  TomlTableReader r(table, "fluid.viscosity", "fluid.viscosity", kViscosityKeys, source_);
  f.viscosity = r.choice("model", kViscosityModelNames, f.viscosity);
  if (f.viscosity == ViscosityModel::Laminar) {
    reject_foreign_parameter(r, "alpha", name_of(f.viscosity), "\"artificial\"",
                             "model, kinematic_viscosity");
    f.kinematic_viscosity = r.number("kinematic_viscosity", NumberRule::left_open(0, 1, "m^2/s"),
                                     f.kinematic_viscosity);
  } else {
    reject_foreign_parameter(r, "kinematic_viscosity", name_of(f.viscosity), "\"laminar\"",
                             "model, alpha");
    f.alpha = r.number("alpha", NumberRule::closed(0, 1, ""), f.alpha);
  }
}

void CaseReader::read_density_diffusion(const TomlTableReader& fluid) {
  const toml::node* node = fluid.find("density_diffusion");
  if (!node) return;
  FluidSpec& f = spec_.fluid;
  if (node->is_string()) {
    f.density_diffusion = fluid.to_choice("density_diffusion", *node, kDensityDiffusionNames);
    return;
  }
  const toml::table& table =
      fluid.nested_table("density_diffusion", *node,
                         "must be \"none\", \"molteni\", \"fourtakas\" or a table such as { model "
                         "= \"molteni\", delta = 0.1 }");
  TomlTableReader r(table, "fluid.density_diffusion", "fluid.density_diffusion", kDiffusionKeys,
                    source_);
  f.density_diffusion = r.choice("model", kDensityDiffusionNames, f.density_diffusion);
  if (f.density_diffusion == DensityDiffusion::None) {
    reject_foreign_parameter(r, "delta", name_of(f.density_diffusion),
                             "\"molteni\" and \"fourtakas\"", "model");
  } else {
    f.delta = r.number("delta", NumberRule::closed(0, 1, ""), f.delta);
  }
}

void CaseReader::read_shifting(const TomlTableReader& fluid) {
  const toml::node* node = fluid.find("shifting");
  if (!node) return;  // the default depends on the open boundaries: see read()
  shifting_given_ = true;
  FluidSpec& f = spec_.fluid;
  if (node->is_string()) {
    f.shifting = fluid.to_choice("shifting", *node, kShiftingModelNames);
    return;
  }
  const toml::table& table = fluid.nested_table("shifting", *node,
                                                "must be \"none\", \"fickian\" or a table such as "
                                                "{ model = \"fickian\", coefficient = 2.0 }");
  TomlTableReader r(table, "fluid.shifting", "fluid.shifting", kShiftingKeys, source_);
  // Parameters only exist for "fickian", so a table without a model means it.
  f.shifting = r.choice("model", kShiftingModelNames, ShiftingModel::Fickian);
  if (f.shifting == ShiftingModel::None) {
    for (const std::string_view key : {"coefficient", "surface_threshold"}) {
      reject_foreign_parameter(r, key, name_of(f.shifting), "\"fickian\"", "model");
    }
  } else {
    f.shifting_coefficient =
        r.number("coefficient", NumberRule::left_open(0, 10, ""), f.shifting_coefficient);
    f.shifting_surface_threshold =
        r.number("surface_threshold", NumberRule::closed(0, 3, ""), f.shifting_surface_threshold);
  }
}

// ---- geometry helpers ---------------------------------------------------------------------

Vec3d CaseReader::read_position(const TomlTableReader& r, std::string_view key,
                                std::string_view meaning) const {
  Vec3d p = r.required_vec3(key, coordinate_rule(), meaning);
  if (is_2d()) p.y = 0;  // y is ignored in 2D: normalise so later stages need not care
  return p;
}

/// A vector whose y must be 0 in 2D (gravity, velocity): a y component would be silently
/// lost, so it is an error rather than ignored.
Vec3d CaseReader::read_in_plane_vector(const TomlTableReader& r, std::string_view key,
                                       const NumberRule& rule, Vec3d fallback) const {
  const toml::node* node = r.find(key);
  if (!node) return fallback;
  const Vec3d v = r.to_vec3(key, *node, rule);
  check_in_plane(r, key, *node, v);
  return v;
}

void CaseReader::check_in_plane(const TomlTableReader& r, std::string_view key,
                                const toml::node& node, const Vec3d& v) const {
  if (is_2d() && v.y != 0) {
    r.fail_value(key, node, fmt::format("y must be 0 because {}", kPlaneReason),
                 node.as_array()->get(1));
  }
}

VelocityHistory CaseReader::read_velocity_history(const TomlTableReader& r,
                                                  std::string_view velocity_key,
                                                  std::string_view history_key) const {
  VelocityHistory history;
  const toml::node* velocity = r.find(velocity_key);
  const toml::node* node = r.find(history_key);
  if (velocity && node) {
    r.fail_value(history_key, *node,
                 fmt::format("cannot be combined with {}: give either a constant {} = "
                             "[u, v, w] or a {} = {{ times = [...], velocities = [...] }}, "
                             "not both",
                             r.key_path(velocity_key), velocity_key, history_key));
  }
  if (velocity) {
    history.times = {0.0};
    history.velocities = {read_in_plane_vector(r, velocity_key, velocity_rule(), {})};
    return history;
  }
  if (!node) return history;
  const toml::table& table = r.nested_table(
      history_key, *node,
      "must be a table such as { times = [0, 1], velocities = [[0, 0, 0], [0.5, 0, 0]] }");
  const std::string path = r.key_path(history_key);
  TomlTableReader m(table, path, path, kHistoryKeys, source_);
  const toml::node& times = m.require("times", "instants in s, >= 0, strictly increasing");
  history.times = m.to_number_array("times", times, NumberRule::non_negative("s"), 1);
  check_increasing(m, "times", times, history.times);
  const toml::node& velocities = m.require("velocities", "one [u, v, w] in m/s per time");
  const auto* array = velocities.as_array();
  if (!array) {
    m.fail_value("velocities", velocities,
                 fmt::format("must be an array of [u, v, w] vectors in m/s, one per time, not {}",
                             type_name(velocities)));
  }
  if (array->size() != history.times.size()) {
    m.fail_value("velocities", velocities,
                 fmt::format("must hold one [u, v, w] per time: {}.times has {} element{}, "
                             "velocities has {}",
                             path, history.times.size(), history.times.size() == 1 ? "" : "s",
                             array->size()));
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    const std::string key = fmt::format("velocities[{}]", i + 1);
    const toml::node& element = (*array)[i];
    const Vec3d v = m.to_vec3(key, element, velocity_rule());
    check_in_plane(m, key, element, v);
    history.velocities.push_back(v);
  }
  return history;
}

BoxSpec CaseReader::read_box(const TomlTableReader& r, std::string_view what) const {
  BoxSpec box;
  box.min = read_position(r, "min", fmt::format("lower corner [x, y, z] of {}, m", what));
  box.max = read_position(r, "max", fmt::format("upper corner [x, y, z] of {}, m", what));
  for (const int axis : used_axes()) {
    if (box.max[axis] > box.min[axis]) continue;
    const char name = "xyz"[axis];
    r.fail_value("max", *r.find("max"),
                 fmt::format("must be > {} = {} on {} ({}: {} <= {})", r.key_path("min"),
                             format_vec3(box.min), is_2d() ? "x and z" : "x, y and z", name,
                             format_number(box.max[axis]), format_number(box.min[axis])));
  }
  return box;
}

// ---- [domain] -----------------------------------------------------------------------------

void CaseReader::read_domain() {
  const toml::table* table = find_table("domain");
  if (!table) return;
  TomlTableReader r(*table, "domain", "[domain]", keys_of("domain"), source_, home_hint);
  const BoxSpec box = read_box(r, "the domain");
  spec_.domain = {true, box.min, box.max, read_periodic(r)};
}

std::array<bool, 3> CaseReader::read_periodic(const TomlTableReader& r) const {
  std::array<bool, 3> periodic{};
  const toml::node* node = r.find("periodic");
  if (!node) return periodic;
  // min and max are required keys of [domain], so a periodic axis always has its extent.
  const WordListRule rule{
      .noun = "axis",
      .known = {"x", "y", "z"},
      .allowed = is_2d() ? std::vector<std::string_view>{"x", "z"}
                         : std::vector<std::string_view>{"x", "y", "z"},
      .not_allowed_reason = kNotIn2D,
      .example = "[\"x\"] or [\"x\", \"y\"]",
      .allow_empty = true,
  };
  for (const std::size_t axis : r.to_word_list("periodic", *node, rule)) periodic[axis] = true;
  return periodic;
}

// ---- [[fill]] -----------------------------------------------------------------------------

void CaseReader::read_fills() {
  const std::vector<const toml::table*> tables = find_array_of_tables("fill");
  if (tables.empty() && !root_.contains("net")) {
    fail_root(
        "a case needs fluid: add at least one [[fill]] table with min and max corners (or, "
        "for a standalone net run, [[net]] tables and a [current])");
  }
  for (std::size_t i = 0; i < tables.size(); ++i) {
    spec_.fills.push_back(read_fill(*tables[i], static_cast<int>(i) + 1));
  }
}

FillSpec CaseReader::read_fill(const toml::table& table, int number) const {
  const std::string name = fmt::format("fill[{}]", number);
  TomlTableReader r(table, name, name, keys_of("fill"), source_, home_hint);
  FillSpec fill;
  fill.where = r.location();
  fill.box = read_box(r, "the fluid box");
  fill.velocity = read_in_plane_vector(r, "velocity", velocity_rule(), fill.velocity);
  fill.surface_z = r.optional_number("surface_z", coordinate_rule());
  if (fill.surface_z && *fill.surface_z < fill.box.min.z) {
    r.fail_value("surface_z", *r.find("surface_z"),
                 fmt::format("must be >= the box's min z ({} m): the free surface cannot lie "
                             "below the fluid",
                             format_number(fill.box.min.z)));
  }
  check_box_fits_lattice(r, fill.box);
  if (spec_.domain.given) check_fill_in_domain(r, fill.box);
  return fill;
}

// A lattice axis is counted in int; a wall adds up to 10 layers on each side.
constexpr double kMaxLatticeSpacings = 2147483647.0 - 20;

void CaseReader::check_box_fits_lattice(const TomlTableReader& r, const BoxSpec& box) const {
  const double dp = spec_.simulation.dp;
  if (!(dp > 0)) return;  // a net-only case has no lattice
  for (const int axis : used_axes()) {
    const char name = "xyz"[axis];
    const double len = box.max[axis] - box.min[axis];
    const double spacings = std::round(len / dp);
    if (spacings < 1) {
      r.fail_table(fmt::format(
          "{} is {} m long on {}, less than half of simulation.dp = {} m: it rounds to no "
          "particle; use dp <= {} m or a longer box",
          r.title(), format_number(len), name, format_number(dp), format_number(2 * len)));
    }
    if (spacings > kMaxLatticeSpacings) {
      r.fail_table(
          fmt::format("{} is {:.3g} particle spacings long on {} (simulation.dp = {} "
                      "m): more than a lattice axis holds (2^31 - 21); use a larger dp",
                      r.title(), spacings, name, format_number(dp)));
    }
  }
}

void CaseReader::check_fill_in_domain(const TomlTableReader& r, const BoxSpec& box) const {
  const DomainSpec& d = spec_.domain;
  for (const int axis : used_axes()) {
    const char name = "xyz"[axis];
    std::string problem;
    if (box.min[axis] < d.min[axis]) {
      problem = fmt::format("its min {} = {} < domain min {} = {}", name,
                            format_number(box.min[axis]), name, format_number(d.min[axis]));
    } else if (box.max[axis] > d.max[axis]) {
      problem = fmt::format("its max {} = {} > domain max {} = {}", name,
                            format_number(box.max[axis]), name, format_number(d.max[axis]));
    }
    if (problem.empty()) continue;
    r.fail_table(fmt::format("{} (min {}, max {}) is not inside [domain] (min {}, max {}): {}",
                             r.title(), format_vec3(box.min), format_vec3(box.max),
                             format_vec3(d.min), format_vec3(d.max), problem));
  }
}

// ---- [output] -----------------------------------------------------------------------------

void CaseReader::read_output() {
  const toml::table* table = find_table("output");
  if (!table) return;
  TomlTableReader r(*table, "output", "[output]", keys_of("output"), source_, home_hint);
  OutputSpec& o = spec_.output;
  o.snapshots = r.boolean("snapshots", o.snapshots);
  o.snapshot_every = r.number("snapshot_every", NumberRule::non_negative("s"), o.snapshot_every);
  if (o.snapshot_every > spec_.simulation.end_time) {
    r.fail_value("snapshot_every", *r.find("snapshot_every"),
                 fmt::format("must be <= simulation.end_time ({} s), or 0 for automatic",
                             format_number(spec_.simulation.end_time)));
  }
  o.series_every = r.number("series_every", NumberRule::non_negative("s"), o.series_every);
  o.checkpoint_every =
      r.number("checkpoint_every", NumberRule::non_negative("s"), o.checkpoint_every);
  o.gauge_every = r.number("gauge_every", NumberRule::non_negative("s"), o.gauge_every);
  if (o.gauge_every > spec_.simulation.end_time) {
    r.fail_value("gauge_every", *r.find("gauge_every"),
                 fmt::format("must be <= simulation.end_time ({} s), or 0 for automatic",
                             format_number(spec_.simulation.end_time)));
  }
  read_force_window(r);
  read_snapshot_region(r);
  // A standalone net run has no particles: no checkpoint (it runs in seconds and starts again
  // as fast) and no particle snapshots to cut down. Said rather than ignored.
  if (spec_.net_only()) {
    for (const std::string_view key : {"checkpoint_every", "snapshot_region", "gauge_every"}) {
      if (const toml::node* node = r.find(key)) {
        r.fail_value(key, *node,
                     "does not apply to a standalone net case (no fluid, no particles): it "
                     "writes no checkpoint, no particle snapshots and no gauges; remove the key");
      }
    }
  }
}

void CaseReader::read_snapshot_region(const TomlTableReader& r) {
  const toml::node* node = r.find("snapshot_region");
  if (!node) return;
  const toml::table& table =
      r.nested_table("snapshot_region", *node,
                     "must be a table such as { min = [x, y, z], max = [x, y, z] } (the box whose "
                     "particles the snapshots hold, m)");
  static const std::vector<std::string_view> keys = {"min", "max"};
  const std::string path = r.key_path("snapshot_region");
  TomlTableReader t(table, path, path, keys, source_);
  const BoxSpec box = read_box(t, "the snapshot region");
  const DomainSpec& d = spec_.domain;
  if (d.given) {
    for (const int axis : used_axes()) {
      if (box.max[axis] > d.min[axis] && box.min[axis] < d.max[axis]) continue;
      r.fail_value("snapshot_region", *node,
                   fmt::format("lies outside [domain] (min {}, max {}) on {}: the snapshots "
                               "would hold no particle",
                               format_vec3(d.min), format_vec3(d.max), "xyz"[axis]));
    }
  }
  spec_.output.snapshot_region = box;
}

void CaseReader::read_force_window(const TomlTableReader& r) {
  const toml::node* node = r.find("force_window");
  if (!node) return;
  const std::vector<double> t =
      r.to_number_array("force_window", *node, NumberRule::non_negative("s"), 2);
  const toml::array& array = *node->as_array();
  if (t.size() != 2) {
    r.fail_value(
        "force_window", *node,
        fmt::format("must be [t0, t1]: a start and an end time in s, got {} elements", t.size()));
  }
  if (t[1] <= t[0]) {
    r.fail_value("force_window", *node,
                 fmt::format("must have t0 < t1, but t1 = {} <= t0 = {}", format_number(t[1]),
                             format_number(t[0])),
                 array.get(1));
  }
  const double end_time = spec_.simulation.end_time;
  if (t[1] > end_time) {
    r.fail_value("force_window", *node,
                 fmt::format("t1 = {} must be <= simulation.end_time ({} s)", format_number(t[1]),
                             format_number(end_time)),
                 array.get(1));
  }
  spec_.output.force_window = std::array<double, 2>{t[0], t[1]};
}

}  // namespace case_detail

// ---- entry points -------------------------------------------------------------------------

namespace {

/// toml++ 3 limits the nesting of arrays and inline tables (256) but walks a dotted key's parts
/// recursively without a limit: a key of 50,000 parts overflowed the stack (SIGSEGV). No case
/// key has more than a few parts, so a key of more than 256 is refused, with its line, before
/// toml++ sees it. Counts the dots outside quotes before a line's first '=', '#', ',', ']' or
/// '{': those of a key or a [table.header], and at most one number's of an array's
/// continuation line ("0.1, 0.2,"); a line of a multi-line string would need 256 dots before
/// any of those characters to be misread.
void check_dotted_key_depth(std::string_view text, const std::string& source_name) {
  constexpr int kMostParts = 256;
  int line = 1, dots = 0;
  bool in_key = true;
  char quote = 0;
  for (const char c : text) {
    if (c == '\n') {
      ++line, dots = 0, in_key = true, quote = 0;
      continue;
    }
    if (!in_key) continue;
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '=' || c == '#' || c == ',' || c == ']' || c == '{') {
      in_key = false;
    } else if (c == '.' && ++dots >= kMostParts) {
      throw Error(fmt::format("{}:{}:1", source_name, line),
                  fmt::format("a dotted key of more than {} parts: no case key has more than a "
                              "few (e.g. fluid.viscosity.alpha)",
                              kMostParts));
    }
  }
}

toml::table parse_toml(std::string_view text, const std::string& source_name) {
  check_dotted_key_depth(text, source_name);
  try {
    return toml::parse(text, std::string(source_name));
  } catch (const toml::parse_error& e) {
    const TomlSource source(source_name);
    throw Error(source.where(e.source()), fmt::format("TOML syntax error: {}", e.description()));
  }
}

CaseSpec read_case(std::string_view text, const std::string& source_name,
                   const std::vector<std::string>& overrides, const std::string& default_name) {
  toml::table root = parse_toml(text, source_name);
  apply_overrides(root, overrides);
  const TomlSource source(source_name);
  CaseSpec spec = case_detail::CaseReader(root, source).read(default_name);
  spec.overrides = overrides;
  return spec;
}

}  // namespace

CaseSpec read_case_file(const std::filesystem::path& path,
                        const std::vector<std::string>& overrides) {
  const std::string text = read_file_text(path);
  return read_case(text, path.string(), overrides, path.stem().string());
}

CaseSpec read_case_string(std::string_view toml_text, const std::string& source_name,
                          const std::vector<std::string>& overrides,
                          const std::string& default_name) {
  return read_case(toml_text, source_name, overrides,
                   default_name.empty() ? source_name : default_name);
}

}  // namespace netsph
