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
#if CANDELA_HAS_OPTIX
  const auto* optix = dynamic_cast<const OptixBackend*>(&session.backend());
  if (optix && !allowInterop) {
    description_ = std::string(kCopyPath) + ": interop switched off (--no-interop)";
    return;
  }
  if (optix) {
    try {
      auto interop = std::make_shared<CudaGlInterop>(*optix);
      interop_ = [interop](ImageDisplay& display, uint32_t width, uint32_t height) {
        interop->transfer(display, width, height);
      };
      description_ = "CUDA-OpenGL interop (pixel buffer on the GPU)";
      return;
    } catch (const std::exception& e) {
      description_ = std::string(kCopyPath) + ": no interop, " + e.what();
      return;
    }
  }
#endif
  (void)allowInterop;  // only the OptiX backend has an interop path
  description_ = std::string(kCopyPath) + ": the " + session.backend().name() + " backend renders on the host";
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
