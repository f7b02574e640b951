#pragma once
// candela's public C++ interface: load or build a scene, render it, time it. Link the imported target
// candela::candela (find_package(candela)); only the names of candela::api are exported from libcandela.
#include "candela/error.h"
#include "candela/image.h"
#include "candela/render.h"
#include "candela/scene.h"

namespace candela::api {

// The library's version, "major.minor.patch".
const char* version();

}  // namespace candela::api
