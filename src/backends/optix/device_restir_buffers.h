#pragma once
#include <cstdint>
#include <utility>

#include "backends/optix/device_buffer.h"
#include "kernel/restir/restir_buffers.h"

namespace candela::optix {

// The OptiX backend's ReSTIR buffers (kernel/restir/restir_buffers.h) in device memory, one per line of
// CANDELA_RESTIR_BUFFERS, with the history's camera. Every pass writes what a later one reads before it is read, so
// they need no clearing.
class DeviceRestirBuffers {
 public:
  // view(firstSampleOfFilm): RestirView::hasHistory says when a sample reuses the history.
  // Buffers for a width x height image (none for 0 x 0), with no history.
  void reset(uint32_t width, uint32_t height) {
#define CANDELA_ALLOCATE_RESTIR_BUFFER(Type, name, count, description) \
  name##_ = DeviceBuffer();                                            \
  if (count(width, height) > 0) name##_ = DeviceBuffer(count(width, height) * sizeof(Type), description);
    CANDELA_RESTIR_BUFFERS(CANDELA_ALLOCATE_RESTIR_BUFFER)
#undef CANDELA_ALLOCATE_RESTIR_BUFFER
    hasHistory_ = false;
  }
  void dropHistory() { hasHistory_ = false; }

  RestirView view(bool firstSampleOfFilm) const {
    RestirView v;
#define CANDELA_POINT_AT_RESTIR_BUFFER(Type, name, count, description) v.name = name##_.as<Type>();
    CANDELA_RESTIR_BUFFERS(CANDELA_POINT_AT_RESTIR_BUFFER)
#undef CANDELA_POINT_AT_RESTIR_BUFFER
    v.previousCamera = previousCamera_;
    v.hasHistory = hasHistory_ && firstSampleOfFilm ? 1u : 0u;
    return v;
  }

  // After both launches of a sample seen through `camera`: its surfaces and reservoirs are the next one's history.
  void endSample(const Camera& camera) {
    std::swap(surfaces_, previousSurfaces_);
    previousCamera_ = camera;
    hasHistory_ = true;
  }

 private:
#define CANDELA_RESTIR_BUFFER_MEMBER(Type, name, count, description) DeviceBuffer name##_;
  CANDELA_RESTIR_BUFFERS(CANDELA_RESTIR_BUFFER_MEMBER)
#undef CANDELA_RESTIR_BUFFER_MEMBER
  Camera previousCamera_;
  bool hasHistory_ = false;
};

}  // namespace candela::optix
