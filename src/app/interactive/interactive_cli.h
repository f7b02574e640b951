#pragma once
#include <CLI/CLI.hpp>

#include "app/interactive/interactive_options.h"

namespace candela {

// The options of the image, its rendering and post-processing, the animation and the exit files, with the same
// defaults and limits for `candela view` and `candela serve`. The scene, scene-input, backend and random-sequence
// options, which the other commands share, are added beside them by the caller.
void addInteractiveOptions(CLI::App& cmd, InteractiveOptions& options);

}  // namespace candela
