// The case file's schema (which keys each table takes, where a misplaced key belongs) and the
// small helpers every table reader shares (case_reader*.cpp). docs/case-reference.md documents
// every key; keep the two in step.
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "netsph/case/case_reader_impl.hpp"
#include "netsph/case/toml_table_reader.hpp"

namespace netsph::case_detail {

// ---- schema -------------------------------------------------------------------------------

const std::vector<TableKeys>& schema() {
  static const std::vector<TableKeys> tables = {
      {"simulation",
       {"name", "dimensions", "dp", "h_over_dp", "kernel", "end_time", "cfl", "dt_min", "dt_max",
        "max_lost_fraction"}},
      {"fluid",
       {"density", "sound_speed", "sound_speed_coef", "gamma", "background_pressure", "gravity",
        "structure_gravity", "viscosity", "density_diffusion", "shifting"}},
      {"domain", {"min", "max", "periodic"}},
      {"fill", {"min", "max", "velocity", "surface_z"}},
      {"wall", {"name", "min", "max", "faces", "layers", "model", "slip", "velocity", "motion"}},
      {"inlet", {"name", "face", "layers", "velocity", "profile", "density", "surface_z"}},
      {"outlet", {"name", "face", "layers", "velocity", "density", "surface_z"}},
      {"body", {"name",          "group",
                "shape",         "size",
                "thickness",     "width",
                "height",        "side",
                "diameter",      "length",
                "twine_length",  "twine_diameter",
                "center",        "normal",
                "axis",          "rotation",
                "motion",        "density",
                "mass",          "initial_velocity",
                "velocity",      "motion_history",
                "model",         "slip",
                "layers",        "reference_velocity",
                "reference_area"}},
      {"net",
       {"name",
        "center",
        "normal",
        "up",
        "angle_of_attack",
        "width",
        "height",
        "twine_length",
        "twine_diameter",
        "mesh_grouping",
        "knot_shape",
        "equivalent_knot",
        "knot_layout",
        "edges",
        "material",
        "material_density",
        "youngs_modulus",
        "axial_stiffness",
        "tension_law",
        "damping_ratio",
        "fixed_edges",
        "sinker",
        "point_loads",
        "rigid",
        "reference_velocity"}},
      {"probe", {"name", "type", "at", "start", "end", "points", "min", "max", "spacing", "every"}},
      {"waves",
       {"type",
        "paddle",
        "wavemaker",
        "height",
        "period",
        "theory",
        "generation",
        "hs",
        "tp",
        "gamma",
        "seed",
        "components",
        "ramp",
        "depth",
        "still_water_level",
        "origin_x",
        "relaxation_zone",
        "relaxation_rate",
        "absorption",
        "displacement"}},
      {"damping", {"name", "from", "to", "rate", "velocity"}},
      {"gauge", {"name", "x", "y"}},
      {"current", {"velocity", "model", "screen", "normal_drag", "tangential_drag"}},
      {"output",
       {"snapshots", "snapshot_every", "series_every", "checkpoint_every", "gauge_every",
        "force_window", "snapshot_region"}},
  };
  return tables;
}

const std::vector<std::string_view>& keys_of(std::string_view table) {
  for (const auto& t : schema()) {
    if (t.table == table) return t.keys;
  }
  static const std::vector<std::string_view> none;
  return none;
}

std::string header_of(std::string_view table) {
  const bool is_array = table == "fill" || table == "wall" || table == "inlet" ||
                        table == "outlet" || table == "body" || table == "net" ||
                        table == "probe" || table == "damping" || table == "gauge";
  return is_array ? fmt::format("[[{}]]", table) : fmt::format("[{}]", table);
}

std::string home_hint(std::string_view key) {
  for (const auto& t : schema()) {
    for (const std::string_view k : t.keys) {
      if (k == key) return fmt::format("'{}' belongs in {}", key, header_of(t.table));
    }
  }
  return {};
}

void reject_foreign_parameter(const TomlTableReader& r, std::string_view key,
                              std::string_view model, std::string_view owners,
                              std::string_view own_keys) {
  if (const toml::node* node = r.find(key)) {
    r.fail_value(key, *node,
                 fmt::format("does not apply to model \"{}\" ({} is a parameter of {}); "
                             "allowed with \"{}\": {}",
                             model, key, owners, model, own_keys));
  }
}

void check_increasing(const TomlTableReader& r, std::string_view key, const toml::node& node,
                      const std::vector<double>& values) {
  for (std::size_t k = 1; k < values.size(); ++k) {
    if (values[k] > values[k - 1]) continue;
    r.fail_value(key, node,
                 fmt::format("must be strictly increasing, but element {} = {} <= element {} = {}",
                             k + 1, format_number(values[k]), k, format_number(values[k - 1])),
                 node.as_array()->get(k));
  }
}

std::string format_derived(double v) {
  return fmt::format("{:.6g}", v);
}

}  // namespace netsph::case_detail
