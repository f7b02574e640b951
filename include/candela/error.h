#pragma once
#include <stdexcept>
#include <string>

namespace candela::api {

// Every failure the library reports: a bad option, a scene that cannot load, a render that cannot run. what() is
// one line, the message the `candela` command prints after "candela: " for the same failure.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message);
  ~Error() override;  // defined in the library, which then holds the type's identity for every program that catches it
};

}  // namespace candela::api
