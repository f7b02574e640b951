#pragma once
#include <memory>
#include <string>

#include "app/device_list.h"
#include "app/progress.h"
#include "backends/backend.h"
#include "backends/optix/compile_progress.h"

namespace candela {

// The backends this build contains, for --help.
std::string availableBackends();

// `name` is "auto", "cpu" or "optix". For "auto", `why` receives one sentence saying which backend was chosen
// and why. A GPU backend renders on the GPUs `devices` names: on one, the OptiX backend; on several, the
// OptiX backend on each behind one (optix/multi_gpu_backend.h). Throws std::runtime_error when the requested
// backend cannot run here, std::invalid_argument when `devices` names GPUs that are not there or was given
// for the cpu backend; "auto" falls back to the CPU only when the devices were not named. A GPU backend's first
// start on a machine compiles its programs for the GPU, which takes a while: `compileProgress` hears how it goes
// (backends/optix/compile_progress.h), there and where a later launch waits for programs still compiling. With
// `start` InBackground the OptiX backend on one GPU returns before its first frame's programs are compiled
// (Backend::startingCompile), and with AtFirstFrame it compiles nothing until the first frame (or
// Backend::preparePrograms); on several GPUs it always waits for a first frame's programs of default settings.
std::unique_ptr<Backend> createBackend(const std::string& name, std::string& why, const DeviceRequest& devices = {},
                                       const ProgramCompileListener& compileProgress = compileProgressOnStderr(),
                                       ProgramStart start = ProgramStart::Wait);
// Gives `backend`, made for the request `name`, the scene. Where `name` is "auto" and the backend is a GPU's that
// cannot render the scene (SceneUnsupported), the CPU backend takes its place, is given the scene, and `why` says
// so in one sentence; with any other request the refusal is thrown on. `why` is left alone otherwise.
void setSceneOrFallBack(std::unique_ptr<Backend>& backend, const std::string& name, const Scene& scene,
                        std::string& why);

// The same on the one GPU `deviceIndex` modulo the GPUs it sees (the processes of a distributed render on one
// node take one each).
std::unique_ptr<Backend> createBackend(const std::string& name, std::string& why, int deviceIndex,
                                       const ProgramCompileListener& compileProgress = compileProgressOnStderr(),
                                       ProgramStart start = ProgramStart::Wait);

}  // namespace candela
