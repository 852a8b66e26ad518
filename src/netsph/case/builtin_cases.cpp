#include "netsph/case/builtin_cases.hpp"

namespace netsph {

std::string_view builtin_case_text(std::string_view name) {
  if (name == "default") name = kDefaultCase;
  for (const auto& c : builtin_cases())
    if (c.name == name) return c.text;
  return {};
}

}  // namespace netsph
