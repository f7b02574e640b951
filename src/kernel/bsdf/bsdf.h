#pragma once
#include "kernel/aovs.h"
#include "kernel/bsdf/blinn_phong.h"
#include "kernel/bsdf/disney.h"
#include "kernel/bsdf/lambertian.h"
#include "kernel/bsdf/pbr.h"
#include "kernel/bsdf/specular.h"
#include "kernel/interaction.h"
#include "kernel/material.h"

namespace candela {

// A material evaluated at one surface point, in that point's shading frame (normal flipped towards wo, tangent
// along the surface's tangent when it has one). Dispatch is a switch over the material type that builds the
// model's small parameter struct on the stack: no virtual calls, so the same code runs on the device.
class Bsdf {
 public:
  // `m` has its textures already applied (see evaluateMaterial).
  CANDELA_FN Bsdf(const Material& m, const SurfaceInteraction& si, Vec3 woWorld) : material_(m) {
    Vec3 n = dot(si.shadingNormal, woWorld) < 0.0f ? -si.shadingNormal : si.shadingNormal;
    Vec3 s = si.tangent - n * dot(n, si.tangent);
    float len = length(s);
    frame_ = len > 1e-6f ? Frame{s / len, cross(n, s / len), n} : Frame::fromNormal(n);
    // Closed meshes are wound outwards: arriving on the front side means entering the material.
    float ior = m.ior > 0.0f ? m.ior : 1.0f;
    eta_ = dot(woWorld, si.geometricNormal) >= 0.0f ? ior : 1.0f / ior;
  }

  CANDELA_FN Vec3 toLocal(Vec3 w) const { return frame_.toLocal(w); }
  CANDELA_FN Vec3 toWorld(Vec3 w) const { return frame_.toWorld(w); }
  CANDELA_FN Vec3 normal() const { return frame_.n; }
  // The relative index of refraction a transmitted direction crosses into.
  CANDELA_FN float eta() const { return eta_; }

  // Delta lobes only: light sampling cannot find them, so next-event estimation is skipped.
  CANDELA_FN bool isDelta() const { return isSpecularMaterial(material_); }
  CANDELA_FN bool hasTransmission() const {
    switch (material_.type) {
      case MaterialType::Glass: return true;
      case MaterialType::Disney: return material_.specTrans > 0.0f && material_.metallic < 1.0f;
      default: return false;
    }
  }

  // Calls f with the model of this material's type.
  template <class F>
  CANDELA_FN auto visit(F&& f) const {
    const Material& m = material_;
    switch (m.type) {
      case MaterialType::BlinnPhong: return f(BlinnPhongBsdf(m.baseColor, m.specularColor, m.shininess));
      case MaterialType::Pbr: return f(PbrBsdf(m.baseColor, m.metallic, m.roughness, m.specular));
      case MaterialType::Disney: return f(DisneyBsdf(m, eta_));
      case MaterialType::Mirror: return f(MirrorBsdf{m.specularColor});
      case MaterialType::Glass: return f(SmoothDielectricBsdf{eta_, sqrtColor(m.baseColor)});
      case MaterialType::Diffuse:
      case MaterialType::Mix: break;  // a mix never gets here: evaluateSurfaceMaterial resolves it first
    }
    return f(LambertianBsdf{m.baseColor});
  }

  CANDELA_FN Vec3 eval(Vec3 woWorld, Vec3 wiWorld) const {
    Vec3 wo = toLocal(woWorld), wi = toLocal(wiWorld);
    return visit([&](const auto& model) { return model.eval(wo, wi); });
  }
  CANDELA_FN float pdf(Vec3 woWorld, Vec3 wiWorld) const {
    Vec3 wo = toLocal(woWorld), wi = toLocal(wiWorld);
    return visit([&](const auto& model) { return model.pdf(wo, wi); });
  }
  // Returns wi in world space. uChoice picks a lobe (and reflection or refraction), u the direction.
  CANDELA_FN BsdfSample sample(Vec3 woWorld, float uChoice, Vec2 u) const {
    Vec3 wo = toLocal(woWorld);
    BsdfSample s = visit([&](const auto& model) { return model.sample(wo, uChoice, u); });
    s.wi = toWorld(s.wi);
    return s;
  }

 private:
  CANDELA_FN static Vec3 sqrtColor(Vec3 c) {
    return {sqrtf(fmaxf(0.0f, c.x)), sqrtf(fmaxf(0.0f, c.y)), sqrtf(fmaxf(0.0f, c.z))};
  }

  Frame frame_;
  Material material_;
  float eta_ = 1.0f;
};

}  // namespace candela
