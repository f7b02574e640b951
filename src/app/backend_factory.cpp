#include "app/backend_factory.h"

#include <stdexcept>

#include "backends/cpu/cpu_backend.h"

namespace candela {

std::string availableBackends() { return "cpu"; }

std::unique_ptr<Backend> createBackend(const std::string& name, std::string& why) {
  if (name == "cpu") {
    why = "backend: cpu (requested)";
    return std::make_unique<CpuBackend>();
  }
  if (name == "auto") {
    why = "backend: cpu (this build has no GPU backend; see README, 'GPU backend')";
    return std::make_unique<CpuBackend>();
  }
  if (name == "optix")
    throw std::runtime_error(
        "the optix backend is not in this build: configure with -DOptiX_INSTALL_DIR=<OptiX SDK> and CUDA "
        "present (see README, 'GPU backend')");
  throw std::runtime_error("unknown backend '" + name + "' (choose auto, cpu or optix)");
}

}  // namespace candela
