// The [[net]] tables and the [current] table of a case file: nets generated from real netting
// data (net/net_generator.hpp) and the uniform current of a standalone net run. Same
// conventions as case_reader.cpp; docs/case-reference.md documents every key.
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "netsph/case/case_reader_impl.hpp"
#include "netsph/core/error.hpp"

namespace netsph::case_detail {
namespace {

const std::vector<std::string_view> kSinkerKeys = {"length", "diameter", "density",
                                                   "drag_coefficient"};
const std::vector<std::string_view> kPointLoadKeys = {"row", "column", "force"};

/// Twine materials: density, kg/m^3, and a typical Young's modulus of net twine, Pa (for
/// nets whose stiffness is not known; the deflection of a net in a current hardly depends on
/// it, the strains being below 1%). "custom" needs material_density and a stiffness.
struct Material {
  std::string_view name;
  double density;
  double youngs_modulus;
};
constexpr std::array<Material, 4> kMaterials = {{{"nylon", 1140, 1.2e9},
                                                 {"polyethylene", 950, 1.0e9},
                                                 {"polyester", 1380, 2.5e9},
                                                 {"custom", 0, 0}}};

}  // namespace

// ---- [[net]] ------------------------------------------------------------------------------

void CaseReader::reject_nets_in_2d() const {
  if (!is_2d()) return;
  const std::vector<const toml::table*> tables = find_array_of_tables("net");
  if (tables.empty()) return;
  TomlTableReader r(*tables[0], "net[1]", "net[1]", keys_of("net"), source_, home_hint);
  r.fail_table("nets need simulation.dimensions = 3 (a net is a surface of knots and twines)");
}

void CaseReader::read_nets() {
  const std::vector<const toml::table*> tables = find_array_of_tables("net");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const int number = static_cast<int>(i) + 1;
    NetSpec net = read_net(*tables[i], number);
    for (const NetSpec& other : spec_.nets) {
      if (other.name != net.name) continue;
      const toml::node* name_node = tables[i]->get("name");
      throw Error(source_.where(name_node ? name_node->source() : tables[i]->source()),
                  fmt::format("net name \"{}\" is used twice: by {} and net[{}]; net names must "
                              "be unique",
                              net.name, other.where.str(), number));
    }
    // A net's knots become bodies of its name's force group: a wall, boundary or body of the
    // same name would share its outputs.
    for (const NamedEntry& other : names_) {
      if (other.name != net.name) continue;
      const toml::node* name_node = tables[i]->get("name");
      throw Error(source_.where(name_node ? name_node->source() : tables[i]->source()),
                  fmt::format("net name \"{}\" is used by {} ({}) too; names must be unique "
                              "among walls, inlets, outlets, bodies and nets (each names its "
                              "outputs)",
                              net.name, other.label, other.where.str()));
    }
    names_.push_back({net.name, fmt::format("net[{}]", number), net.where});
    spec_.nets.push_back(std::move(net));
  }
}

NetSpec CaseReader::read_net(const toml::table& table, int number) const {
  const std::string label = fmt::format("net[{}]", number);
  TomlTableReader r(table, label, label, keys_of("net"), source_, home_hint);
  NetSpec net;
  net.where = r.location();
  net.name = r.string("name", fmt::format("net{}", number));
  if (!plain_file_name(net.name)) {
    r.fail_value("name", *r.find("name"),
                 "must be a plain file name: letters, digits, '_', '-' and '.' (the net writes "
                 "<name>.xdmf, net_<name>_<n>.vtk and knots_<name>.csv)");
  }
  net.center = read_position(r, "center", "position [x, y, z] of the outline's centre, m");
  check_in_domain(r, "center", net.center);
  read_net_orientation(r, net);
  net.width = r.required_number("width", NumberRule::positive("m"), "outline width, m, > 0");
  net.height = r.required_number("height", NumberRule::positive("m"), "outline height, m, > 0");
  net.twine_length = r.required_number("twine_length", NumberRule::positive("m"),
                                       "real twine (bar) length l0 between crossings, m, > 0");
  net.twine_diameter = r.required_number("twine_diameter", NumberRule::positive("m"),
                                         "real twine diameter d0, m, > 0");
  if (net.twine_diameter >= net.twine_length) {
    r.fail_value("twine_diameter", *r.find("twine_diameter"),
                 fmt::format("must be < twine_length ({} m): a twine thicker than its mesh closes "
                             "the net",
                             format_number(net.twine_length)));
  }
  net.mesh_grouping = r.number("mesh_grouping", NumberRule::closed(1, 100, ""), 1.0);
  const double twine = net.mesh_grouping * net.twine_length;
  for (const std::string_view key : {"width", "height"}) {
    const double side = key == "width" ? net.width : net.height;
    if (side < twine * 0.95) {
      r.fail_value(key, *r.find(key),
                   fmt::format("must hold at least one numerical mesh of mesh_grouping x "
                               "twine_length = {} m",
                               format_derived(twine)));
    }
  }
  net.knot_shape = r.choice("knot_shape", kKnotShapeNames, net.knot_shape);
  net.equivalent_knot = r.choice("equivalent_knot", kEquivalentKnotRuleNames, net.equivalent_knot);
  net.layout = r.choice("knot_layout", kKnotLayoutNames, net.layout);
  net.edges = r.choice("edges", kEdgeKnotsNames, net.edges);
  if (net.edges == EdgeKnots::SolidityMatched && net.layout == KnotLayout::Inset) {
    r.fail_value("edges", *r.find("edges"),
                 "applies to knot_layout = \"crossings\" only: the inset layout's knots are "
                 "whole elements that already match the real solidity");
  }
  read_net_material(r, net);
  net.damping_ratio = r.number("damping_ratio", NumberRule::closed(0, 10, ""), net.damping_ratio);
  read_net_edges(r, net);
  read_net_sinker(r, net);
  read_net_point_loads(r, net);
  net.rigid = r.boolean("rigid", false);
  if (net.rigid && r.has("fixed_edges")) {
    r.fail_value("fixed_edges", *r.find("fixed_edges"),
                 "cannot be combined with rigid = true, which anchors every knot");
  }
  net.reference_velocity = r.optional_number("reference_velocity", NumberRule::positive("m/s"));
  if (!net.reference_velocity) net.reference_velocity = spec_.uniform_inflow();
  return net;
}

