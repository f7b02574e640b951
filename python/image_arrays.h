#pragma once
#include <pybind11/numpy.h>

#include "candela/image.h"

namespace candela::python {

// The image as a float32 array, height x width x channels (height x width for one channel), that shares the
// image's pixels: the array's base owns the image, so no pixel is copied.
pybind11::array_t<float> arrayOf(const api::Image& image);

}  // namespace candela::python
