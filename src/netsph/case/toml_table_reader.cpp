#include "netsph/case/toml_table_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

namespace netsph {

// ---- TomlSource ---------------------------------------------------------------------------

SourceLocation TomlSource::location(const toml::source_region& region) const {
  if (!region.path) return {fallback_, 0, 0};
  const std::string& path = *region.path;
  // A --set value was parsed from a one-line synthetic document: its line and column mean
  // nothing to the user, the option text does.
  if (std::string_view(path).starts_with(kOverrideSourcePrefix)) return {path, 0, 0};
  return {path, static_cast<int>(region.begin.line), static_cast<int>(region.begin.column)};
}

// ---- formatting ---------------------------------------------------------------------------

std::string format_number(double v) {
  return fmt::format("{}", v);
}

std::string format_vec3(const Vec3d& v) {
  return fmt::format("[{}, {}, {}]", format_number(v.x), format_number(v.y), format_number(v.z));
}

namespace {

std::string format_unlimited(const toml::node& node);

std::string format_array(const toml::array& array) {
  std::string out = "[";
  for (std::size_t i = 0; i < array.size(); ++i) {
    if (i > 0) out += ", ";
    out += format_unlimited(array[i]);
  }
  return out + "]";
}

std::string format_table(const toml::table& table) {
  if (table.empty()) return "{}";
  // toml++ iterates keys alphabetically; show them as the user wrote them.
  std::vector<std::pair<const toml::key*, const toml::node*>> entries;
  for (const auto& [key, value] : table) entries.emplace_back(&key, &value);
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    const auto& pa = key_region(*a.first, *a.second).begin;
    const auto& pb = key_region(*b.first, *b.second).begin;
    return std::pair(pa.line, pa.column) < std::pair(pb.line, pb.column);
  });
  std::string out = "{ ";
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i > 0) out += ", ";
    out += std::string(entries[i].first->str()) + " = " + format_unlimited(*entries[i].second);
  }
  return out + " }";
}

std::string format_unlimited(const toml::node& node) {
  if (const auto* s = node.as_string()) return toml_quote(s->get());
  if (const auto* i = node.as_integer()) return fmt::format("{}", i->get());
  if (const auto* f = node.as_floating_point()) {
    // Keep "3.0" distinguishable from the integer 3: it matters for "must be an integer".
    std::string s = format_number(f->get());
    if (s.find_first_of(".eEna") == std::string::npos) s += ".0";
    return s;
  }
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  if (const auto* a = node.as_array()) return format_array(*a);
  if (const auto* t = node.as_table()) return format_table(*t);
  std::ostringstream os;  // dates and times: toml++ prints them in TOML syntax
  node.visit([&os](const auto& v) { os << v; });
  return os.str();
}

// Optimal string alignment distance (Levenshtein plus adjacent transpositions), so that
// "visocsity" is one edit from "viscosity".
std::size_t edit_distance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::string toml_quote(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (byte < 0x20 || byte == 0x7f) {  // control characters must be escaped in TOML
      out += fmt::format("\\u{:04X}", static_cast<unsigned>(byte));
    } else {
      out += c;
    }
  }
  return out + '"';
}

std::string format_value(const toml::node& node) {
  constexpr std::size_t kMaxLength = 80;
  std::string s = format_unlimited(node);
  if (s.size() > kMaxLength) s = s.substr(0, kMaxLength - 3) + "...";
  return s;
}

std::string_view type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a floating-point number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

std::string closest_match(std::string_view word, const std::vector<std::string_view>& candidates) {
  const std::string w = lower(word);
  // Short words tolerate fewer edits: "dx" -> "dp" is plausible, "ab" -> "dp" is not.
  // A suggestion never replaces the whole word: "w" is not a typo of "x".
  const std::size_t tolerance =
      std::min(w.size() <= 4 ? std::size_t{1} : (w.size() <= 8 ? 2 : 3), w.size() - 1);
  std::string best;
  std::size_t best_distance = tolerance + 1;
  for (const std::string_view c : candidates) {
    const std::size_t d = edit_distance(w, lower(c));
    if (d < best_distance) best_distance = d, best = std::string(c);
  }
  if (!best.empty() || w.size() < 3) return best;
  // An abbreviation ("visc") is far from the full key in edits but unambiguous as a prefix.
  for (const std::string_view c : candidates) {
    if (!lower(c).starts_with(w)) continue;
    if (!best.empty()) return {};  // ambiguous
    best = std::string(c);
  }
  return best;
}

