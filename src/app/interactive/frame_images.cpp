#include "app/interactive/frame_images.h"

#include <chrono>

#include "app/interactive/post_filter.h"
#include "backends/backend.h"

namespace candela {

const Image& FrameImages::image() {
  if (!image_) image_ = denoiser_.apply(session_, post_.denoiser, post_.atrousParams);
  return *image_;
}

const Image* FrameImages::emission() {
  if (!post_.bilateral) return nullptr;
  if (!emission_) emission_ = session_.emission();
  return &*emission_;
}

const Image& FrameImages::filtered() {
  if (!post_.bilateral) return image();
  if (!filtered_) filtered_ = postFiltered(image(), *emission(), post_);
  return *filtered_;
}

DisplayFrame FrameImages::display() {
  DisplayRequest request;
  request.display = post_.display;
  switch (post_.denoiser) {
    case DenoiserChoice::None:
      if (post_.bilateral) request.source = BilateralFiltered{post_.bilateralParams};
      break;
    case DenoiserChoice::Atrous:
      request.source = denoiser_.atrousSource(session_, post_.atrousParams);
      if (post_.bilateral) request.smoothing = post_.bilateralParams;
      break;
    default: {
      const auto start = std::chrono::steady_clock::now();
      const Image& linear = filtered();
      hostPixels_.resize(linear.pixels.size() * 3);
      writeDisplayPixels({linear.pixels.data(), nullptr, linear.width, linear.height}, post_.display, 1,
                         hostPixels_.data());
      DisplayFrame frame{linear.width, linear.height, hostPixels_.data()};
      frame.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      return frame;
    }
  }
  return session_.backend().display().read(request);
}

}  // namespace candela
