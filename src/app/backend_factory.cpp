#include "app/backend_factory.h"

#include <stdexcept>

#include "backends/cpu/cpu_backend.h"
#if CANDELA_HAS_OPTIX
#include "backends/optix/optix_backend.h"
#endif

namespace candela {

#if CANDELA_HAS_OPTIX
std::string availableBackends() { return "cpu, optix"; }
#else
std::string availableBackends() { return "cpu"; }
#endif

std::unique_ptr<Backend> createBackend(const std::string& name, std::string& why, [[maybe_unused]] int deviceIndex) {
  if (name == "cpu") {
    why = "backend: cpu (requested)";
    return std::make_unique<CpuBackend>();
  }
#if CANDELA_HAS_OPTIX
  if (name == "optix") {
    auto backend = std::make_unique<OptixBackend>(deviceIndex);
    why = "backend: optix (requested)";
    return backend;
  }
  if (name == "auto") {
    try {
      auto backend = std::make_unique<OptixBackend>(deviceIndex);
      why = "backend: optix (auto: found " + backend->deviceName() + ")";
      return backend;
    } catch (const std::runtime_error& e) {
      why = std::string("backend: cpu (auto: no usable GPU: ") + e.what() + ")";
      return std::make_unique<CpuBackend>();
    }
  }
#else
  if (name == "auto") {
    why = "backend: cpu (this build has no GPU backend; see README, 'GPU backend')";
    return std::make_unique<CpuBackend>();
  }
  if (name == "optix")
    throw std::runtime_error(
        "the optix backend is not in this build: configure with -DOptiX_INSTALL_DIR=<OptiX SDK> and CUDA "
        "present (see README, 'GPU backend')");
#endif
  throw std::runtime_error("unknown backend '" + name + "' (choose auto, cpu or optix)");
}

}  // namespace candela