std::string did_you_mean(std::string_view word, const std::vector<std::string_view>& candidates) {
  const std::string best = closest_match(word, candidates);
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

std::string join(const std::vector<std::string_view>& words, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) out += separator;
    out += words[i];
  }
  return out;
}

std::pair<const toml::key*, const toml::node*> first_unknown_key(
    const toml::table& table, const std::vector<std::string_view>& allowed) {
  // toml++ iterates keys alphabetically; the user expects the first one in the file.
  const toml::key* first = nullptr;
  const toml::node* first_value = nullptr;
  for (const auto& [key, value] : table) {
    if (std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end()) continue;
    const auto& here = key_region(key, value).begin;
    if (first) {
      const auto& there = key_region(*first, *first_value).begin;
      if (std::pair(there.line, there.column) <= std::pair(here.line, here.column)) continue;
    }
    first = &key;
    first_value = &value;
  }
  return {first, first_value};
}

const toml::source_region& key_region(const toml::key& key, const toml::node& value) {
  return key.source().path ? key.source() : value.source();
}

// ---- rules --------------------------------------------------------------------------------

bool NumberRule::accepts(double v) const {
  if (!std::isfinite(v)) return false;
  if (lo_open ? v <= lo : v < lo) return false;
  if (hi_open ? v >= hi : v > hi) return false;
  return true;
}

std::string NumberRule::describe() const {
  if (std::isinf(lo) && std::isinf(hi)) {
    return unit.empty() ? "a finite number" : "a finite number in " + std::string(unit);
  }
  std::string range;
  if (std::isinf(hi)) {
    range = fmt::format("{} {}", lo_open ? ">" : ">=", format_number(lo));
  } else if (std::isinf(lo)) {
    range = fmt::format("{} {}", hi_open ? "<" : "<=", format_number(hi));
  } else {
    range = fmt::format("in {}{}, {}{}", lo_open ? "(" : "[", format_number(lo), format_number(hi),
                        hi_open ? ")" : "]");
  }
  return unit.empty() ? range : range + " " + std::string(unit);
}

std::string IntRule::describe() const {
  if (hi == lo + 1) return fmt::format("{} or {}", lo, hi);
  return fmt::format("an integer in [{}, {}]", lo, hi);
}

// ---- TomlTableReader ----------------------------------------------------------------------

TomlTableReader::TomlTableReader(const toml::table& table, std::string path, std::string title,
                                 std::vector<std::string_view> allowed, const TomlSource& source,
                                 UnknownKeyHint hint)
    : table_(table),
      path_(std::move(path)),
      title_(std::move(title)),
      allowed_(std::move(allowed)),
      source_(source) {
  reject_unknown_keys(hint);
}

void TomlTableReader::reject_unknown_keys(UnknownKeyHint hint) const {
  const auto [first, first_value] = first_unknown_key(table_, allowed_);
  if (!first) return;
  const std::string_view name = first->str();
  std::string suggestion = did_you_mean(name, allowed_);
  if (suggestion.empty() && hint) {
    const std::string extra = hint(name);
    if (!extra.empty()) suggestion = " (" + extra + ")";
  }
  throw Error(source_.where(key_region(*first, *first_value)),
              fmt::format("unknown key '{}' in {}{}; allowed: {}", name, title_, suggestion,
                          join(allowed_)));
}

std::string TomlTableReader::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

const toml::node* TomlTableReader::find(std::string_view key) const {
  return table_.get(key);
}

const toml::node& TomlTableReader::require(std::string_view key, std::string_view meaning) const {
  const toml::node* node = find(key);
  if (!node) fail_table(fmt::format("{} is missing required key '{}' ({})", title_, key, meaning));
  return *node;
}

void TomlTableReader::fail_value(std::string_view key, const toml::node& value,
                                 std::string_view message, const toml::node* at) const {
  throw Error(source_.where((at ? *at : value).source()),
              fmt::format("{} = {}: {}", key_path(key), format_value(value), message));
}

