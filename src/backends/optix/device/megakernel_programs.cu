// The path tracer's megakernel, and the program that records its rays for the raw-trace mode: they share a pipeline
// (program_use.cpp says why).
#include "backends/optix/device/program_common.h"
#include "backends/optix/device/record_pixel.h"
#include "backends/optix/device/render_pixel.h"

extern "C" __global__ void __raygen__render() { renderPixel<false>(); }

// Traces one sample per pixel like __raygen__render and records its rays; the image is left alone.
extern "C" __global__ void __raygen__record() { recordPixel(); }
