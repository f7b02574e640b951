#pragma once
#include <glm/mat4x4.hpp>

#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"

namespace candela {

// pbrt's `AreaLightSource "diffuse"`: radiance L (times scale) from the front of the shapes that follow, or from
// both sides; `power` (watts) sets the radiance from the area of each shape instead. pbrt-v4 makes a light of
// every triangle of a mesh (and every patch of a bilinear mesh), so `power` applies to each of them.
struct PbrtAreaLight {
  Vec3 radiance{1, 1, 1};
  bool twoSided = false;
  float power = 0.0f;  // 0: not given
};
PbrtAreaLight makePbrtAreaLight(const std::string& type, const PbrtParameters& params, PbrtContext& context);

// The radiance an area light gives a shape (a triangle, a patch, a quadric) of `worldArea` (after `power`).
Vec3 pbrtAreaLightRadiance(const PbrtAreaLight& light, float worldArea);

// pbrt's `LightSource "infinite"` as candela's environment: a constant L, or an image (`filename`) in pbrt-v4's
// equal-area octahedral layout (square) or pbrt-v3's equirectangular one (twice as wide as high), resampled into
// candela's equirectangular orientation through the light's transform `worldFromLight` and, when `mirrorX`, the
// reflection x -> -x that turns pbrt's left-handed world into candela's right-handed one. `illuminance` scales
// either, as in pbrt-v4, to give that many lux (times `scale`) on a surface facing the light's +z.
Environment makePbrtInfiniteLight(const PbrtParameters& params, const glm::mat4& worldFromLight, bool mirrorX,
                                  PbrtContext& context);

// pbrt's `LightSource "point"`, "spot" and "distant" as candela's punctual lights, placed by `worldFromLight` (the
// world mirror included): I (or L for a distant light) times scale; a spot's `coneangle` and `conedelta` bound its
// smoothstep falloff as in pbrt-v4; a distant light travels from `from` to `to`. As in pbrt-v4, a point or spot
// light's `power` (over the sphere, or the spot's cone with its falloff counted as half) and a distant light's
// `illuminance` multiply I (or L), whose spectrum is normalised to luminance 1 (RGB values are taken as they are).
PunctualLight makePbrtPunctualLight(const std::string& type, const PbrtParameters& params,
                                    const glm::mat4& worldFromLight);

// Where pbrt-v4's equal-area octahedral map (Clarberg 2008) puts direction `d` (unit length): [0, 1]^2.
Vec2 equalAreaSphereToSquare(Vec3 d);

}  // namespace candela
