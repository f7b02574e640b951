// The wavefront schedule's programs (wavefront_programs.h), a module of their own.
#include "backends/optix/device/program_common.h"

using namespace candela;
using namespace candela::optix;

#include "backends/optix/device/wavefront_programs.h"
