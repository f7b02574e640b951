// ReSTIR DI's whole-render tests (tests/render/restir_suite.h) on the CPU backend.
#include "backends/cpu/cpu_backend.h"
#include "render/restir_suite.h"

namespace candela::test::restir {

INSTANTIATE_TYPED_TEST_SUITE_P(Cpu, RestirScenes, CpuBackend);

}  // namespace candela::test::restir
