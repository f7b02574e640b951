#include "app/backend_factory.h"

#include <cstdio>
#include <stdexcept>

#include "backends/cpu/cpu_backend.h"
#if CANDELA_HAS_OPTIX
#include "backends/optix/cuda_devices.h"
#include "backends/optix/multi_gpu_backend.h"
#include "backends/optix/optix_backend.h"
#endif

namespace candela {

namespace {

#if CANDELA_HAS_OPTIX
// Where the devices were not named, a machine whose other GPUs cannot all be used (another process holds one in
// exclusive mode, one is out of memory) renders on its first GPU, as it would with one.
std::unique_ptr<Backend> makeGpuBackend(const DeviceRequest& devices, const ProgramCompileListener& compileProgress,
                                        ProgramStart start) {
  const std::vector<int> indices = resolveDevices(devices, optix::gpuNames());
  if (indices.size() == 1) return std::make_unique<OptixBackend>(indices[0], compileProgress, start);
  if (devices.given) return std::make_unique<MultiGpuBackend>(indices, compileProgress);
  try {
    return std::make_unique<MultiGpuBackend>(indices, compileProgress);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "candela: warning: not every GPU can be used (%s): rendering on GPU %d alone\n", e.what(),
                 indices[0]);
    return std::make_unique<OptixBackend>(indices[0], compileProgress, start);
  }
}
#endif

// `makeGpu` makes the GPU backend of the request; "auto" falls back to the CPU when it fails and `fallBack`.
template <class MakeGpu>
std::unique_ptr<Backend> create(const std::string& name, std::string& why, bool fallBack,
                                [[maybe_unused]] const MakeGpu& makeGpu) {
  if (name == "cpu") {
    why = "backend: cpu (requested)";
    return std::make_unique<CpuBackend>();
  }
#if CANDELA_HAS_OPTIX
  if (name == "optix") {
    auto backend = makeGpu();
    why = "backend: optix (requested)";
    return backend;
  }
  if (name == "auto") {
    try {
      auto backend = makeGpu();
      why = "backend: optix (auto: found " + backend->deviceName() + ")";
      return backend;
    } catch (const std::runtime_error& e) {
      if (!fallBack) throw;
      why = std::string("backend: cpu (auto: no usable GPU: ") + e.what() + ")";
      return std::make_unique<CpuBackend>();
    }
  }
#else
  if (name == "auto" && fallBack) {
    why = "backend: cpu (this build has no GPU backend; see README, 'GPU backend')";
    return std::make_unique<CpuBackend>();
  }
  if (name == "optix" || name == "auto")
    throw std::runtime_error(
        "the optix backend is not in this build: configure with -DOptiX_INSTALL_DIR=<OptiX SDK> and CUDA "
        "present (see README, 'GPU backend')");
#endif
  throw std::runtime_error("unknown backend '" + name + "' (choose auto, cpu or optix)");
}

}  // namespace

#if CANDELA_HAS_OPTIX
std::string availableBackends() { return "cpu, optix"; }
#else
std::string availableBackends() { return "cpu"; }
#endif

std::unique_ptr<Backend> createBackend(const std::string& name, std::string& why, const DeviceRequest& devices,
                                       [[maybe_unused]] const ProgramCompileListener& compileProgress,
                                       [[maybe_unused]] ProgramStart start) {
  if (devices.given && name == "cpu")
    throw std::invalid_argument("--devices chooses GPUs: it needs the optix backend, not cpu");
#if CANDELA_HAS_OPTIX
  return create(name, why, !devices.given, [&] { return makeGpuBackend(devices, compileProgress, start); });
#else
  return create(name, why, !devices.given, [] { return std::unique_ptr<Backend>(); });
#endif
}

void setSceneOrFallBack(std::unique_ptr<Backend>& backend, const std::string& name, const Scene& scene,
                        std::string& why) {
  try {
    backend->setScene(scene);
  } catch (const SceneUnsupported& e) {
    if (name != "auto" || backend->name() == "cpu") throw;
    backend = std::make_unique<CpuBackend>();
    backend->setScene(scene);
    why = std::string("backend: cpu (auto: the GPU backend cannot render this scene: ") + e.what() + ")";
  }
}

std::unique_ptr<Backend> createBackend(const std::string& name, std::string& why, [[maybe_unused]] int deviceIndex,
                                       [[maybe_unused]] const ProgramCompileListener& compileProgress,
                                       [[maybe_unused]] ProgramStart start) {
#if CANDELA_HAS_OPTIX
  return create(name, why, true, [&] { return std::make_unique<OptixBackend>(deviceIndex, compileProgress, start); });
#else
  return create(name, why, true, [] { return std::unique_ptr<Backend>(); });
#endif
}

}  // namespace candela
