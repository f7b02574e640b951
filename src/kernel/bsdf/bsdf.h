#pragma once
#include "kernel/bsdf/material_models.h"
#include "kernel/interaction.h"
#include "kernel/kernel_variant.h"
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
    // Each model's case returns, but the fallback's breaks, to share the code after the switch with a mix and with
    // types outside the list: every model is built in one place, as in a switch written out by hand.
    switch (m.type) {
#define CANDELA_BUILD_MODEL_CASE(type, Model, name, shadingName) \
  case MaterialType::type:                                       \
    if (isFallback(MaterialType::type)) break;                   \
    model_.as##type = Model::fromMaterial(m, eta, si.uv);        \
    return;
      CANDELA_MATERIAL_MODELS(CANDELA_BUILD_MODEL_CASE)
#undef CANDELA_BUILD_MODEL_CASE
      case MaterialType::Mix: break;  // never built: evaluateSurfaceMaterial resolves a mix first
    }
    type_ = kFallbackType;
    model_.asDiffuse = LambertianBsdf::fromMaterial(m, eta, si.uv);
  }

  CANDELA_FN Vec3 toLocal(Vec3 w) const { return frame_.toLocal(w); }
  CANDELA_FN Vec3 toWorld(Vec3 w) const { return frame_.toWorld(w); }
  CANDELA_FN Vec3 normal() const { return frame_.n; }

  // Calls f with the model of this material's type; the fallback's case shares the call after the switch, as the
  // constructor's does.
  template <class F>
  CANDELA_FN auto visit(F&& f) const {
    switch (type_) {
#define CANDELA_VISIT_MODEL_CASE(type, Model, name, shadingName) \
  case MaterialType::type:                                       \
    if (isFallback(MaterialType::type)) break;                   \
    return f(model_.as##type);
      CANDELA_MATERIAL_MODELS(CANDELA_VISIT_MODEL_CASE)
#undef CANDELA_VISIT_MODEL_CASE
      case MaterialType::Mix: break;  // never: the constructor builds the fallback instead
    }
    return f(model_.asDiffuse);
  }

  // Delta lobes only: light sampling cannot find them, so next-event estimation is skipped.
  CANDELA_FN bool isDelta() const { return isDeltaModel(type_); }
  CANDELA_FN bool hasTransmission() const {
    return visit([](const auto& model) { return model.hasTransmission(); });
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
  // The model built for a mix or a type outside the list: a diffuse surface, asDiffuse.
  static constexpr MaterialType kFallbackType = MaterialType::Diffuse;
  // Whether `type` is built as the fallback: the fallback itself, and a model this compile of the kernel leaves out
  // (kernel/kernel_variant.h), whose code then folds away.
  CANDELA_FN static constexpr bool isFallback(MaterialType type) {
    return type == kFallbackType || !kernelHasModel(type);
  }

  // The one model type_ names (the member as<type>: asDiffuse, asDisney, ...); the others are never read. Each is
  // plain data, so assigning one begins its life.
  union Model {
    CANDELA_FN Model() {}
#define CANDELA_MODEL_MEMBER(type, Class, name, shadingName) Class as##type;
    CANDELA_MATERIAL_MODELS(CANDELA_MODEL_MEMBER)
#undef CANDELA_MODEL_MEMBER
  };

  Frame frame_;
  MaterialType type_;
  Model model_;
};

}  // namespace candela
