#pragma once
// Reads and validates a TOML case file into a CaseSpec. Every key is checked: a bad value,
// a missing required key or an unknown key (a typo) throws netsph::Error naming the file,
// line, column, key, the bad value and what is allowed.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "netsph/case/case_spec.hpp"

namespace netsph {

/// `overrides` are "dotted.key=value" strings from `--set` (value in TOML syntax; a bare
/// word is taken as a string). They replace or add keys before validation.
CaseSpec read_case_file(const std::filesystem::path& path,
                        const std::vector<std::string>& overrides = {});

/// Same, from text; `source_name` is used in error messages (e.g. "builtin:default") and, unless
/// `default_name` is given, as the name of a case without simulation.name.
CaseSpec read_case_string(std::string_view toml_text, const std::string& source_name,
                          const std::vector<std::string>& overrides = {},
                          const std::string& default_name = {});

/// A whole file as text; throws netsph::Error naming the file when it cannot be read.
std::string read_file_text(const std::filesystem::path& path);

}  // namespace netsph
