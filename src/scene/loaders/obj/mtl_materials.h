#pragma once
#include <tiny_obj_loader.h>

#include <string>

#include "io/load_diagnostics.h"
#include "io/path_confinement.h"
#include "scene/loaders/texture_table.h"

namespace candela {

// Maps one MTL material onto the material models:
//   illum 3 or 5 (reflection, ray traced) -> Mirror tinted by Ks
//   illum 4, 6 or 7 (refraction)          -> Glass with index Ni, tinted by Tf
//   any PBR extension value (Pr, Pm, Ps, Pc, Pcr, aniso, map_Pr, map_Pm, map_Ps) -> Disney
//   a non-black Ks                        -> BlinnPhong (Kd, Ks, Ns)
//   otherwise                             -> Diffuse (Kd)
// Ke is the emitted radiance; d (or 1 - Tr) below 1 makes the material blend; map_d makes it alpha-tested.
// map_Kd, map_Ke, map_d, map_Pr, map_Pm and norm become textures, found relative to `textureDirectory` and read
// only where `files` allows (path_confinement.h).
// Features without a counterpart (map_Ks, map_Ns, map_Ps, bump height maps, texture -o/-s transforms) are
// reported in `warnings` and left out.
Material materialFromMtl(const tinyobj::material_t& mtl, const std::string& mtlFile,
                         const std::string& textureDirectory, const PathRule& files, TextureTable& textures,
                         LoadWarnings& warnings);

}  // namespace candela
