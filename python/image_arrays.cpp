#include "image_arrays.h"

#include <vector>

namespace py = pybind11;

namespace candela::python {

py::array_t<float> arrayOf(const api::Image& image) {
  auto* owner = new api::Image(image);  // shares the pixels; the capsule below ends it with the array
  py::capsule base(owner, [](void* p) { delete static_cast<api::Image*>(p); });
  std::vector<py::ssize_t> shape{py::ssize_t(image.height()), py::ssize_t(image.width())};
  if (image.channels() != 1) shape.push_back(py::ssize_t(image.channels()));
  return py::array_t<float>(shape, owner->data(), base);
}

}  // namespace candela::python