void CaseReader::read_net_orientation(const TomlTableReader& r, NetSpec& net) const {
  if (const toml::node* node = r.find("up")) net.up = read_direction(r, "up", *node, false, "");
  const toml::node* normal = r.find("normal");
  const toml::node* angle = r.find("angle_of_attack");
  if (normal && angle) {
    r.fail_value("angle_of_attack", *angle,
                 "cannot be combined with normal: give the net's normal, or its angle to the "
                 "current (+x) turned about up, not both");
  }
  if (normal) net.normal = read_direction(r, "normal", *normal, false, "");
  if (angle) {
    const double degrees =
        r.to_number("angle_of_attack", *angle, NumberRule::left_open(0, 90, "deg"));
    if (std::abs(net.up.x) > 1e-9) {
      r.fail_value("angle_of_attack", *angle,
                   fmt::format("needs an up direction with no x component (up = {}): the net "
                               "turns about up away from facing +x",
                               format_vec3(net.up)));
    }
    // Facing +x at 90 degrees; turned about up by 90 - angle.
    const double beta = (90 - degrees) * std::numbers::pi / 180;
    const Vec3d x{1, 0, 0};
    net.normal = x * std::cos(beta) + cross(net.up, x) * std::sin(beta);
  }
  if (std::abs(dot(net.normal, net.up)) > 0.999) {
    r.fail_value(normal ? "normal" : "up", normal ? *normal : *r.find("up"),
                 fmt::format("normal {} and up {} are parallel: up must lie (nearly) in the net's "
                             "plane",
                             format_vec3(net.normal), format_vec3(net.up)));
  }
}

void CaseReader::read_net_material(const TomlTableReader& r, NetSpec& net) const {
  const toml::node* node = r.find("material");
  const Material* material = &kMaterials[0];
  if (node) {
    std::vector<std::string_view> names;
    for (const Material& m : kMaterials) names.push_back(m.name);
    const std::string word = r.to_string("material", *node);
    material = nullptr;
    for (const Material& m : kMaterials) {
      if (m.name == word) material = &m;
    }
    if (!material) {
      r.fail_value(
          "material", *node,
          fmt::format("unknown material{}; allowed: {}", did_you_mean(word, names), join(names)));
    }
  }
  net.material = std::string(material->name);
  const bool custom = material->name == "custom";
  if (custom && !r.has("material_density")) {
    r.require("material_density", "twine material density, kg/m^3, for material = \"custom\"");
  }
  net.material_density =
      r.number("material_density", NumberRule::closed(1, 1e5, "kg/m^3"), material->density);
  const bool modulus = r.has("youngs_modulus");
  const bool ea = r.has("axial_stiffness");
  const bool law = r.has("tension_law");
  if (int(modulus) + int(ea) + int(law) > 1) {
    const std::string_view second = law ? "tension_law" : "axial_stiffness";
    r.fail_value(second, *r.find(second),
                 "give one of youngs_modulus (Pa), axial_stiffness (EA, N) or tension_law "
                 "([c1, c2], N), not several");
  }
  if (custom && !modulus && !ea && !law) {
    r.require("youngs_modulus",
              "twine Young's modulus, Pa, for material = \"custom\" (or axial_stiffness, or "
              "tension_law)");
  }
  net.youngs_modulus =
      r.number("youngs_modulus", NumberRule::left_open(0, 1e12, "Pa"), material->youngs_modulus);
  net.axial_stiffness = r.number("axial_stiffness", NumberRule::left_open(0, 1e10, "N"), 0.0);
  if (law) {
    const toml::node& n = *r.find("tension_law");
    const std::vector<double> c =
        r.to_number_array("tension_law", n, NumberRule::non_negative("N"), 2);
    if (c.size() != 2 || c[0] + c[1] <= 0) {
      r.fail_value("tension_law", n,
                   "must be [c1, c2] in N for T = c1 eps + c2 eps^2, non-negative and not both 0 "
                   "(REEF3D's nylon: [1160, 37300])");
    }
    net.tension_law = std::array<double, 2>{c[0], c[1]};
  }
}

