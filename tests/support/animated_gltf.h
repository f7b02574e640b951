#pragma once
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace candela::test {

constexpr float kSqrtHalf = 0.70710678f;

// A small animated glTF for the tests: a unit quad (emissive, facing +z) under two nodes and a camera at z = 10, with
// two animations.
//   "Move": node 0 translates linearly (0,0,0) -> (2,0,0) -> (2,4,0) at 0, 1, 2 s and turns linearly from 0 to
//           90 degrees about z over 0..2 s; node 1 (the quad's, at rest at (0,1,0)) scales by step 1 -> 3 at 1 s.
//   "Bounce": node 1 translates by cubic spline from (0,1,0) (out-tangent (0,2,0)) to (0,1,0) over 0..1 s.
struct AnimatedFile {
  nlohmann::json gltf;
  std::vector<uint8_t> buffer;

  // Adds an accessor of float data and returns its index.
  int add(const std::vector<float>& values, const char* type);

  AnimatedFile();

  // Writes animated.gltf and animated.bin into `folder`; returns the path of animated.gltf.
  std::string write(const std::filesystem::path& folder);
};

}  // namespace candela::test
