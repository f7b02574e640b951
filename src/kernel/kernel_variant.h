#pragma once
// The lean kernel: the path tracer without the parts most scenes do not use (the hair and diffuse-transmission
// models, curves and thin films), which a GPU module is compiled as where CANDELA_LEAN_KERNEL is defined for the
// whole module. The OptiX backend renders a scene that uses none of them with lean modules (backends/optix/
// program_use.h), which compile in less time on a first start; the CPU build, and every module of a scene that uses
// them, are the full kernel. Leaving a part out is only ever a constant condition that the compiler folds away: the
// source stays one. Which models the lean kernel has, each model says (kInLeanKernel; kernel/bsdf/material_models.h).

namespace candela {

#if defined(CANDELA_LEAN_KERNEL)
constexpr bool kLeanKernel = true;
#else
constexpr bool kLeanKernel = false;
#endif

}  // namespace candela
