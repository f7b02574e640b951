// The analytic whole-render tests (tests/render/analytic_scenes_suite.h) on the OptiX backend.
#include "backends/optix/optix_backend.h"
#include "render/analytic_scenes_suite.h"

namespace candela::test {

INSTANTIATE_TYPED_TEST_SUITE_P(Optix, AnalyticScenes, EverySampler<OptixBackend>);

}  // namespace candela::test
