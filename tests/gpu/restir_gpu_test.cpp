// ReSTIR DI's whole-render tests (tests/render/restir_suite.h) on the OptiX backend, whose ReSTIR launches are
// its own (megakernel-like, one thread per pixel).
#include "backends/optix/optix_backend.h"
#include "render/restir_suite.h"

namespace candela::test::restir {

INSTANTIATE_TYPED_TEST_SUITE_P(Optix, RestirScenes, OptixBackend);

}  // namespace candela::test::restir
