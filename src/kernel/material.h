#pragma once
#include <cstdint>

#include "core/math.h"

namespace candela {

enum class MaterialType : uint32_t { Diffuse = 0 };

// Flat parameters that a device buffer can hold; kernel code dispatches on `type`.
struct Material {
  MaterialType type = MaterialType::Diffuse;
  Vec3 baseColor{0.8f, 0.8f, 0.8f};
  Vec3 emission{0.0f, 0.0f, 0.0f};  // emitted radiance, W/(m^2 sr)
};

}  // namespace candela
