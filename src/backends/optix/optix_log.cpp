#include "backends/optix/optix_log.h"

#include "backends/optix/optix_error.h"

namespace candela::optix {

void throwWithLog(OptixResult result, const char* what, const std::string& log) {
  try {
    checkOptix(result, what);
  } catch (const OptixError& e) {
    throw OptixError(result, std::string(e.what()) + ": " + log);
  }
  throw OptixError(result, std::string(what) + ": " + log);  // a result checkOptix lets pass
}

}  // namespace candela::optix
