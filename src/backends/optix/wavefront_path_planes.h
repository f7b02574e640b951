#pragma once
// How the wavefront schedule keeps a path between launches in the planes of WavefrontBuffers::paths, declared once:
// which word of which plane holds which member, with the packing and unpacking generated from that declaration and
// checked against PathState when this compiles. Host and device code alike (tests check the packing on the host).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "backends/optix/wavefront_buffers.h"
#include "kernel/path_vertex.h"

namespace candela::optix {

// All the wavefront schedule keeps of a path: its state and where its sampler goes on.
struct WavefrontPath {
  PathState state;
  uint32_t dimension = 0;  // the sampler's next dimension
};

// The planes in order, each as the members of WavefrontPath its words x, y, z and w hold: 32-bit floats and
// unsigned integers, as their bits. Every word of WavefrontPath is packed exactly once (checked below).
// The first plane is all an ended path keeps and the last launch reads (kPathResultPlane).
#define CANDELA_PATH_PLANES(X)                                                    \
  X(state.radiance.x, state.radiance.y, state.radiance.z, state.rays)             \
  X(state.beta.x, state.beta.y, state.beta.z, state.etaScale)                     \
  X(state.lastScatter.x, state.lastScatter.y, state.lastScatter.z, state.bsdfPdf) \
  X(state.lastNormal.x, state.lastNormal.y, state.lastNormal.z, state.depth)      \
  X(state.cone.width, state.cone.spread, dimension, state.bounceFlags)

constexpr uint32_t kPathResultPlane = 0;

// A member's bits as a plane's word, and back.
template <class T>
CANDELA_FN uint32_t packWord(T value) {
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, uint32_t>, "a plane's word holds a float or a uint32_t");
  if constexpr (std::is_same_v<T, uint32_t>) {
    return value;
  } else {
#if defined(__CUDA_ARCH__)
    return __float_as_uint(value);
#else
    uint32_t word;
    std::memcpy(&word, &value, sizeof word);
    return word;
#endif
  }
}

template <class T>
CANDELA_FN void unpackWord(uint32_t word, T& value) {
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, uint32_t>, "a plane's word holds a float or a uint32_t");
  if constexpr (std::is_same_v<T, uint32_t>) {
    value = word;
  } else {
#if defined(__CUDA_ARCH__)
    value = __uint_as_float(word);
#else
    std::memcpy(&value, &word, sizeof value);
#endif
  }
}

// Plane `plane` of `path`. With a constant plane (a literal, or an unrolled loop's counter) only its words are
// computed.
CANDELA_FN Words4 packPathPlane(const WavefrontPath& path, uint32_t plane) {
  uint32_t k = 0;
#define CANDELA_PACK_PLANE(wordX, wordY, wordZ, wordW) \
  if (plane == k++) return {packWord(path.wordX), packWord(path.wordY), packWord(path.wordZ), packWord(path.wordW)};
  CANDELA_PATH_PLANES(CANDELA_PACK_PLANE)
#undef CANDELA_PACK_PLANE
  return {};
}

// Sets the members of `path` that plane `plane` holds from `words`; the others stay. `words` is taken by value: a
// plane read from device memory is then loaded whole, as one 16-byte load, whichever of its members are used.
CANDELA_FN void unpackPathPlane(Words4 words, uint32_t plane, WavefrontPath& path) {
  uint32_t k = 0;
#define CANDELA_UNPACK_PLANE(wordX, wordY, wordZ, wordW) \
  if (plane == k++) {                                    \
    unpackWord(words.x, path.wordX);                     \
    unpackWord(words.y, path.wordY);                     \
    unpackWord(words.z, path.wordZ);                     \
    unpackWord(words.w, path.wordW);                     \
    return;                                              \
  }
  CANDELA_PATH_PLANES(CANDELA_UNPACK_PLANE)
#undef CANDELA_UNPACK_PLANE
}

// Where the member at byte `offset` of WavefrontPath is packed: 4 x plane + word (x 0, y 1, z 2, w 3), or
// kUnpacked. For code that reads or writes single words of a plane to check where they are.
constexpr uint32_t kUnpacked = ~0u;
constexpr uint32_t packedWordAt(size_t offset) {
  uint32_t word = 0;
#define CANDELA_LOCATE_WORD(member)                           \
  if (offset == offsetof(WavefrontPath, member)) return word; \
  ++word;
#define CANDELA_LOCATE_PLANE(wordX, wordY, wordZ, wordW) \
  CANDELA_LOCATE_WORD(wordX) CANDELA_LOCATE_WORD(wordY) CANDELA_LOCATE_WORD(wordZ) CANDELA_LOCATE_WORD(wordW)
  CANDELA_PATH_PLANES(CANDELA_LOCATE_PLANE)
#undef CANDELA_LOCATE_PLANE
#undef CANDELA_LOCATE_WORD
  return kUnpacked;
}

constexpr bool packedAt(size_t offset, uint32_t plane, uint32_t word) {
  return packedWordAt(offset) == 4 * plane + word;
}
constexpr bool packedIn(size_t offset, uint32_t plane) { return packedWordAt(offset) / 4 == plane; }

// Whether the planes pack every 32-bit word of WavefrontPath exactly once: each packed member is a 4-byte word of its
// own, none twice. With the sizes below equal, no member goes unpacked.
constexpr bool packsEveryWordOnce() {
  static_assert(sizeof(WavefrontPath) / 4 <= 64, "one bit per word of WavefrontPath below");
  uint64_t packed = 0;
#define CANDELA_PACK_ONCE(member)                                                                        \
  {                                                                                                      \
    constexpr size_t offset = offsetof(WavefrontPath, member);                                           \
    static_assert(sizeof(WavefrontPath{}.member) == 4 && offset % 4 == 0, #member " is no 32-bit word"); \
    if (packed & (uint64_t(1) << (offset / 4))) return false;                                            \
    packed |= uint64_t(1) << (offset / 4);                                                               \
  }
#define CANDELA_PACK_PLANE_ONCE(wordX, wordY, wordZ, wordW) \
  CANDELA_PACK_ONCE(wordX) CANDELA_PACK_ONCE(wordY) CANDELA_PACK_ONCE(wordZ) CANDELA_PACK_ONCE(wordW)
  CANDELA_PATH_PLANES(CANDELA_PACK_PLANE_ONCE)
#undef CANDELA_PACK_PLANE_ONCE
#undef CANDELA_PACK_ONCE
  return packed == (uint64_t(1) << (sizeof(WavefrontPath) / 4)) - 1;
}

#define CANDELA_ONE_PLANE(wordX, wordY, wordZ, wordW) +1
static_assert(0 CANDELA_PATH_PLANES(CANDELA_ONE_PLANE) == kPathPlanes,
              "kPathPlanes (wavefront_buffers.h) must count the planes CANDELA_PATH_PLANES declares");
#undef CANDELA_ONE_PLANE
static_assert(sizeof(WavefrontPath) == sizeof(PathState) + sizeof(uint32_t),
              "PathState must be whole 32-bit words, or a plane cannot hold them");
static_assert(sizeof(WavefrontPath) == kPathPlanes * sizeof(Words4),
              "the planes must hold all of PathState and the dimension: a member added to PathState needs a word");
static_assert(packsEveryWordOnce(), "CANDELA_PATH_PLANES must pack each word of WavefrontPath once");

}  // namespace candela::optix
