#pragma once
// The majorant grid's voxels along a ray, front to back (pbrt-v4's DDAMajorantIterator): a 3D DDA (Amanatides and
// Woo) over the grid of a MediumGrid, clipped to its box and to the ray's segment, giving each piece of the ray
// with the majorant of the voxel it crosses.
#include "kernel/media/medium_grid.h"

namespace candela {

// A piece of a ray, [tMin, tMax), within which sigma_t never exceeds `majorant` in any channel.
struct MajorantSegment {
  float tMin = 0.0f;
  float tMax = 0.0f;
  float majorant = 0.0f;
};

class MajorantWalk {
 public:
  // Starts at the ray (world space, its own parametrisation kept: the direction is not renormalised in the
  // medium's space) from 0 to tEnd (infinite: to the box's far side).
  CANDELA_FN MajorantWalk(const MediumGrid& grid, const float* values, const Ray& ray, float tEnd)
      : grid_(grid), values_(values) {
    const Vec3 o = grid.mediumFromWorld.point(ray.origin);
    const Vec3 d = grid.mediumFromWorld.vector(ray.direction);
    const float origin[3] = {o.x, o.y, o.z}, direction[3] = {d.x, d.y, d.z};
    const float lo[3] = {grid.p0.x, grid.p0.y, grid.p0.z}, hi[3] = {grid.p1.x, grid.p1.y, grid.p1.z};
    const uint32_t res[3] = {grid.mx, grid.my, grid.mz};
    // The slabs of the box.
    float t0 = 0.0f, t1 = tEnd;
    for (int axis = 0; axis < 3; ++axis) {
      if (direction[axis] == 0.0f) {
        if (origin[axis] < lo[axis] || origin[axis] > hi[axis]) t1 = -1.0f;
        continue;
      }
      float tNear = (lo[axis] - origin[axis]) / direction[axis];
      float tFar = (hi[axis] - origin[axis]) / direction[axis];
      if (tNear > tFar) {
        const float swap = tNear;
        tNear = tFar;
        tFar = swap;
      }
      t0 = fmaxf(t0, tNear);
      t1 = fminf(t1, tFar);
    }
    tMin_ = t0;
    tMax_ = t1;
    if (!(t0 < t1)) return;
    // The same ray in the grid's unit cube, where voxel i of an axis spans [i / res, (i + 1) / res).
    for (int axis = 0; axis < 3; ++axis) {
      const float extent = hi[axis] - lo[axis];
      const float gridOrigin = (origin[axis] - lo[axis]) / extent;
      const float gridDirection = direction[axis] / extent;
      const float entry = gridOrigin + gridDirection * t0;
      const float r = float(res[axis]);
      voxel_[axis] = int(clampf(entry * r, 0.0f, r - 1.0f));
      if (gridDirection == 0.0f) {
        nextCrossing_[axis] = kInf;
        deltaT_[axis] = kInf;
        step_[axis] = 1;
        voxelLimit_[axis] = int(res[axis]);
        continue;
      }
      deltaT_[axis] = 1.0f / (fabsf(gridDirection) * r);
      const bool forwards = gridDirection > 0.0f;
      const float boundary = float(voxel_[axis] + (forwards ? 1 : 0)) / r;
      nextCrossing_[axis] = t0 + (boundary - entry) / gridDirection;
      step_[axis] = forwards ? 1 : -1;
      voxelLimit_[axis] = forwards ? int(res[axis]) : -1;
    }
  }

  // The next piece, or false past the last.
  CANDELA_FN bool next(MajorantSegment& segment) {
    if (!(tMin_ < tMax_)) return false;
    const int axis = nextCrossing_[0] < nextCrossing_[1] ? (nextCrossing_[0] < nextCrossing_[2] ? 0 : 2)
                                                         : (nextCrossing_[1] < nextCrossing_[2] ? 1 : 2);
    const float exit = fminf(tMax_, nextCrossing_[axis]);
    segment = {tMin_, exit,
               gridMajorant(grid_, values_, uint32_t(voxel_[0]), uint32_t(voxel_[1]), uint32_t(voxel_[2]))};
    tMin_ = nextCrossing_[axis] > tMax_ ? tMax_ : exit;
    voxel_[axis] += step_[axis];
    if (voxel_[axis] == voxelLimit_[axis]) tMin_ = tMax_;
    nextCrossing_[axis] += deltaT_[axis];
    return true;
  }

 private:
  const MediumGrid& grid_;
  const float* values_;
  float tMin_ = 0.0f, tMax_ = 0.0f;
  float nextCrossing_[3] = {kInf, kInf, kInf};
  float deltaT_[3] = {kInf, kInf, kInf};
  int step_[3] = {1, 1, 1};
  int voxelLimit_[3] = {1, 1, 1};
  int voxel_[3] = {0, 0, 0};
};

}  // namespace candela
