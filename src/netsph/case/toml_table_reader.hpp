#pragma once
// TomlTableReader: typed, validated access to one TOML table of a case file. It knows the
// table's allowed keys up front, so a typo is reported as "unknown key" (with a suggestion)
// before it can surface as a confusing "missing required key". Every error names the
// position, the dotted key, the bad value and what is allowed.
//
// Private to the case module: this header includes toml++, which netsph_case links privately.
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "netsph/case/case_spec.hpp"
#include "netsph/core/enum_names.hpp"
#include "netsph/core/error.hpp"
#include "netsph/core/vec3.hpp"

namespace netsph {

/// Maps toml++ source regions to error positions. Nodes parsed from a `--set` option carry
/// the option as their path; nodes without a path fall back to the case source name.
class TomlSource {
 public:
  explicit TomlSource(std::string fallback) : fallback_(std::move(fallback)) {}

  /// "file:line:column"; just the option text for `--set` values (their columns would
  /// point into a synthetic document); the fallback name for nodes without a source.
  std::string where(const toml::source_region& region) const { return location(region).str(); }
  SourceLocation location(const toml::source_region& region) const;
  const std::string& name() const { return fallback_; }

 private:
  std::string fallback_;
};

/// The prefix every `--set` value's source path starts with.
inline constexpr std::string_view kOverrideSourcePrefix = "--set ";

/// The allowed range of a floating-point key. Integers are accepted for floats.
struct NumberRule {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
  std::string_view unit;

  static NumberRule any(std::string_view unit) { return {.unit = unit}; }
  static NumberRule positive(std::string_view unit) {
    return {.lo = 0, .lo_open = true, .unit = unit};
  }
  static NumberRule non_negative(std::string_view unit) { return {.lo = 0, .unit = unit}; }
  static NumberRule closed(double lo, double hi, std::string_view unit) {
    return {.lo = lo, .hi = hi, .unit = unit};
  }
  /// (lo, hi]
  static NumberRule left_open(double lo, double hi, std::string_view unit) {
    return {.lo = lo, .hi = hi, .lo_open = true, .unit = unit};
  }

  bool accepts(double v) const;
  /// "> 0 m", "in [1, 100000] kg/m^3", "a finite number in m"
  std::string describe() const;
};

/// The allowed range of an integer key.
struct IntRule {
  std::int64_t lo;
  std::int64_t hi;
  /// "2 or 3", "an integer in [1, 10]"
  std::string describe() const;
};

/// An array of distinct words from a fixed set: wall faces, periodic axes.
struct WordListRule {
  std::string_view noun;                  ///< "face", "axis"
  std::vector<std::string_view> known;    ///< every word of the set
  std::vector<std::string_view> allowed;  ///< the words allowed here: a subset of `known`
  /// Why a known word may not be allowed: "in 2D because ...".
  std::string_view not_allowed_reason;
  std::string_view example;  ///< "[\"xmin\", \"xmax\", \"zmin\"]"
  bool allow_empty = false;
};

/// Optional extra hint for an unknown key that is not close to any allowed key, e.g. "it
/// belongs in [fluid]". Returns "" for none.
using UnknownKeyHint = std::string (*)(std::string_view key);

class TomlTableReader {
 public:
  /// `path`: dotted prefix of the table's keys in messages ("fluid", "wall[2]"); `title`:
  /// how the table itself is named ("[fluid]", "wall[2]"). Throws for keys not in `allowed`.
  TomlTableReader(const toml::table& table, std::string path, std::string title,
                  std::vector<std::string_view> allowed, const TomlSource& source,
                  UnknownKeyHint hint = nullptr);

  const toml::table& table() const { return table_; }
  const std::string& path() const { return path_; }
  const std::string& title() const { return title_; }
  const TomlSource& source() const { return source_; }
  /// "fluid.density"
  std::string key_path(std::string_view key) const;
  SourceLocation location() const { return source_.location(table_.source()); }

  const toml::node* find(std::string_view key) const;
  bool has(std::string_view key) const { return find(key) != nullptr; }
  /// Throws "<title> is missing required key '<key>' (<meaning>)" at the table.
  const toml::node& require(std::string_view key, std::string_view meaning) const;

  double number(std::string_view key, const NumberRule& rule, double fallback) const;
  std::optional<double> optional_number(std::string_view key, const NumberRule& rule) const;
  double required_number(std::string_view key, const NumberRule& rule,
                         std::string_view meaning) const;
  double to_number(std::string_view key, const toml::node& node, const NumberRule& rule) const;

