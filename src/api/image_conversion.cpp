#include "api/image_conversion.h"

#include <memory>
#include <type_traits>

namespace candela::api_detail {

// An Image's pixels are read as consecutive floats, three per pixel.
static_assert(sizeof(candela::Vec3) == 3 * sizeof(float) && std::is_standard_layout_v<candela::Vec3>);

api::Image sharedImage(candela::Image&& image) {
  auto owner = std::make_shared<candela::Image>(std::move(image));
  float* pixels = owner->pixels.empty() ? nullptr : &owner->pixels.front().x;
  return api::Image(owner->width, owner->height, 3, std::shared_ptr<float>(owner, pixels));
}

api::Image sharedPlane(uint32_t width, uint32_t height, std::vector<float>&& plane) {
  auto owner = std::make_shared<std::vector<float>>(std::move(plane));
  return api::Image(width, height, 1, std::shared_ptr<float>(owner, owner->data()));
}

}  // namespace candela::api_detail
