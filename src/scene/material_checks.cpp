#include "scene/material_checks.h"

namespace candela {

namespace {

// One function per check of the list, named after it; each says what is wrong, or nothing.
template <class T>
const char* Finite(const T& value, size_t) {
  return isFinite(value) ? nullptr : "is not finite";
}
const char* NonNegative(Vec3 v, size_t) {
  return isFinite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f ? nullptr : "is negative or not finite";
}
const char* TextureIndex(int32_t texture, size_t textureCount) {
  return texture == kNoTexture || (texture >= 0 && size_t(texture) < textureCount) ? nullptr
                                                                                   : "names a missing texture";
}
template <class T>
const char* ByHand(const T&, size_t) {
  return nullptr;
}

}  // namespace

std::string materialMemberProblem(const Material& m, size_t textureCount) {
#define CANDELA_CHECK_MATERIAL_MEMBER(Type, name, value, check) \
  if (const char* problem = check(m.name, textureCount)) return std::string("a material's " #name " ") + problem;
  CANDELA_MATERIAL_MEMBERS(CANDELA_CHECK_MATERIAL_MEMBER)
#undef CANDELA_CHECK_MATERIAL_MEMBER
  return {};
}

}  // namespace candela