  std::int64_t integer(std::string_view key, const IntRule& rule, std::int64_t fallback) const;
  bool boolean(std::string_view key, bool fallback) const;
  std::string string(std::string_view key, std::string fallback) const;
  std::string to_string(std::string_view key, const toml::node& node) const;

  /// An array of at least `min_size` numbers, each within `rule`. Messages number the
  /// elements from 1 and point at the bad one.
  std::vector<double> to_number_array(std::string_view key, const toml::node& node,
                                      const NumberRule& rule, std::size_t min_size) const;
  /// The words of an array of distinct words, as indices into `rule.known`, in file order.
  std::vector<std::size_t> to_word_list(std::string_view key, const toml::node& node,
                                        const WordListRule& rule) const;

  /// An array of exactly three numbers.
  Vec3d vec3(std::string_view key, const NumberRule& rule, Vec3d fallback) const;
  Vec3d required_vec3(std::string_view key, const NumberRule& rule, std::string_view meaning) const;
  Vec3d to_vec3(std::string_view key, const toml::node& node, const NumberRule& rule) const;

  /// An enumerated string key: one of the words of `choices` (an enum's table of names,
  /// core/enum_names.hpp), listed in the table's order when the value is not.
  template <typename E, std::size_t N>
  E choice(std::string_view key, const std::array<EnumName<E>, N>& choices, E fallback) const {
    const toml::node* node = find(key);
    return node ? to_choice(key, *node, choices) : fallback;
  }
  template <typename E, std::size_t N>
  E to_choice(std::string_view key, const toml::node& node,
              const std::array<EnumName<E>, N>& choices) const {
    const auto names = names_of(choices);
    const std::string word =
        to_word(key, node, std::vector<std::string_view>(names.begin(), names.end()));
    // to_word() accepted the word, so the table has it.
    return value_of(choices, word).value_or(choices.front().value);
  }

  /// Throws "<key path> = <value>: <message>" at the position of `at` (the value itself,
  /// or an element of it).
  [[noreturn]] void fail_value(std::string_view key, const toml::node& value,
                               std::string_view message, const toml::node* at = nullptr) const;
  /// Throws `message` at the position of the table.
  [[noreturn]] void fail_table(std::string_view message) const;
  /// The inline table `value` of `key`; anything else throws "<key path> = <value>:
  /// <expected>, not <its type>" (expected: "must be a table such as { ... }").
  const toml::table& nested_table(std::string_view key, const toml::node& value,
                                  std::string_view expected) const;

 private:
  void reject_unknown_keys(UnknownKeyHint hint) const;
  /// The string value of `node`, which must be one of `allowed`.
  std::string to_word(std::string_view key, const toml::node& node,
                      const std::vector<std::string_view>& allowed) const;

  const toml::table& table_;
  std::string path_;
  std::string title_;
  std::vector<std::string_view> allowed_;
  const TomlSource& source_;
};

// ---- helpers shared with the case reader -------------------------------------------------

/// Compact one-line TOML-like rendering of a value for messages (long values are cut).
std::string format_value(const toml::node& node);
/// A TOML basic string: "a \"b\"" (also valid TOML, so overrides can reuse it).
std::string toml_quote(std::string_view s);
/// "[0, 0, -9.81]"
std::string format_vec3(const Vec3d& v);
/// Shortest round-trip rendering: 1000 -> "1000", 1e-6 -> "1e-06".
std::string format_number(double v);
/// "a string", "an integer", "a table", ...
std::string_view type_name(const toml::node& node);
/// The closest of `candidates` to `word` by edit distance, or "" when none is close.
std::string closest_match(std::string_view word, const std::vector<std::string_view>& candidates);
/// " (did you mean 'x'?)" or "".
std::string did_you_mean(std::string_view word, const std::vector<std::string_view>& candidates);
/// "a, b, c"
std::string join(const std::vector<std::string_view>& words, std::string_view separator = ", ");
/// The first key of `table` (in file order) that is not in `allowed`, with its value; null
/// when every key is allowed.
std::pair<const toml::key*, const toml::node*> first_unknown_key(
    const toml::table& table, const std::vector<std::string_view>& allowed);
/// The position of a key, falling back to its value's when the key was made by an override.
const toml::source_region& key_region(const toml::key& key, const toml::node& value);

}  // namespace netsph
