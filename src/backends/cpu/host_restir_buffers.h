#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "kernel/restir/restir_buffers.h"

namespace candela {

// The CPU backend's ReSTIR buffers (kernel/restir/restir_buffers.h), one vector per line of CANDELA_RESTIR_BUFFERS,
// with the history's camera.
class HostRestirBuffers {
 public:
  // view(firstSampleOfFilm): RestirView::hasHistory says when a sample reuses the history.
  // Buffers for a width x height image, with no history.
  void reset(uint32_t width, uint32_t height) {
#define CANDELA_RESIZE_RESTIR_BUFFER(Type, name, count, description) name##_.assign(count(width, height), Type{});
    CANDELA_RESTIR_BUFFERS(CANDELA_RESIZE_RESTIR_BUFFER)
#undef CANDELA_RESIZE_RESTIR_BUFFER
    hasHistory_ = false;
  }
  void dropHistory() { hasHistory_ = false; }

  RestirView view(bool firstSampleOfFilm) {
    RestirView v;
#define CANDELA_POINT_AT_RESTIR_BUFFER(Type, name, count, description) v.name = name##_.data();
    CANDELA_RESTIR_BUFFERS(CANDELA_POINT_AT_RESTIR_BUFFER)
#undef CANDELA_POINT_AT_RESTIR_BUFFER
    v.previousCamera = previousCamera_;
    v.hasHistory = hasHistory_ && firstSampleOfFilm ? 1u : 0u;
    return v;
  }

  // After both passes of a sample seen through `camera`: its surfaces and reservoirs are the next one's history.
  void endSample(const Camera& camera) {
    std::swap(surfaces_, previousSurfaces_);
    previousCamera_ = camera;
    hasHistory_ = true;
  }

 private:
#define CANDELA_RESTIR_BUFFER_MEMBER(Type, name, count, description) std::vector<Type> name##_;
  CANDELA_RESTIR_BUFFERS(CANDELA_RESTIR_BUFFER_MEMBER)
#undef CANDELA_RESTIR_BUFFER_MEMBER
  Camera previousCamera_;
  bool hasHistory_ = false;
};

}  // namespace candela
