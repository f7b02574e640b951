#include "app/viewer/window_capture.h"

#include <stdexcept>
#include <vector>

#include "app/viewer/gl.h"
#include "io/images/image_io.h"

namespace candela {

void captureWindow(const std::string& path, int framebufferWidth, int framebufferHeight) {
  const size_t rowBytes = size_t(framebufferWidth) * 3;
  std::vector<unsigned char> pixels(rowBytes * size_t(framebufferHeight));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, framebufferWidth, framebufferHeight, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  // OpenGL's rows run bottom to top; they are written top to bottom with a negative stride from the end.
  const unsigned char* lastRow = pixels.data() + rowBytes * size_t(framebufferHeight - 1);
  writePngFile(path, framebufferWidth, framebufferHeight, 3, lastRow, -int(rowBytes));
}

}  // namespace candela
