#pragma once
// How the backend's image reaches the display texture: on the GPU through CUDA-OpenGL interop where the OptiX
// backend renders on the device that runs the OpenGL context, else read back to the host and uploaded.
#include <cstdint>
#include <functional>
#include <string>

#include "app/interactive/render_session.h"
#include "app/viewer/image_display.h"

namespace candela {

class ImageTransfer {
 public:
  // Needs a current OpenGL context; picks the path once, for the session's backend. With `allowInterop` false
  // it takes the host copy even where interop would work, so that the two can be compared.
  ImageTransfer(const RenderSession& session, bool allowInterop);
  ~ImageTransfer();
  ImageTransfer(const ImageTransfer&) = delete;
  ImageTransfer& operator=(const ImageTransfer&) = delete;

  void transfer(const RenderSession& session, ImageDisplay& display);
  // "CUDA-OpenGL interop", or the copy path and why interop is not used.
  const std::string& description() const { return description_; }

 private:
  // The interop path where one is used: fills the display from the backend's image of the given size.
  std::function<void(ImageDisplay&, uint32_t, uint32_t)> interop_;
  std::string description_;
};

}  // namespace candela
