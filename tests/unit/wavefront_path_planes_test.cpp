// The wavefront schedule's planes of path state (backends/optix/wavefront_path_planes.h), packed and unpacked on the
// host with the functions the device programs use: the layout's static checks say every word is packed once; these
// say the generated code moves each word to its place and back.
#include <gtest/gtest.h>

#include <cstring>
#include <set>

#include "backends/optix/wavefront_path_planes.h"

namespace candela::optix {
namespace {

// A path whose 32-bit words are all different.
WavefrontPath distinctPath() {
  static_assert(std::is_trivially_copyable_v<WavefrontPath>);
  uint32_t words[sizeof(WavefrontPath) / 4];
  for (uint32_t i = 0; i < sizeof(WavefrontPath) / 4; ++i) words[i] = 0x40000000u + 977u * i;
  WavefrontPath path;
  std::memcpy(&path, words, sizeof path);
  return path;
}

TEST(WavefrontPathPlanes, EveryWordRoundTripsThroughThePlanes) {
  const WavefrontPath path = distinctPath();
  const uint32_t zeros[sizeof(WavefrontPath) / 4] = {};
  WavefrontPath back;
  std::memcpy(&back, zeros, sizeof back);
  for (uint32_t plane = 0; plane < kPathPlanes; ++plane) unpackPathPlane(packPathPlane(path, plane), plane, back);
  EXPECT_EQ(std::memcmp(&back, &path, sizeof path), 0);
}

TEST(WavefrontPathPlanes, ThePlanesHoldEachWordOnceWherePackedWordAtSaysItIs) {
  const WavefrontPath path = distinctPath();
  uint32_t pathWords[sizeof(WavefrontPath) / 4];
  std::memcpy(pathWords, &path, sizeof path);
  std::set<uint32_t> seen;
  for (uint32_t plane = 0; plane < kPathPlanes; ++plane) {
    const Words4 words = packPathPlane(path, plane);
    const uint32_t values[4] = {words.x, words.y, words.z, words.w};
    for (uint32_t word = 0; word < 4; ++word) {
      EXPECT_TRUE(seen.insert(values[word]).second) << "plane " << plane << " word " << word;
      // Find the word of the path holding this value: packedWordAt must place it here.
      for (uint32_t i = 0; i < sizeof(WavefrontPath) / 4; ++i) {
        if (pathWords[i] == values[word]) {
          EXPECT_EQ(packedWordAt(4 * i), 4 * plane + word) << "path word " << i;
        }
      }
    }
  }
  EXPECT_EQ(seen.size(), sizeof(WavefrontPath) / 4);
}

// An ended path stores only the result plane; the last launch reads the radiance and the ray count from it.
TEST(WavefrontPathPlanes, TheResultPlaneAloneGivesTheRadianceAndTheRays) {
  WavefrontPath path;
  path.state.radiance = {0.5f, 2.0f, 3.25f};
  path.state.rays = 7;
  path.state.depth = 3;
  WavefrontPath ended;
  unpackPathPlane(packPathPlane(path, kPathResultPlane), kPathResultPlane, ended);
  EXPECT_EQ(ended.state.radiance.x, 0.5f);
  EXPECT_EQ(ended.state.radiance.y, 2.0f);
  EXPECT_EQ(ended.state.radiance.z, 3.25f);
  EXPECT_EQ(ended.state.rays, 7u);
}

}  // namespace
}  // namespace candela::optix
