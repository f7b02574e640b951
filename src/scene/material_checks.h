#pragma once
// The checks of a material's members that their list names (CANDELA_MATERIAL_MEMBERS, kernel/material.h), for
// scene validation (scene.h) and the scene cache's.
#include <cstddef>
#include <string>

#include "kernel/material.h"

namespace candela {

// What is wrong with the first member of `m` that fails its check, as "a material's <member> ..."; empty where
// none does. `textureCount`: how many textures the scene has.
std::string materialMemberProblem(const Material& m, size_t textureCount);

}  // namespace candela
