// The megakernel that also adds the AOVs (albedo, normal, depth) to the film: renders whose denoisers need guides.
// Its pipeline holds a copy of the record program beside it, as the path tracer's does (program_use.cpp says why);
// that copy is compiled here, so that a render with AOVs does not compile the path tracer's module.
#include "backends/optix/device/program_common.h"
#include "backends/optix/device/record_pixel.h"
#include "backends/optix/device/render_pixel.h"

extern "C" __global__ void __raygen__renderWithAovs() { renderPixel<true>(); }

extern "C" __global__ void __raygen__record() { recordPixel(); }
