#pragma once
#include <pybind11/pybind11.h>

namespace candela::python {

// candela.Scene (a scene built from arrays: api::SceneBuilder) and candela.LoadedScene (api::Scene: loaded, or
// built, ready to render).
void bindScenes(pybind11::module_& module);

}  // namespace candela::python
