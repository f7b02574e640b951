#pragma once
#include <tiny_gltf.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace candela {

class GltfBufferCharge;

// EXT_meshopt_compression (gltfpack's and glTF-Transform's compressed bufferViews) through meshoptimizer's decoder,
// where candela is built with it (libmeshoptimizer-dev; CANDELA_HAS_MESHOPT). Without it, a file that requires the
// extension is refused naming it (gltf_extensions.h), and one that only uses it is read from its fallback data.
bool gltfMeshoptAvailable();

// tinygltf reads every buffer, yet a meshopt file's fallback buffer (where the decoded bufferViews point, marked
// with the extension or not) usually has no uri and no data. Returns the file's bytes (.gltf text or .glb) with
// each such buffer given a 3-byte data URI in its place, for decodeMeshoptBufferViews to supersede; nothing when
// meshopt is unavailable, the file has no such buffer, or its JSON cannot be read (tinygltf then reports the problem).
std::optional<std::vector<uint8_t>> withMeshoptPlaceholderBuffers(const uint8_t* data, size_t size);

// Decodes every bufferView of `model` that EXT_meshopt_compression compresses (modes ATTRIBUTES, TRIANGLES and
// INDICES; filters OCTAHEDRAL, QUATERNION and EXPONENTIAL) into a new buffer, which the bufferView then names: the
// loader reads its accessors as any others. Corrupt data, or sizes the compressed data cannot hold, throw LoadError
// naming the file and the bufferView. The decoded buffers are charged to `charge`, the model's, before any is
// decoded: views that decode to more than the load may use are refused (LoadBudgetError) with nothing allocated.
void decodeMeshoptBufferViews(tinygltf::Model& model, const std::string& file, GltfBufferCharge& charge);

}  // namespace candela
