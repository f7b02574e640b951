#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace candela {

// Checks the byte ranges a glTF file's JSON declares before tinygltf reads it: tinygltf takes a negative
// byteOffset as 0, and a bufferView that EXT_meshopt_compression decodes is never read where it claims to lie,
// so neither would otherwise be noticed. Every byteOffset of a bufferView, an accessor or a sparse accessor's
// indices and values must be a whole number from 0, and every bufferView must lie inside its buffer's
// byteLength. A problem throws LoadError naming the file and the JSON path; a file whose JSON cannot be read is
// left to tinygltf.
void checkGltfByteRanges(const uint8_t* data, size_t size, const std::string& file);

}  // namespace candela
