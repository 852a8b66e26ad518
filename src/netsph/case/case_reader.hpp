#pragma once
// Reads and validates a TOML case file into a CaseSpec. Every key is checked: a bad value,
// a missing required key or an unknown key (a typo) throws netsph::Error naming the file,
// line, column, key, the bad value and what is allowed.
#include <cstdint>
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

/// The most a case file may hold: 4 MiB, about 800 times the largest case shipped (5 KB), room
/// for a prescribed motion's history of some 50,000 samples. toml++ makes a node of every
/// value, several times the text's size in memory, so an unbounded file (a device such as
/// /dev/zero, a log given by mistake) would exhaust memory before any message.
inline constexpr std::uintmax_t kMaxCaseFileBytes = std::uintmax_t{4} << 20;

/// A whole regular file of at most `max_bytes` as text; throws netsph::Error naming the file
/// when it cannot be read, is not a regular file (a device, a pipe) or is larger.
std::string read_file_text(const std::filesystem::path& path,
                           std::uintmax_t max_bytes = kMaxCaseFileBytes);

}  // namespace netsph
