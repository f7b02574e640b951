#pragma once
// OptiX calls that fill a log of the compiler's messages: when they fail, the log goes into the error.
#include <optix_types.h>

#include <cstddef>
#include <cstring>
#include <string>

namespace candela::optix {

// Throws OptixError naming `what`, as checkOptix does, with `log` after it.
[[noreturn]] void throwWithLog(OptixResult result, const char* what, const std::string& log);

// Calls `call(log, &logSize)` and throws as throwWithLog when it fails.
template <class Call>
void checkWithLog(const char* what, Call call) {
  char log[2048];
  size_t logSize = sizeof log;
  const OptixResult result = call(log, &logSize);
  if (result != OPTIX_SUCCESS) throwWithLog(result, what, std::string(log, strnlen(log, sizeof log)));
}

}  // namespace candela::optix
