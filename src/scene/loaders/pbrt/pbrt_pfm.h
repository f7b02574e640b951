#pragma once
#include <cstdint>
#include <string>

#include "scene/loaders/texture_limits.h"
#include "scene/scene.h"

namespace candela {

// A Portable Float Map (.pfm: "PF" colour or "Pf" grey, either byte order) as a float texture, top row first,
// area averaged while it is read down to at most `maxSide` pixels a side (the aspect ratio kept). The decoded
// texture is charged to the load's memory budget (io/load_budget.h) before it is made. Throws LoadError naming
// the file when it is malformed, its header claims more pixels than it holds, or the budget is exceeded.
// `fileExtent`, when given, receives the image's size in the file.
Texture readPfm(const std::string& path, uint32_t maxSide, TextureExtent* fileExtent = nullptr);

}  // namespace candela
