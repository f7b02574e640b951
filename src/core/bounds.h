#pragma once
#include <algorithm>

#include "core/math.h"

namespace candela {

// An axis-aligned box grown point by point; empty until the first point.
struct Bounds3 {
  Vec3 lo{kInf, kInf, kInf};
  Vec3 hi{-kInf, -kInf, -kInf};

  bool empty() const { return lo.x > hi.x; }
  void extend(Vec3 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  Vec3 centre() const { return (lo + hi) * 0.5f; }
  float radius() const { return empty() ? 0.0f : 0.5f * length(hi - lo); }
};

}  // namespace candela
