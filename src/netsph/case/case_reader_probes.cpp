// The [[probe]] tables of a case file: points, lines and planes where the fluid is sampled
// during a run (run/probes.hpp). Same conventions as case_reader.cpp; docs/case-reference.md
// documents every key.
#include <cmath>

#include <fmt/format.h>

#include "netsph/case/case_reader_impl.hpp"
#include "netsph/core/error.hpp"

namespace netsph::case_detail {
namespace {

/// Keys that belong to one probe type only: given with another, they would be ignored.
struct TypeKeys {
  ProbeType type;
  std::vector<std::string_view> keys;
};
const std::vector<TypeKeys>& type_keys() {
  static const std::vector<TypeKeys> keys = {{ProbeType::Point, {"at"}},
                                             {ProbeType::Line, {"start", "end", "points"}},
                                             {ProbeType::Plane, {"min", "max", "spacing"}}};
  return keys;
}

constexpr double kMaxProbePoints = 1e6;

}  // namespace

bool plain_file_name(const std::string& name) {
  if (name.empty() || name == "." || name == "..") return false;
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

void CaseReader::read_probes() {
  const std::vector<const toml::table*> tables = find_array_of_tables("probe");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const int number = static_cast<int>(i) + 1;
    ProbeSpec probe = read_probe(*tables[i], number);
    for (const ProbeSpec& other : spec_.probes) {
      if (other.name != probe.name) continue;
      const toml::node* name_node = tables[i]->get("name");
      throw Error(source_.where(name_node ? name_node->source() : tables[i]->source()),
                  fmt::format("probe name \"{}\" is used twice: by {} and probe[{}]; probe names "
                              "must be unique (each names a file in probes/)",
                              probe.name, other.where.str(), number));
    }
    spec_.probes.push_back(std::move(probe));
  }
}

ProbeSpec CaseReader::read_probe(const toml::table& table, int number) const {
  const std::string label = fmt::format("probe[{}]", number);
  TomlTableReader r(table, label, label, keys_of("probe"), source_, home_hint);
  ProbeSpec probe;
  probe.where = r.location();
  if (spec_.net_only()) {
    r.fail_table(
        "probes sample the SPH fluid, and this case has none (no [[fill]]: a standalone "
        "net in a uniform [current])");
  }
  probe.name = r.string("name", fmt::format("probe{}", number));
  if (!plain_file_name(probe.name)) {
    r.fail_value("name", *r.find("name"),
                 "must be a plain file name: letters, digits, '_', '-' and '.' (the probe writes "
                 "probes/<name>.csv)");
  }
  r.require("type", "\"point\", \"line\" or \"plane\"");
  probe.type = r.choice("type", kProbeTypeNames, ProbeType::Point);
  for (const TypeKeys& t : type_keys()) {
    if (t.type == probe.type) continue;
    for (const std::string_view key : t.keys) {
      if (const toml::node* node = r.find(key)) {
        const std::string_view own = name_of(probe.type);
        r.fail_value(key, *node,
                     fmt::format("does not apply to type = \"{}\" ({} is a key of \"{}\" "
                                 "probes); a \"{}\" probe takes: {}",
                                 own, key, name_of(t.type), own,
                                 join(type_keys()[static_cast<int>(probe.type)].keys)));
      }
    }
  }
  const double dp = spec_.simulation.dp;
  switch (probe.type) {
    case ProbeType::Point:
      probe.a = probe.b = read_position(r, "at", "the point [x, y, z], m");
      check_in_domain(r, "at", probe.a);
      break;
    case ProbeType::Line: {
      probe.a = read_position(r, "start", "the line's first point [x, y, z], m");
      probe.b = read_position(r, "end", "the line's last point [x, y, z], m");
      check_in_domain(r, "start", probe.a);
      check_in_domain(r, "end", probe.b);
      const double length = norm(probe.b - probe.a);
      if (!(length > 0)) {
        r.fail_value("end", *r.find("end"), "must differ from start: a line needs a length");
      }
      const auto fallback = static_cast<std::int64_t>(std::lround(length / dp)) + 1;
      probe.points = static_cast<int>(
          r.integer("points", IntRule{2, static_cast<std::int64_t>(kMaxProbePoints)},
                    std::max<std::int64_t>(2, fallback)));
      break;
    }
    case ProbeType::Plane: {
      probe.a = read_position(r, "min", "one corner [x, y, z] of the rectangle, m");
      probe.b = read_position(r, "max", "the opposite corner [x, y, z], m");
      check_in_domain(r, "min", probe.a);
      check_in_domain(r, "max", probe.b);
      int flat = 0;
      for (const int axis : used_axes()) flat += probe.a[axis] == probe.b[axis] ? 1 : 0;
      const int wanted = is_2d() ? 0 : 1;
      if (flat != wanted) {
        r.fail_value("max", *r.find("max"),
                     is_2d() ? std::string("must differ from min in both x and z (2D planes are "
                                           "rectangles in the x-z plane)")
                             : std::string("must equal min on exactly one axis, the plane's "
                                           "normal (planes are axis-aligned rectangles), and "
                                           "differ from it on the other two"));
      }
      probe.spacing = r.number("spacing", NumberRule::positive("m"), dp);
      const Vec3d extent = probe.b - probe.a;
      double count = 1;
      for (const int axis : used_axes())
        if (extent[axis] != 0) count *= std::fabs(extent[axis]) / probe.spacing + 1;
      if (count > kMaxProbePoints) {
        r.fail_value("spacing", r.find("spacing") ? *r.find("spacing") : *r.find("max"),
                     fmt::format("gives {:.3g} points; at most {:.0g} per probe: choose a coarser "
                                 "spacing or a smaller rectangle",
                                 count, kMaxProbePoints));
      }
      break;
    }
  }
  probe.every = r.number("every", NumberRule::non_negative("s"), 0.0);
  return probe;
}

}  // namespace netsph::case_detail