const toml::table& TomlTableReader::nested_table(std::string_view key, const toml::node& value,
                                                 std::string_view expected) const {
  const auto* table = value.as_table();
  if (!table) fail_value(key, value, fmt::format("{}, not {}", expected, type_name(value)));
  return *table;
}

void TomlTableReader::fail_table(std::string_view message) const {
  throw Error(source_.where(table_.source()), std::string(message));
}

double TomlTableReader::to_number(std::string_view key, const toml::node& node,
                                  const NumberRule& rule) const {
  double v = 0;
  if (const auto* i = node.as_integer()) {
    v = static_cast<double>(i->get());
  } else if (const auto* f = node.as_floating_point()) {
    v = f->get();
  } else {
    const std::string range = rule.describe();  // "a finite number" needs no "a number"
    const std::string expected = range.starts_with("a ") ? range : "a number " + range;
    fail_value(key, node, fmt::format("must be {}, not {}", expected, type_name(node)));
  }
  if (!rule.accepts(v)) fail_value(key, node, "must be " + rule.describe());
  return v;
}

double TomlTableReader::number(std::string_view key, const NumberRule& rule,
                               double fallback) const {
  const toml::node* node = find(key);
  return node ? to_number(key, *node, rule) : fallback;
}

std::optional<double> TomlTableReader::optional_number(std::string_view key,
                                                       const NumberRule& rule) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  return to_number(key, *node, rule);
}

double TomlTableReader::required_number(std::string_view key, const NumberRule& rule,
                                        std::string_view meaning) const {
  return to_number(key, require(key, meaning), rule);
}

std::int64_t TomlTableReader::integer(std::string_view key, const IntRule& rule,
                                      std::int64_t fallback) const {
  const toml::node* node = find(key);
  if (!node) return fallback;
  const auto* i = node->as_integer();
  if (!i) {
    // 2.0 is rejected too: a float where a count is expected is usually a mix-up of keys.
    const std::string range = rule.describe();
    const std::string expected = range.starts_with("an integer") ? range : range + " (an integer)";
    fail_value(key, *node, fmt::format("must be {}, not {}", expected, type_name(*node)));
  }
  const std::int64_t v = i->get();
  if (v < rule.lo || v > rule.hi) fail_value(key, *node, "must be " + rule.describe());
  return v;
}

bool TomlTableReader::boolean(std::string_view key, bool fallback) const {
  const toml::node* node = find(key);
  if (!node) return fallback;
  const auto* b = node->as_boolean();
  if (!b) fail_value(key, *node, fmt::format("must be true or false, not {}", type_name(*node)));
  return b->get();
}

std::string TomlTableReader::to_string(std::string_view key, const toml::node& node) const {
  const auto* s = node.as_string();
  if (!s) fail_value(key, node, fmt::format("must be a string, not {}", type_name(node)));
  return s->get();
}

std::string TomlTableReader::string(std::string_view key, std::string fallback) const {
  const toml::node* node = find(key);
  return node ? to_string(key, *node) : fallback;
}

std::string TomlTableReader::to_word(std::string_view key, const toml::node& node,
                                     const std::vector<std::string_view>& allowed) const {
  std::vector<std::string> quoted;
  for (const std::string_view a : allowed) quoted.push_back(toml_quote(a));
  std::vector<std::string_view> quoted_views(quoted.begin(), quoted.end());
  const std::string options = allowed.size() == 1 ? quoted[0] : "one of " + join(quoted_views);
  const auto* s = node.as_string();
  if (!s) fail_value(key, node, fmt::format("must be {}, not {}", options, type_name(node)));
  const std::string& word = s->get();
  if (std::find(allowed.begin(), allowed.end(), word) == allowed.end()) {
    // With a single allowed word a "did you mean" would only repeat it.
    const std::string hint = allowed.size() > 1 ? did_you_mean(word, allowed) : "";
    fail_value(key, node, "must be " + options + hint);
  }
  return word;
}

