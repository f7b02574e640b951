#pragma once
// The lean kernel: the path tracer without the parts most scenes do not use (the hair and diffuse-transmission
// models, curves and thin films), which a GPU module is compiled as where CANDELA_LEAN_KERNEL is defined for the
// whole module. The OptiX backend renders a scene that uses none of them with lean modules (backends/optix/
// program_use.h), which compile in less time on a first start; the CPU build, and every module of a scene that uses
// them, are the full kernel. Leaving a part out is only ever a constant condition here that the compiler folds away:
// the source stays one.
#include "kernel/material.h"

namespace candela {

#if defined(CANDELA_LEAN_KERNEL)
constexpr bool kLeanKernel = true;
#else
constexpr bool kLeanKernel = false;
#endif

// The models the lean kernel keeps: the three shading models the viewers switch between, diffuse, mirror and glass
// (and a mix, which resolves to one of the materials before a model is built). A model added to the list is in the
// full kernel only until it is named here.
CANDELA_FN constexpr bool isLeanKernelModel(MaterialType type) {
  return type == MaterialType::Diffuse || type == MaterialType::BlinnPhong || type == MaterialType::Pbr ||
         type == MaterialType::Disney || type == MaterialType::Mirror || type == MaterialType::Glass ||
         type == MaterialType::Mix;
}

// Whether this compile of the kernel has the model of `type`.
CANDELA_FN constexpr bool kernelHasModel(MaterialType type) { return !kLeanKernel || isLeanKernelModel(type); }

// Whether the lean kernel renders `m` as the full kernel does: its model is there, and it has no thin film.
CANDELA_FN bool leanKernelRenders(const Material& m) { return isLeanKernelModel(m.type) && !(m.iridescence > 0.0f); }

}  // namespace candela
