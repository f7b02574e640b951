// The analytic whole-render tests (analytic_scenes_suite.h) on the CPU backend.
#include "backends/cpu/cpu_backend.h"
#include "render/analytic_scenes_suite.h"

namespace candela::test {

INSTANTIATE_TYPED_TEST_SUITE_P(Cpu, AnalyticScenes, EverySampler<CpuBackend>);

}  // namespace candela::test
