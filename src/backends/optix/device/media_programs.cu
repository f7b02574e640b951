// The megakernel of scenes with participating media (kernel/media/volume_path.h), with and without the AOVs: a
// module and a pipeline of their own, so that the path tracer of scenes without media stays as it was.
#include "backends/optix/device/program_common.h"
#include "backends/optix/device/render_pixel.h"

extern "C" __global__ void __raygen__renderMedia() { renderPixel<false, true>(); }
extern "C" __global__ void __raygen__renderMediaWithAovs() { renderPixel<true, true>(); }
