#include "netsph/case/case_overrides.hpp"

#include <cctype>
#include <charconv>
#include <optional>

#include <fmt/format.h>

#include "netsph/case/toml_table_reader.hpp"
#include "netsph/core/error.hpp"

namespace netsph {
namespace {

// Errors about the shape of an option (rather than about its value) point at the option
// itself; the message quotes the whole option.
constexpr std::string_view kOption = "--set";

struct Override {
  std::string option;             ///< the whole "dotted.key=value" string
  std::vector<std::string> keys;  ///< the dotted key, split
  std::string value;              ///< the text after the first '='
  std::string source() const { return std::string(kOverrideSourcePrefix) + option; }
};

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return std::string(s.substr(first, last - first + 1));
}

Override split_override(const std::string& option) {
  const auto eq = option.find('=');
  if (eq == std::string::npos) {
    throw Error(
        std::string(kOption),
        fmt::format("'{}' is not of the form dotted.key=value (e.g. simulation.dp=0.01)", option));
  }
  Override o{option, {}, trim(std::string_view(option).substr(eq + 1))};
  const std::string key = trim(std::string_view(option).substr(0, eq));
  if (key.empty()) {
    throw Error(std::string(kOption),
                fmt::format("'{}' has an empty key; expected dotted.key=value", option));
  }
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    o.keys.push_back(trim(std::string_view(key).substr(start, dot - start)));
    if (o.keys.back().empty()) {
      throw Error(std::string(kOption),
                  fmt::format("'{}': key '{}' has an empty part between dots", option, key));
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return o;
}

/// Text that can only be meant as TOML (an array, an inline table, a quoted string) is an
/// error when it does not parse; anything else falls back to a string.
bool looks_like_toml(std::string_view value) {
  return !value.empty() && std::string_view("[{\"'").find(value.front()) != std::string_view::npos;
}

bool is_container(std::string_view value) {
  return !value.empty() && (value.front() == '[' || value.front() == '{');
}

/// Parses the value into a one-key document {v = value}; its nodes carry the option as path.
toml::table parse_value(const Override& o) {
  try {
    toml::table doc = toml::parse("v = " + o.value, o.source());
    if (doc.size() == 1 && doc.contains("v")) return doc;
  } catch (const toml::parse_error& e) {
    if (looks_like_toml(o.value)) {
      const std::string_view hint =
          is_container(o.value) ? " (strings inside arrays and tables need quotes)" : "";
      throw Error(o.source(), fmt::format("value '{}' is not valid TOML: {}{}", o.value,
                                          e.description(), hint));
    }
  }
  try {
    return toml::parse("v = " + toml_quote(o.value), o.source());
  } catch (const toml::parse_error& e) {  // e.g. invalid UTF-8
    throw Error(o.source(), fmt::format("value is not valid text: {}", e.description()));
  }
}

/// An empty table or array whose source is the option, so errors about it name the option.
toml::table make_table(const Override& o) {
  return toml::parse("", o.source());
}
toml::array make_array(const Override& o) {
  toml::table doc = toml::parse("v = []", o.source());
  return std::move(*doc.get_as<toml::array>("v"));
}

std::optional<std::size_t> parse_index(const std::string& segment) {
  std::size_t index = 0;
  const char* end = segment.data() + segment.size();
  const auto [ptr, ec] = std::from_chars(segment.data(), end, index);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return index;
}

bool is_index(const std::string& segment) {
  return parse_index(segment).has_value();
}

[[noreturn]] void fail(const Override& o, std::string_view message) {
  throw Error(std::string(kOption), fmt::format("'{}': {}", o.option, message));
}

/// The child `key` of `table`, created (as a table, or as an array when the next key
/// segment is an index) when missing.
toml::node& child_of_table(toml::table& table, const std::string& key, bool next_is_index,
                           const Override& o) {
  if (toml::node* child = table.get(key)) return *child;
  if (next_is_index) return table.insert(key, make_array(o)).first->second;
  return table.insert(key, make_table(o)).first->second;
}

/// Entry `segment` of an array of tables; the next free index appends an empty table.
toml::node& entry_of_array(toml::array& array, const std::string& segment,
                           const std::string& walked, bool last, const Override& o) {
  const auto index = parse_index(segment);
  if (!array.empty() && !array.is_array_of_tables()) {
    fail(o,
         fmt::format("{} is an array of values; set it as a whole, e.g. {}=[...]", walked, walked));
  }
  if (!index && !segment.empty() &&
      (segment[0] == '-' || std::isdigit(static_cast<unsigned char>(segment[0])))) {
    // Meant as an index (negative, or too large to be one): "e.g. wall.0.-1" would not help.
    fail(o, fmt::format("{}.{}: '{}' is not an index; the entries of {} are numbered from 0 "
                        "(the case has {})",
                        walked, segment, segment, walked, array.size()));
  }
  if (!index) {
    fail(o, fmt::format("{} is an array of tables: select an entry with a 0-based index, "
                        "e.g. {}.0.{}",
                        walked, walked, segment));
  }
  if (last && array.empty()) {
    // Not in the case yet: nothing tells an array of values (gravity) from one of tables.
    fail(o, fmt::format("the case has no {0}: set an array of values as a whole, e.g. {0}=[...]; "
                        "for an entry of an array of tables set its keys, e.g. {0}.{1}.<key>=...",
                        walked, *index));
  }
  if (last) {
    fail(o, fmt::format("cannot replace a whole entry of {}; set its keys, e.g. {}.{}.<key>=...",
                        walked, walked, *index));
  }
  if (*index > array.size()) {
    fail(o,
         fmt::format("index {} is out of range: {} has {} entr{} (0-based; index {} adds one)",
                     *index, walked, array.size(), array.size() == 1 ? "y" : "ies", array.size()));
  }
  if (*index == array.size()) array.push_back(make_table(o));
  return array[*index];
}

/// Keys that give the same quantity two ways and so exclude each other. An override of one
/// replaces the other as well, so `--set fluid.sound_speed=30` works on a case that sets
/// sound_speed_coef instead of failing with "cannot be combined".
/// Each pair belongs to one top-level table: a body's `motion` is not a wall's.
struct Alternatives {
  std::string_view table, a, b;
};
constexpr Alternatives kAlternatives[] = {
    {"fluid", "sound_speed", "sound_speed_coef"},
    {"wall", "velocity", "motion"},
    {"inlet", "velocity", "profile"},
    {"body", "velocity", "motion_history"},
};

void erase_alternatives(toml::table& table, std::string_view top, std::string_view key) {
  for (const auto& alt : kAlternatives) {
    if (top != alt.table) continue;
    if (key == alt.a) table.erase(alt.b);
    if (key == alt.b) table.erase(alt.a);
  }
}

void apply_override(toml::table& root, const Override& o) {
  toml::table parsed = parse_value(o);
  toml::node& value = *parsed.get("v");
  toml::node* current = &root;
  std::string walked;  // the dotted key so far, for messages
  for (std::size_t i = 0; i < o.keys.size(); ++i) {
    const std::string& segment = o.keys[i];
    const bool last = i + 1 == o.keys.size();
    if (auto* table = current->as_table()) {
      if (last) {
        erase_alternatives(*table, o.keys.front(), segment);
        table->insert_or_assign(segment, std::move(value));  // moving keeps the node's source
        return;
      }
      current = &child_of_table(*table, segment, is_index(o.keys[i + 1]), o);
    } else if (auto* array = current->as_array()) {
      current = &entry_of_array(*array, segment, walked, last, o);
    } else {
      fail(o, fmt::format("{} is {}, not a table, so it has no key '{}'", walked,
                          type_name(*current), segment));
    }
    walked += (walked.empty() ? "" : ".") + segment;
  }
}

}  // namespace

void apply_overrides(toml::table& root, const std::vector<std::string>& overrides) {
  for (const std::string& option : overrides) apply_override(root, split_override(option));
}

}  // namespace netsph
