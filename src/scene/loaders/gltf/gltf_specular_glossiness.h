#pragma once
#include "core/math.h"

namespace candela {

// KHR_materials_pbrSpecularGlossiness in the metallic-roughness model, as the conversion that Khronos published
// with the extension (and glTF-Transform and Babylon.js use) does it: the metallic value solves the dielectric
// and metallic blend for the perceived brightness of the diffuse and specular colours (dielectrics reflect 4%),
// the base colour blends the colour each reading implies by metallic squared, and roughness is 1 - glossiness.
// It is exact for a pure dielectric with a 4% specular and for a pure metal; in between, and for coloured
// specular on dielectrics, it is the closest the metallic-roughness model comes.
struct MetallicRoughness {
  Vec3 baseColor;
  float metallic = 0.0f;
  float roughness = 1.0f;
};

MetallicRoughness metallicRoughnessFromSpecularGlossiness(Vec3 diffuse, Vec3 specular, float glossiness);

}  // namespace candela