void CaseReader::read_net_edges(const TomlTableReader& r, NetSpec& net) const {
  static const std::vector<std::string_view> kEdgeNames = {"bottom", "top", "left", "right"};
  const toml::node* node = r.find("fixed_edges");
  if (!node) {
    net.fixed_edges = {false, true, false, false};  // hung from a top bar
    return;
  }
  const WordListRule rule{.noun = "edge",
                          .known = kEdgeNames,
                          .allowed = kEdgeNames,
                          .not_allowed_reason = "",
                          .example = "[\"top\"]",
                          .allow_empty = true};
  for (const std::size_t e : r.to_word_list("fixed_edges", *node, rule)) net.fixed_edges[e] = true;
}

void CaseReader::read_net_sinker(const TomlTableReader& r, NetSpec& net) const {
  const toml::node* node = r.find("sinker");
  if (!node) return;
  const toml::table& table =
      r.nested_table("sinker", *node,
                     "must be a table such as { length = 0.3, diameter = 0.006, density = 8610 } "
                     "(a bar along the bottom edge)");
  const std::string path = r.key_path("sinker");
  TomlTableReader t(table, path, path, kSinkerKeys, source_);
  SinkerSpec& s = net.sinker;
  s.length = t.number("length", NumberRule::positive("m"), net.width);
  s.diameter = t.required_number("diameter", NumberRule::positive("m"), "bar diameter, m, > 0");
  s.density = t.required_number("density", NumberRule::closed(1, 1e5, "kg/m^3"),
                                "bar material density, kg/m^3 (steel: 7850)");
  s.drag_coefficient =
      t.number("drag_coefficient", NumberRule::closed(0, 10, ""), s.drag_coefficient);
  if (net.fixed_edges[0]) {
    r.fail_value("sinker", *node,
                 "cannot hang on a fixed bottom edge: remove \"bottom\" from fixed_edges or the "
                 "sinker");
  }
}

void CaseReader::read_net_point_loads(const TomlTableReader& r, NetSpec& net) const {
  const toml::node* node = r.find("point_loads");
  if (!node) return;
  const auto* array = node->as_array();
  if (!array) {
    r.fail_value("point_loads", *node,
                 "must be an array of tables such as [{ row = 0, column = 3, force = [0, 0, -1] "
                 "}]");
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    const auto* table = array->get(i)->as_table();
    const std::string path = fmt::format("{}[{}]", r.key_path("point_loads"), i + 1);
    if (!table) {
      r.fail_value("point_loads", *node,
                   fmt::format("element {} must be a table {{ row, column, force }}", i + 1),
                   array->get(i));
    }
    TomlTableReader t(*table, path, path, kPointLoadKeys, source_);
    NetPointLoad load;
    load.row = static_cast<int>(t.integer("row", IntRule{0, 1000000}, 0));
    load.column = static_cast<int>(t.integer("column", IntRule{0, 1000000}, 0));
    load.force =
        t.required_vec3("force", NumberRule::any("N"), "force [Fx, Fy, Fz] on the knot, N");
    net.point_loads.push_back(load);
  }
}

// ---- [current] ----------------------------------------------------------------------------

void CaseReader::read_current() {
  const toml::table* table = find_table("current");
  if (!table) return;
  TomlTableReader r(*table, "current", "[current]", keys_of("current"), source_, home_hint);
  CurrentSpec& c = spec_.current;
  c.given = true;
  c.where = r.location();
  c.velocity = r.required_vec3("velocity", velocity_rule(), "current velocity [u, v, w], m/s");
  c.model = r.choice("model", kNetLoadModelNames, c.model);
  c.screen = r.choice("screen", kScreenCoefficientsNames, c.screen);
  if (c.model != NetLoadModel::Screen) {
    reject_foreign_parameter(r, "screen", name_of(c.model), "model \"screen\"",
                             "normal_drag, tangential_drag");
  }
  c.normal_drag = r.number("normal_drag", NumberRule::closed(0, 10, ""), c.normal_drag);
  c.tangential_drag = r.number("tangential_drag", NumberRule::closed(0, 10, ""), c.tangential_drag);
  if (c.model != NetLoadModel::Morison) {
    for (const std::string_view key : {"normal_drag", "tangential_drag"}) {
      reject_foreign_parameter(r, key, name_of(c.model), "model \"morison\"",
                               c.model == NetLoadModel::Screen ? "screen" : "");
    }
  }
  if (!spec_.fills.empty()) {
    r.fail_table(
        "applies to standalone nets only (no [[fill]]): with SPH fluid the knots feel "
        "the fluid itself; remove [current] or the [[fill]] tables");
  }
}

}  // namespace netsph::case_detail
