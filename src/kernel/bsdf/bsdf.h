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
// along the surface's tangent when it has one). The model of the material's type is built once, here, and every
// eval, pdf, evalPdf and sample call of the vertex dispatches to it with a switch over the type: no virtual
// calls, so the same code runs on the device.
class Bsdf {
 public:
  // `m` has its textures already applied (see evaluateMaterial).
  CANDELA_FN Bsdf(const Material& m, const SurfaceInteraction& si, Vec3 woWorld) : type_(m.type) {
    Vec3 n = dot(si.shadingNormal, woWorld) < 0.0f ? -si.shadingNormal : si.shadingNormal;
    Vec3 s = si.tangent - n * dot(n, si.tangent);
    float len = length(s);
    frame_ = len > 1e-6f ? Frame{s / len, cross(n, s / len), n} : Frame::fromNormal(n);
    // Closed meshes are wound outwards: arriving on the front side means entering the material.
    float ior = m.ior > 0.0f ? m.ior : 1.0f;
    float eta = dot(woWorld, si.geometricNormal) >= 0.0f ? ior : 1.0f / ior;
    switch (m.type) {
      case MaterialType::BlinnPhong:
        model_.blinnPhong = BlinnPhongBsdf(m.baseColor, m.specularColor, m.shininess);
        break;
      case MaterialType::Pbr:
        model_.pbr = PbrBsdf(m.baseColor, m.metallic, m.roughness, m.specular, m.iridescence, m.iridescenceIor,
                             m.iridescenceThickness);
        break;
      case MaterialType::Disney: model_.disney = DisneyBsdf(m, eta); break;
      case MaterialType::Mirror: model_.mirror = MirrorBsdf{m.specularColor}; break;
      case MaterialType::Glass: model_.glass = SmoothDielectricBsdf{eta, sqrtColor(m.baseColor)}; break;
      case MaterialType::Diffuse:
      default:
        type_ = MaterialType::Diffuse;
        model_.lambertian = LambertianBsdf{m.baseColor};
        break;
    }
  }

  CANDELA_FN Vec3 toLocal(Vec3 w) const { return frame_.toLocal(w); }
  CANDELA_FN Vec3 toWorld(Vec3 w) const { return frame_.toWorld(w); }
  CANDELA_FN Vec3 normal() const { return frame_.n; }

  // Delta lobes only: light sampling cannot find them, so next-event estimation is skipped.
  CANDELA_FN bool isDelta() const { return type_ == MaterialType::Mirror || type_ == MaterialType::Glass; }
  CANDELA_FN bool hasTransmission() const {
    switch (type_) {
      case MaterialType::Glass: return true;
      case MaterialType::Disney: return model_.disney.glassWeight > 0.0f;
      default: return false;
    }
  }

  // Calls f with the model of this material's type.
  template <class F>
  CANDELA_FN auto visit(F&& f) const {
    switch (type_) {
      case MaterialType::BlinnPhong: return f(model_.blinnPhong);
      case MaterialType::Pbr: return f(model_.pbr);
      case MaterialType::Disney: return f(model_.disney);
      case MaterialType::Mirror: return f(model_.mirror);
      case MaterialType::Glass: return f(model_.glass);
      case MaterialType::Diffuse:
      case MaterialType::Mix: break;  // never built: evaluateSurfaceMaterial resolves a mix first
    }
    return f(model_.lambertian);
  }

  CANDELA_FN Vec3 eval(Vec3 woWorld, Vec3 wiWorld) const {
    Vec3 wo = toLocal(woWorld), wi = toLocal(wiWorld);
    return visit([&](const auto& model) { return model.eval(wo, wi); });
  }
  CANDELA_FN float pdf(Vec3 woWorld, Vec3 wiWorld) const {
    Vec3 wo = toLocal(woWorld), wi = toLocal(wiWorld);
    return visit([&](const auto& model) { return model.pdf(wo, wi); });
  }
  // eval() and pdf() in one call, for next-event estimation and its MIS weight.
  CANDELA_FN BsdfEval evalPdf(Vec3 woWorld, Vec3 wiWorld) const {
    Vec3 wo = toLocal(woWorld), wi = toLocal(wiWorld);
    return visit([&](const auto& model) { return model.evalPdf(wo, wi); });
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

  // The one model type_ names; the others are never read. Each is plain data, so assigning one begins its life.
  union Model {
    CANDELA_FN Model() {}
    LambertianBsdf lambertian;
    BlinnPhongBsdf blinnPhong;
    PbrBsdf pbr;
    DisneyBsdf disney;
    MirrorBsdf mirror;
    SmoothDielectricBsdf glass;
  };

  Frame frame_;
  MaterialType type_;
  Model model_;
};

}  // namespace candela
