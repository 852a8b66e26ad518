#pragma once
// The one exception type of netsph. It carries where the problem is (a case file position
// "file:line:column", a command-line option, or a module) and what to do about it; main()
// prints it as one line and exits non-zero.
#include <stdexcept>
#include <string>

namespace netsph {

class Error : public std::runtime_error {
 public:
  Error(std::string where, std::string message)
      : std::runtime_error(where.empty() ? message : where + ": " + message),
        where_(std::move(where)),
        message_(std::move(message)) {}

  const std::string& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  std::string where_;
  std::string message_;
};

}  // namespace netsph
