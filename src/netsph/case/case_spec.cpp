#include "netsph/case/case_spec.hpp"

#include <fmt/format.h>

namespace netsph {

std::string SourceLocation::str() const {
  // Line 0 means "no position": a --set option or a programmatically built case.
  if (line == 0) return file;
  return fmt::format("{}:{}:{}", file, line, column);
}

}  // namespace netsph
