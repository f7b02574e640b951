// The checks of a material's members are generated from their list (kernel/material.h): every member the list
// marks checked is refused, by name, when it holds what its check rejects, and a default material passes.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "scene/material_checks.h"

namespace candela {
namespace {

constexpr size_t kTextures = 2;

// Puts into `member` a value its check rejects; false for the members checked by hand.
bool spoil(float& member, const char* check) {
  if (std::string(check) != "Finite") return false;
  member = std::numeric_limits<float>::quiet_NaN();
  return true;
}
bool spoil(Vec3& member, const char* check) {
  if (std::string(check) == "Finite")
    member.y = std::numeric_limits<float>::infinity();
  else if (std::string(check) == "NonNegative")
    member.z = -0.25f;
  else
    return false;
  return true;
}
bool spoil(int32_t& member, const char* check) {
  if (std::string(check) != "TextureIndex") return false;
  member = int32_t(kTextures);
  return true;
}
template <class T>
bool spoil(T&, const char*) {
  return false;
}

TEST(MaterialChecks, ADefaultMaterialPasses) { EXPECT_EQ(materialMemberProblem(Material{}, 0), ""); }

TEST(MaterialChecks, EveryCheckedMemberIsRefusedByName) {
  int checked = 0, expected = 0;
#define CANDELA_SPOIL_MEMBER(Type, name, value, check)                                                         \
  {                                                                                                            \
    Material m;                                                                                                \
    if (std::string(#check) != "ByHand") ++expected;                                                           \
    if (spoil(m.name, #check)) {                                                                               \
      ++checked;                                                                                               \
      const std::string problem = materialMemberProblem(m, kTextures);                                         \
      EXPECT_EQ(problem.rfind(std::string("a material's ") + #name + " ", 0), 0u) << #name << ": " << problem; \
    }                                                                                                          \
  }
  CANDELA_MATERIAL_MEMBERS(CANDELA_SPOIL_MEMBER)
#undef CANDELA_SPOIL_MEMBER
  EXPECT_EQ(checked, expected);  // every member not checked by hand
  EXPECT_GT(checked, 30);
}

TEST(MaterialChecks, TexturesInRangeAndNegativeColoursOfFiniteMembersPass) {
  Material m;
  m.baseColorTexture = int32_t(kTextures) - 1;
  m.emission = {0, 0, 0};
  m.baseColor = {-1.0f, 0.5f, 0.5f};  // Finite, not NonNegative: loaders clamp colours where they must
  EXPECT_EQ(materialMemberProblem(m, kTextures), "");
  m.normalTexture = -2;
  EXPECT_EQ(materialMemberProblem(m, kTextures), "a material's normalTexture names a missing texture");
}

}  // namespace
}  // namespace candela
