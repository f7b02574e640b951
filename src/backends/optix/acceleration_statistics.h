#pragma once
#include <cstdint>

namespace candela {

// Acceleration-structure builds since a backend was made, for checking that scene updates rebuild only what
// changed.
struct AccelerationStatistics {
  uint64_t meshBuilds = 0;      // meshes built, into GASes of their own or batches
  uint64_t batchedMeshes = 0;   // of those, built many to a GAS
  uint64_t instanceBuilds = 0;  // IAS builds
};

}  // namespace candela
