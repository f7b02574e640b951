#pragma once
#include <string>

#include "app/interactive/interactive_options.h"

namespace candela {

struct ViewerOptions {
  InteractiveOptions interactive;  // what candela serve takes too
  bool interop = true;             // false: the image reaches the screen through the host copy even where interop works
  std::string windowCapture;       // on exit: the window's pixels, panel included (.png)
  std::string stateFile = "candela-view-state.json";  // F12 writes the viewer's state here
};

// Opens the window and runs until it closes or `interactive.frames` frames are done; returns the process exit code.
// Throws std::runtime_error with one sentence when there is no display, no OpenGL 3.3, or the scene or backend
// cannot be loaded at start.
int runViewer(const ViewerOptions& options);

}  // namespace candela
