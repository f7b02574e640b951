#pragma once
#include <vector>

#include "candela/image.h"
#include "image/image.h"

namespace candela::api_detail {

// The library's internals, which libcandela does not export (candela.map).
//
// The library's images as api::Image without copying their pixels: the returned image owns the vector.
api::Image sharedImage(candela::Image&& image);
api::Image sharedPlane(uint32_t width, uint32_t height, std::vector<float>&& plane);  // one channel

}  // namespace candela::api_detail
