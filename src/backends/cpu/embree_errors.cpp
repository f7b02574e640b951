#include "backends/cpu/embree_errors.h"

namespace candela {

namespace {

const char* errorName(RTCError error) {
  switch (error) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT: return "an invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "an invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "a CPU Embree does not support";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "an unknown error";
  }
}

}  // namespace

std::string embreeFailure(RTCError error, const std::string& what, const EmbreeSceneSize& size) {
  if (error == RTC_ERROR_OUT_OF_MEMORY)
    return "not enough memory for Embree while " + what + ": the scene has " + std::to_string(size.meshes) +
           " meshes of " + std::to_string(size.triangles) + " triangles in all and " + std::to_string(size.instances) +
           " instances";
  return "Embree failed while " + what + " (" + errorName(error) + ", error " + std::to_string(int(error)) + ")";
}

}  // namespace candela
