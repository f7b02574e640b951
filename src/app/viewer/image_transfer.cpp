#include "app/viewer/image_transfer.h"

#include <memory>
#include <stdexcept>

#if CANDELA_HAS_OPTIX
#include "app/viewer/cuda_gl_interop.h"
#endif

namespace candela {

namespace {

const char* const kCopyPath = "host copy (readImage + glTexSubImage2D)";

}  // namespace

ImageTransfer::ImageTransfer(const RenderSession& session, bool allowInterop) {
  const Backend& backend = session.backend();
  const DeviceImage* deviceImage = backend.deviceImage();
  if (!deviceImage) {
    description_ = std::string(kCopyPath) + ": the " + backend.name() + " backend renders on the host";
    return;
  }
  if (!allowInterop) {
    description_ = std::string(kCopyPath) + ": interop switched off (--no-interop)";
    return;
  }
#if CANDELA_HAS_OPTIX
  try {
    auto interop = std::make_shared<CudaGlInterop>(*deviceImage, backend.deviceName());
    interop_ = [interop](ImageDisplay& display, uint32_t width, uint32_t height) {
      interop->transfer(display, width, height);
    };
    description_ = "CUDA-OpenGL interop (pixel buffer on the GPU)";
  } catch (const std::exception& e) {
    description_ = std::string(kCopyPath) + ": no interop, " + e.what();
  }
#else
  description_ = std::string(kCopyPath) + ": this build has no CUDA-OpenGL interop";
#endif
}

ImageTransfer::~ImageTransfer() = default;

void ImageTransfer::transfer(const RenderSession& session, ImageDisplay& display) {
  if (interop_) {
    const RenderSettings& s = session.appliedSettings();
    interop_(display, s.width, s.height);
    return;
  }
  display.upload(session.image());
}

}  // namespace candela
