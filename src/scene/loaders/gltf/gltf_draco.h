#pragma once
#include <tiny_gltf.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene/loaders/gltf/gltf_buffer_charge.h"

namespace candela {

// KHR_draco_mesh_compression through Google's Draco library, where candela is built with it (libdraco-dev;
// CANDELA_HAS_DRACO). Without it, a file that requires the extension is refused naming it (gltf_extensions.h),
// and one that only uses it is read from its uncompressed fallback accessors.
bool gltfDracoAvailable();

// tinygltf refuses a primitive whose indices accessor has no bufferView, and a Draco primitive's never has one.
// Returns the file's bytes (.gltf text or .glb) with `indices` taken off every Draco-compressed primitive, for
// decodeDracoPrimitives to restore from the decoded faces; nothing when Draco is unavailable, the file has no
// such primitive, or its JSON cannot be read (tinygltf then reports the problem).
std::optional<std::vector<uint8_t>> withoutDracoIndices(const uint8_t* data, size_t size);

// Decodes every Draco-compressed triangle primitive of `model` into a new buffer with a bufferView and a new
// accessor per attribute and for the indices, which the primitive then names: the loader reads them as any
// others. Each attribute keeps its accessor's type, component type and normalisation and takes its values
// from the Draco attribute whose unique id the extension's `attributes` give it. Each decoded primitive's buffer
// is charged to `charge` (the load's budget) before it is filled. Corrupt or inconsistent Draco data throws
// LoadError naming the file and the primitive's JSON path.
void decodeDracoPrimitives(tinygltf::Model& model, const std::string& file, GltfBufferCharge& charge);

}  // namespace candela
