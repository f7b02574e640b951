#pragma once
#include <string>

namespace candela {

// Writes the window's pixels as they are now in the back buffer (image and panel) to a PNG. Throws
// std::runtime_error naming the file when it cannot.
void captureWindow(const std::string& path, int framebufferWidth, int framebufferHeight);

}  // namespace candela
