#pragma once
#include <memory>
#include <string>

#include "backends/backend.h"

namespace candela {

// The backends this build contains, for --help.
std::string availableBackends();

// `name` is "auto", "cpu" or "optix". For "auto", `why` receives one sentence saying which backend was chosen
// and why. A GPU backend takes GPU `deviceIndex` modulo the GPUs it sees (the processes of a distributed render on
// one node take one each). Throws std::runtime_error when the requested backend cannot run here.
std::unique_ptr<Backend> createBackend(const std::string& name, std::string& why, int deviceIndex = 0);

}  // namespace candela
