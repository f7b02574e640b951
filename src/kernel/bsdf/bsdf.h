#pragma once
#include "kernel/bsdf/lambertian.h"
#include "kernel/interaction.h"
#include "kernel/material.h"

namespace candela {

// A material evaluated at one surface point, in that point's shading frame. Dispatch is a switch over the
// material type: no virtual calls, so the same code runs on the device.
class Bsdf {
 public:
  CANDELA_FN Bsdf(const Material& m, const SurfaceInteraction& si, Vec3 woWorld)
      : frame_(Frame::fromNormal(dot(si.shadingNormal, woWorld) < 0.0f ? -si.shadingNormal : si.shadingNormal)),
        type_(m.type),
        lambertian_{m.baseColor} {}

  CANDELA_FN Vec3 toLocal(Vec3 w) const { return frame_.toLocal(w); }
  CANDELA_FN Vec3 toWorld(Vec3 w) const { return frame_.toWorld(w); }
  CANDELA_FN Vec3 normal() const { return frame_.n; }

  CANDELA_FN Vec3 eval(Vec3 woWorld, Vec3 wiWorld) const {
    Vec3 wo = toLocal(woWorld), wi = toLocal(wiWorld);
    switch (type_) {
      case MaterialType::Diffuse:
        return lambertian_.eval(wo, wi);
    }
    return {0, 0, 0};
  }
  CANDELA_FN float pdf(Vec3 woWorld, Vec3 wiWorld) const {
    Vec3 wo = toLocal(woWorld), wi = toLocal(wiWorld);
    switch (type_) {
      case MaterialType::Diffuse:
        return lambertian_.pdf(wo, wi);
    }
    return 0.0f;
  }
  // Returns wi in world space.
  CANDELA_FN BsdfSample sample(Vec3 woWorld, Vec2 u) const {
    Vec3 wo = toLocal(woWorld);
    BsdfSample s;
    switch (type_) {
      case MaterialType::Diffuse:
        s = lambertian_.sample(wo, u);
        break;
    }
    s.wi = toWorld(s.wi);
    return s;
  }

 private:
  Frame frame_;
  MaterialType type_;
  LambertianBsdf lambertian_;
};

}  // namespace candela
