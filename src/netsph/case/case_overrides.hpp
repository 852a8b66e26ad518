#pragma once
// `--set dotted.key=value` overrides, applied to the parsed TOML document before it is
// validated, so an overridden value is checked exactly like one written in the file.
// Private to the case module (includes toml++).
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace netsph {

/// Applies `overrides` in order. A numeric key segment selects an entry of an array of tables
/// (0-based; the next free index appends a new entry); missing tables are created. Values
/// are TOML; a value that is not valid TOML is taken as a string. Nodes made from an override
/// carry the source path "--set <option>", so later errors name the option.
void apply_overrides(toml::table& root, const std::vector<std::string>& overrides);

}  // namespace netsph
