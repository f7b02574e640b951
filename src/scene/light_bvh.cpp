#include "scene/light_bvh.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "kernel/lights.h"

namespace candela {

namespace {

// The angle between unit vectors, accurate also where they are nearly parallel (as pbrt-v4's AngleBetween).
float angleBetween(Vec3 a, Vec3 b) {
  if (dot(a, b) < 0.0f) return kPi - 2.0f * std::asin(std::min(1.0f, length(a + b) * 0.5f));
  return 2.0f * std::asin(std::min(1.0f, length(b - a) * 0.5f));
}

// `v` rotated by `angle` about the unit axis `k` (Rodrigues' formula).
Vec3 rotate(Vec3 v, Vec3 k, float angle) {
  float c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(k, v) * s + k * (dot(k, v) * (1.0f - c));
}

float safeAcos(float x) { return std::acos(std::clamp(x, -1.0f, 1.0f)); }

struct Cone {
  Vec3 w;
  float cosTheta;
};

// The smallest cone holding two cones of directions (pbrt-v4's Union of DirectionCones).
Cone unite(Cone a, Cone b) {
  const Cone entireSphere{a.w, -1.0f};
  float thetaA = safeAcos(a.cosTheta), thetaB = safeAcos(b.cosTheta);
  float thetaD = angleBetween(a.w, b.w);
  if (std::min(thetaD + thetaB, kPi) <= thetaA) return a;
  if (std::min(thetaD + thetaA, kPi) <= thetaB) return b;
  float thetaO = 0.5f * (thetaA + thetaD + thetaB);
  if (thetaO >= kPi) return entireSphere;
  Vec3 axis = cross(a.w, b.w);
  if (dot(axis, axis) == 0.0f) return entireSphere;
  return {normalize(rotate(a.w, normalize(axis), thetaO - thetaA)), std::cos(thetaO)};
}

Vec3 minimum(Vec3 a, Vec3 b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
Vec3 maximum(Vec3 a, Vec3 b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }

float surfaceArea(const LightBounds& b) {
  Vec3 d = b.hi - b.lo;
  return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

// pbrt-v4's BVHLightSampler::EvaluateCost: power times the solid angle the lights emit into (the measure of
// their cone of normals widened by the emission angle) times the box's area, times how much longer the node's
// box is along its longest axis than along the split axis `axis`.
float splitCost(const LightBounds& b, Vec3 nodeDiagonal, int axis) {
  if (b.phi == 0.0f) return 0.0f;
  float thetaO = safeAcos(b.cosThetaO), thetaE = safeAcos(b.cosThetaE);
  float thetaW = std::min(thetaO + thetaE, kPi);
  float sinThetaO = std::sqrt(std::max(0.0f, 1.0f - b.cosThetaO * b.cosThetaO));
  float solidAngle =
      2.0f * kPi * (1.0f - b.cosThetaO) +
      kPi / 2.0f *
          (2.0f * thetaW * sinThetaO - std::cos(thetaO - 2.0f * thetaW) - 2.0f * thetaO * sinThetaO + b.cosThetaO);
  float elongation = maxComponent(nodeDiagonal) / nodeDiagonal[axis];
  return b.phi * solidAngle * elongation * surfaceArea(b);
}

struct BuildLight {
  LightBounds bounds;
  Vec3 centroid;
  uint32_t index;  // in the light table
};

// Splits below this depth are halves by count, so that every bit trail fits 64 bits whatever the cost picks.
constexpr int kCostSplitDepth = 32;
constexpr int kBuckets = 12;

class Builder {
 public:
  explicit Builder(LightBvh& bvh) : bvh_(bvh) {}

  // Builds the subtree over lights[start, end) and returns its bounds; its root is the next node appended.
  LightBounds build(std::vector<BuildLight>& lights, size_t start, size_t end, uint64_t trail, int depth) {
    if (end - start == 1) {
      LightBvhNode leaf;
      leaf.bounds = compact(lights[start].bounds);
      leaf.childOrLight = lights[start].index;
      leaf.isLeaf = 1;
      bvh_.nodes.push_back(leaf);
      bvh_.bitTrails[lights[start].index] = trail;
      return lights[start].bounds;
    }
    size_t mid = split(lights, start, end, depth);
    size_t nodeIndex = bvh_.nodes.size();
    bvh_.nodes.emplace_back();
    LightBounds first = build(lights, start, mid, trail, depth + 1);
    bvh_.nodes[nodeIndex].childOrLight = uint32_t(bvh_.nodes.size());
    LightBounds second = build(lights, mid, end, trail | (uint64_t(1) << depth), depth + 1);
    LightBounds both = unite(first, second);
    bvh_.nodes[nodeIndex].bounds = compact(both);
    return both;
  }

 private:
  // Orders lights[start, end) into two non-empty groups and returns where the second begins.
  static size_t split(std::vector<BuildLight>& lights, size_t start, size_t end, int depth) {
    LightBounds all;
    Vec3 centroidLo{kInf, kInf, kInf}, centroidHi{-kInf, -kInf, -kInf};
    for (size_t i = start; i < end; ++i) {
      all = unite(all, lights[i].bounds);
      centroidLo = minimum(centroidLo, lights[i].centroid);
      centroidHi = maximum(centroidHi, lights[i].centroid);
    }
    auto bucketOf = [&](const BuildLight& l, int axis) {
      float extent = centroidHi[axis] - centroidLo[axis];
      int b = int(float(kBuckets) * (l.centroid[axis] - centroidLo[axis]) / extent);
      return std::clamp(b, 0, kBuckets - 1);
    };
    float bestCost = kInf;
    int bestAxis = -1, bestBucket = -1;
    Vec3 diagonal = all.hi - all.lo;
    for (int axis = 0; depth < kCostSplitDepth && axis < 3; ++axis) {
      if (!(centroidHi[axis] > centroidLo[axis])) continue;
      std::array<LightBounds, kBuckets> buckets{};
      for (size_t i = start; i < end; ++i) {
        LightBounds& b = buckets[size_t(bucketOf(lights[i], axis))];
        b = unite(b, lights[i].bounds);
      }
      // below[i] holds buckets [0, i], above[i] buckets [i + 1, kBuckets).
      std::array<LightBounds, kBuckets> below{}, above{};
      below[0] = buckets[0];
      for (int i = 1; i < kBuckets; ++i) below[size_t(i)] = unite(below[size_t(i - 1)], buckets[size_t(i)]);
      for (int i = kBuckets - 2; i >= 0; --i) above[size_t(i)] = unite(above[size_t(i + 1)], buckets[size_t(i + 1)]);
      for (int i = 0; i < kBuckets - 1; ++i) {
        if (below[size_t(i)].phi == 0.0f || above[size_t(i)].phi == 0.0f) continue;
        float cost = splitCost(below[size_t(i)], diagonal, axis) + splitCost(above[size_t(i)], diagonal, axis);
        if (cost > 0.0f && cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestBucket = i;
        }
      }
    }
    if (bestAxis >= 0) {
      auto firstOfSecond = std::partition(lights.begin() + long(start), lights.begin() + long(end),
                                          [&](const BuildLight& l) { return bucketOf(l, bestAxis) <= bestBucket; });
      size_t mid = size_t(firstOfSecond - lights.begin());
      if (mid > start && mid < end) return mid;
    }
    // No useful split by cost: halves by count along the longest extent of the centroids.
    Vec3 extent = centroidHi - centroidLo;
    int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    size_t mid = start + (end - start) / 2;
    std::nth_element(lights.begin() + long(start), lights.begin() + long(mid), lights.begin() + long(end),
                     [axis](const BuildLight& a, const BuildLight& b) { return a.centroid[axis] < b.centroid[axis]; });
    return mid;
  }

  LightBvh& bvh_;
};

}  // namespace

LightBounds triangleLightBounds(const LightTriangle& light) {
  Vec3 p1 = light.p0 + light.edge1, p2 = light.p0 + light.edge2;
  LightBounds b;
  b.lo = minimum(light.p0, minimum(p1, p2));
  b.hi = maximum(light.p0, maximum(p1, p2));
  b.w = normalize(cross(light.edge1, light.edge2)) * light.frontSign;
  b.phi = light.power;
  b.cosThetaO = 1.0f;  // one normal
  b.cosThetaE = 0.0f;  // emits over the hemisphere about it
  b.twoSided = 0;
  return b;
}

LightBounds punctualLightBounds(const PunctualLight& light) {
  LightBounds b;
  b.lo = b.hi = light.position;
  b.phi = 4.0f * kPi * luminance(light.intensity);
  b.twoSided = 0;
  if (light.type == PunctualLightType::Spot) {
    b.w = light.direction;
    b.cosThetaO = light.cosInner;
    b.cosThetaE = std::cos(std::max(0.0f, safeAcos(light.cosOuter) - safeAcos(light.cosInner)));
  } else {
    b.cosThetaO = -1.0f;  // every direction
    b.cosThetaE = 0.0f;
  }
  return b;
}

LightBounds unite(const LightBounds& a, const LightBounds& b) {
  if (a.phi == 0.0f) return b;
  if (b.phi == 0.0f) return a;
  Cone cone = unite(Cone{a.w, a.cosThetaO}, Cone{b.w, b.cosThetaO});
  LightBounds u;
  u.lo = minimum(a.lo, b.lo);
  u.hi = maximum(a.hi, b.hi);
  u.w = cone.w;
  u.phi = a.phi + b.phi;
  u.cosThetaO = cone.cosTheta;
  u.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
  u.twoSided = a.twoSided | b.twoSided;
  return u;
}

LightBvh buildLightBvh(const std::vector<LightTriangle>& lights, const std::vector<PunctualLight>& punctual) {
  LightBvh bvh;
  const size_t count = lights.size() + punctual.size();
  if (count == 0) return bvh;
  std::vector<BuildLight> work;
  work.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    LightBounds b =
        i < lights.size() ? triangleLightBounds(lights[i]) : punctualLightBounds(punctual[i - lights.size()]);
    work.push_back({b, (b.lo + b.hi) * 0.5f, i});
  }
  bvh.bitTrails.assign(count, 0);
  bvh.nodes.reserve(2 * count - 1);
  Builder(bvh).build(work, 0, work.size(), 0, 0);
  return bvh;
}

}  // namespace candela
