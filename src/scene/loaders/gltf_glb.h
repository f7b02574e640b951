#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace candela {

// The bytes of a .glb whose JSON chunk (of `jsonLength` bytes, from byte 20) is replaced by `text`: what the
// loader's passes that rewrite a file's JSON before tinygltf reads it (gltf_draco.h, gltf_meshopt.h) return.
std::vector<uint8_t> replaceGlbJson(const uint8_t* data, size_t size, size_t jsonLength, std::string text);

}  // namespace candela
