#pragma once
#include "app/serve/serve_options.h"

namespace candela {

// candela serve: loads the scene, listens, prints the address to open (with its token where one is required) and
// renders for the browsers that connect until SIGINT or SIGTERM, or until options.interactive.frames frames are
// sent; then writes the --screenshot.
// Returns the process exit code; throws std::runtime_error with one sentence when it cannot start.
int runServe(ServeOptions options);

}  // namespace candela
