#include "app/interactive/frame_images.h"

#include "app/interactive/post_filter.h"

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

}  // namespace candela
