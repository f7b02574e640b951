#pragma once
// What the programs of every module share. Each .cu file beside this one is compiled to a module of its own
// (backends/optix/program_modules.h), and each declares the launch parameters: a pipeline's launch fills them for
// all of its modules' programs. Include once, at the top of a module's file. Device code only.
#include <optix.h>

#include "backends/optix/device/optix_tracer.h"
#include "backends/optix/launch_params.h"
#include "kernel/film_accumulation.h"

// Filled by optixLaunch; the pipeline names it in pipelineLaunchParamsVariableName.
extern "C" {
__constant__ candela::optix::LaunchParameters params;
}

// The image pixel of this launch index: a launch covers the rows from params.firstRow on.
inline __device__ uint2 launchPixelXY() {
  const uint3 index = optixGetLaunchIndex();
  return make_uint2(index.x, index.y + params.firstRow);
}

inline __device__ uint32_t launchPixel() {
  const uint2 xy = launchPixelXY();
  return xy.y * params.settings.width + xy.x;
}

inline __device__ candela::optix::OptixTracer sceneTracer() {
  return candela::optix::OptixTracer(params.traversable, params.scene.hasCutouts != 0,
                                     params.scene.curveSegments != nullptr);
}
