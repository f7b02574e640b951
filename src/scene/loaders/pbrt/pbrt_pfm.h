#pragma once
#include <string>

#include "scene/scene.h"

namespace candela {

// A Portable Float Map (.pfm: "PF" colour or "Pf" grey, either byte order) as a float texture, top row first.
// Throws LoadError naming the file when it is malformed or its header claims more pixels than it holds.
Texture readPfm(const std::string& path);

}  // namespace candela
