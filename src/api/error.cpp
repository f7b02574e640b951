#include "candela/error.h"

namespace candela::api {

Error::Error(const std::string& message) : std::runtime_error(message) {}
Error::~Error() = default;

}  // namespace candela::api
