// The megakernel that also adds the AOVs (albedo, normal, depth) to the film: renders whose denoisers need guides.
#include "backends/optix/device/program_common.h"
#include "backends/optix/device/render_pixel.h"

extern "C" __global__ void __raygen__renderWithAovs() { renderPixel<true>(); }