std::vector<double> TomlTableReader::to_number_array(std::string_view key, const toml::node& node,
                                                     const NumberRule& rule,
                                                     std::size_t min_size) const {
  const auto* array = node.as_array();
  if (!array) {
    fail_value(key, node,
               fmt::format("must be an array of numbers (each {}), not {}", rule.describe(),
                           type_name(node)));
  }
  if (array->size() < min_size) {
    fail_value(key, node,
               fmt::format("must have at least {} element{}, got {}", min_size,
                           min_size == 1 ? "" : "s", array->size()));
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = (*array)[i];
    double v = 0;
    if (const auto* integer_value = element.as_integer()) {
      v = static_cast<double>(integer_value->get());
    } else if (const auto* float_value = element.as_floating_point()) {
      v = float_value->get();
    } else {
      fail_value(key, node,
                 fmt::format("element {} must be a number, not {}", i + 1, type_name(element)),
                 &element);
    }
    if (!rule.accepts(v)) {
      fail_value(
          key, node,
          fmt::format("element {} = {} must be {}", i + 1, format_value(element), rule.describe()),
          &element);
    }
    values.push_back(v);
  }
  return values;
}

std::vector<std::size_t> TomlTableReader::to_word_list(std::string_view key, const toml::node& node,
                                                       const WordListRule& rule) const {
  const auto* array = node.as_array();
  if (!array) {
    fail_value(key, node,
               fmt::format("must be an array of {} names (e.g. {}), not {}", rule.noun,
                           rule.example, type_name(node)));
  }
  if (array->empty() && !rule.allow_empty) {
    fail_value(
        key, node,
        fmt::format("must name at least one {}; allowed: {}", rule.noun, join(rule.allowed)));
  }
  std::vector<std::size_t> indices;
  for (const toml::node& element : *array) {
    const auto* s = element.as_string();
    if (!s) {
      fail_value(key, node,
                 fmt::format("{} names must be strings (e.g. {}), not {}", rule.noun, rule.example,
                             type_name(element)),
                 &element);
    }
    const std::string& word = s->get();
    const auto it = std::find(rule.known.begin(), rule.known.end(), word);
    if (it == rule.known.end()) {
      fail_value(key, node,
                 fmt::format("unknown {} \"{}\"{}; allowed: {}", rule.noun, word,
                             did_you_mean(word, rule.allowed), join(rule.allowed)),
                 &element);
    }
    if (std::find(rule.allowed.begin(), rule.allowed.end(), word) == rule.allowed.end()) {
      fail_value(key, node,
                 fmt::format("{} \"{}\" is not allowed {}; allowed: {}", rule.noun, word,
                             rule.not_allowed_reason, join(rule.allowed)),
                 &element);
    }
    const auto index = static_cast<std::size_t>(it - rule.known.begin());
    if (std::find(indices.begin(), indices.end(), index) != indices.end()) {
      fail_value(key, node, fmt::format("{} \"{}\" is listed twice", rule.noun, word), &element);
    }
    indices.push_back(index);
  }
  return indices;
}

Vec3d TomlTableReader::to_vec3(std::string_view key, const toml::node& node,
                               const NumberRule& rule) const {
  const std::string expected =
      "must be an array of 3 numbers [x, y, z]" +
      (rule.unit.empty() ? std::string() : " in " + std::string(rule.unit));
  const auto* array = node.as_array();
  if (!array) fail_value(key, node, fmt::format("{}, not {}", expected, type_name(node)));
  if (array->size() != 3) {
    fail_value(key, node,
               fmt::format("{}, got {} element{}", expected, array->size(),
                           array->size() == 1 ? "" : "s"));
  }
  Vec3d v;
  for (int i = 0; i < 3; ++i) {
    const toml::node& element = (*array)[static_cast<std::size_t>(i)];
    const char axis = "xyz"[i];
    if (const auto* integer_value = element.as_integer()) {
      v[i] = static_cast<double>(integer_value->get());
    } else if (const auto* float_value = element.as_floating_point()) {
      v[i] = float_value->get();
    } else {
      fail_value(key, node, fmt::format("{} must be a number, not {}", axis, type_name(element)),
                 &element);
    }
    if (!rule.accepts(v[i])) {
      fail_value(key, node, fmt::format("{} must be {}", axis, rule.describe()), &element);
    }
  }
  return v;
}

Vec3d TomlTableReader::vec3(std::string_view key, const NumberRule& rule, Vec3d fallback) const {
  const toml::node* node = find(key);
  return node ? to_vec3(key, *node, rule) : fallback;
}

Vec3d TomlTableReader::required_vec3(std::string_view key, const NumberRule& rule,
                                     std::string_view meaning) const {
  return to_vec3(key, require(key, meaning), rule);
}

}  // namespace netsph
