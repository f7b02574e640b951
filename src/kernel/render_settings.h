#pragma once
#include <cstdint>

#include "core/path_sampler.h"
#include "kernel/texture_filtering.h"

namespace candela {

// How next-event estimation picks an emissive triangle: through the light BVH, by how much each can light the
// shading point, or by emitted power alone from one table.
enum class LightSamplerKind : uint32_t { Bvh, Power };

// How the camera ray's first vertex gets its direct light: by next-event estimation and BSDF sampling combined by
// MIS, as every other vertex (Off), or from a reservoir of ReSTIR DI reused across pixels and samples
// (kernel/restir/restir_passes.h): unbiased (Di), or with the cheaper 1/M weights that leave a bias (DiBiased).
enum class RestirMode : uint32_t { Off, Di, DiBiased };

struct RenderSettings {
  uint32_t width = 512;
  uint32_t height = 512;
  uint32_t maxDepth = 8;       // path segments after the camera ray; 1 = direct lighting only
  uint32_t rouletteDepth = 3;  // bounces before Russian roulette may end a path
  uint32_t seed = 0;
  SamplerKind sampler = SamplerKind::Sobol;
  // How textures are filtered over the footprints of camera rays and of their mirror and glass bounces
  // (kernel/ray_cone.h); Finest reads level 0 everywhere, as before mip pyramids.
  TextureFilter textureFilter = TextureFilter::Anisotropic;
  LightSamplerKind lightSampler = LightSamplerKind::Bvh;
  RestirMode restir = RestirMode::Off;
};

}  // namespace candela
