#pragma once
#include <cstdint>

#include "scene/scene.h"

namespace candela {

// A town at night for many-light benchmarks: a grid of blocks, each a box building with lit windows on its
// walls, and a street lamp (a small quad shining down) at every crossing, over a ground plane, with no
// environment. `blocks` per side gives blocks^2 buildings, 8 windows each, and (blocks + 1)^2 lamps: 24 blocks
// make 4,608 windows and 625 lamps, 10,466 emissive triangles. The same seed gives the same town.
Scene makeNightTown(uint32_t blocks, uint32_t seed);

// A field of `lights` point lights of equal intensity, 0.3 to 1.5 m over a 100 m square ground, among 81 box
// pillars, with no environment and no emissive surface.
Scene makePointLitField(uint32_t lights, uint32_t seed);

}  // namespace candela
