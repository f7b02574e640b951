#include "scene/loaders/pbrt/pbrt_lights.h"

#include <algorithm>
#include <cmath>

#include "core/file_extension.h"
#include "io/images/image_decoding.h"
#include "io/load_budget.h"
#include "scene/loaders/pbrt/pbrt_pfm.h"

namespace candela {

namespace {

// Bilinear lookup of a float image at (u, v) in [0, 1]^2, v down the rows, clamped at the edges.
Vec3 sampleClamped(const Texture& image, float u, float v) {
  float x = std::clamp(u * float(image.width) - 0.5f, 0.0f, float(image.width - 1));
  float y = std::clamp(v * float(image.height) - 0.5f, 0.0f, float(image.height - 1));
  uint32_t x0 = uint32_t(x), y0 = uint32_t(y);
  uint32_t x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  float fx = x - float(x0), fy = y - float(y0);
  auto texel = [&](uint32_t tx, uint32_t ty) {
    const float* p = image.floats.data() + (size_t(ty) * image.width + tx) * image.channels;
    return image.channels >= 3 ? Vec3{p[0], p[1], p[2]} : Vec3{p[0], p[0], p[0]};
  };
  return lerp(fy, lerp(fx, texel(x0, y0), texel(x1, y0)), lerp(fx, texel(x0, y1), texel(x1, y1)));
}

}  // namespace

Vec2 equalAreaSphereToSquare(Vec3 d) {
  float x = std::fabs(d.x), y = std::fabs(d.y), z = std::fabs(d.z);
  float r = std::sqrt(std::max(0.0f, 1.0f - z));
  float a = std::max(x, y), b = std::min(x, y);
  b = a == 0.0f ? 0.0f : b / a;
  float phi = std::atan(b) * 2.0f / kPi;
  if (x < y) phi = 1.0f - phi;
  float v = phi * r;
  float u = r - v;
  if (d.z < 0.0f) {
    std::swap(u, v);
    u = 1.0f - u;
    v = 1.0f - v;
  }
  u = std::copysign(u, d.x);
  v = std::copysign(v, d.y);
  return {0.5f * (u + 1.0f), 0.5f * (v + 1.0f)};
}

PbrtAreaLight makePbrtAreaLight(const std::string& type, const PbrtParameters& params, PbrtContext& context) {
  if (type != "diffuse") context.warn("area light " + type, "area light '" + type + "' read as 'diffuse'");
  PbrtAreaLight light;
  PbrtColor L = params.getColor("L").value_or(PbrtColor{{1, 1, 1}, true});
  light.radiance = L.rgb * params.getFloat("scale", 1.0f);
  light.twoSided = params.getBool("twosided", false);
  light.power = std::max(0.0f, params.getFloat("power", 0.0f));
  if (params.find("filename")) context.warn("area light image", "area light images are not supported: L used");
  return light;
}

Vec3 pbrtAreaLightRadiance(const PbrtAreaLight& light, float worldArea) {
  if (!(light.power > 0.0f)) return light.radiance;
  // pbrt-v4 divides out the luminance of the illuminant behind an RGB L (so (1, 1, 1) emits 1 nit), not that
  // of the RGB value: L = (2, 2, 2) with `power` emits twice the power asked for, as in pbrt.
  float emitting = kPi * worldArea * (light.twoSided ? 2.0f : 1.0f);
  return emitting > 0.0f ? light.radiance * (light.power / emitting) : Vec3{0, 0, 0};
}

PunctualLight makePbrtPunctualLight(const std::string& type, const PbrtParameters& params,
                                    const glm::mat4& worldFromLight) {
  auto point = [&](const char* name, Vec3 fallback) {
    std::vector<Vec3> p = params.getVec3s(name);
    Vec3 local = p.empty() ? fallback : p[0];
    glm::vec4 world = worldFromLight * glm::vec4(local.x, local.y, local.z, 1.0f);
    return Vec3{world.x, world.y, world.z};
  };
  PunctualLight light;
  float scale = params.getFloat("scale", 1.0f);
  const Vec3 from = point("from", {0, 0, 0});
  if (type == "distant") {
    light.type = PunctualLightType::Directional;
    // pbrt-v4: `illuminance` (lux) times the spectrum of L, normalised to luminance 1 (as RGB L already is).
    const float illuminance = params.getFloat("illuminance", -1.0f);
    if (illuminance > 0.0f) scale *= illuminance;
    light.intensity = params.getColor("L").value_or(PbrtColor{{1, 1, 1}, true}).rgb * scale;
    light.direction = normalize(point("to", {0, 0, 1}) - from);
    return light;
  }
  light.position = from;
  const float power = params.getFloat("power", -1.0f);
  if (type == "spot") {
    light.type = PunctualLightType::Spot;
    light.direction = normalize(point("to", {0, 0, 1}) - from);
    // pbrt-v3 named the falloff band `conedeltaangle` (pbrt-v4-scenes' villa still does).
    const float cone = params.getFloat("coneangle", 30.0f);
    const float delta =
        params.find("conedelta") ? params.getFloat("conedelta", 5.0f) : params.getFloat("conedeltaangle", 5.0f);
    light.cosOuter = std::cos(cone * kPi / 180.0f);
    light.cosInner = std::cos(std::max(cone - delta, 0.0f) * kPi / 180.0f);
    // pbrt-v4's solid angle of a spot, its falloff counted as half: `power` (lumens) over it gives the intensity.
    const float solidAngle = 2.0f * kPi * ((1.0f - light.cosInner) + (light.cosInner - light.cosOuter) / 2.0f);
    if (power > 0.0f && solidAngle > 0.0f) scale *= power / solidAngle;
  } else if (power > 0.0f) {
    scale *= power / (4.0f * kPi);  // a point light's power spreads over the whole sphere
  }
  light.intensity = params.getColor("I").value_or(PbrtColor{{1, 1, 1}, true}).rgb * scale;
  return light;
}

// The most rows of an infinite light's map once resampled to candela's equirectangular layout.
constexpr uint32_t kMaxEnvironmentHeight = 8192;

Environment makePbrtInfiniteLight(const PbrtParameters& params, const glm::mat4& worldFromLight, bool mirrorX,
                                  PbrtContext& context) {
  Environment env;
  float scale = params.getFloat("scale", 1.0f);
  // pbrt-v4's `illuminance`: what the light gives a surface facing its +z (lux).
  const float illuminance = params.getFloat("illuminance", -1.0f);
  if (params.find("portal")) context.warn("infinite portal", "infinite light portals are ignored");
  std::string file = params.getString("filename", "");
  if (file.empty()) {
    if (illuminance > 0.0f) scale *= illuminance / kPi;  // a uniform L gives pi L on a surface
    env.radiance = params.getColor("L").value_or(PbrtColor{{1, 1, 1}, true}).rgb * scale;
    return env;
  }
  std::string path = context.resolve(file, params.file, params.line);
  Texture source =
      lowerCaseExtension(path) == ".pfm" ? readPfm(path, kMaxEnvironmentHeight * 2) : loadEnvironmentImage(path);
  bool octahedral = source.width == source.height;
  if (!octahedral && source.width != 2 * source.height)
    context.warn("infinite map layout", "environment map '" + file +
                                            "' is neither square (pbrt-v4's octahedral "
                                            "layout) nor 2:1: read as equirectangular");
  glm::mat4 lightFromWorld = glm::inverse(worldFromLight);
  Texture& map = env.map;
  // Not the file's name: the map is no longer the file's layout (a viewer's saved view must not name the file as
  // an equirectangular map).
  map.name = path + " (resampled to equirectangular)";
  // As many rows as the file's for the layouts pbrt writes; for any other shape (a map of 1 x 8192 pixels) as
  // many texels as the file has, so that a thin file does not become a map of a hundred million texels.
  const bool usualLayout = octahedral || source.width == 2 * source.height;
  const double sourceTexels = double(source.width) * double(source.height);
  map.height = usualLayout ? source.height : uint32_t(std::max(1.0, std::round(std::sqrt(sourceTexels / 2.0))));
  map.height = std::clamp(map.height, 1u, kMaxEnvironmentHeight);
  map.width = 2 * map.height;
  chargeLoadMemory(uint64_t(map.width) * map.height * 3 * sizeof(float), path,
                   "the infinite light's map resampled to " + std::to_string(map.width) + "x" +
                       std::to_string(map.height) + " texels");
  map.channels = 3;
  map.floats.resize(size_t(map.width) * map.height * 3);
  double mapIlluminance = 0.0;  // of the file's values over the light's upper hemisphere, before `scale`
  for (uint32_t row = 0; row < map.height; ++row)
    for (uint32_t column = 0; column < map.width; ++column) {
      // candela's map direction of this texel (kernel/environment.h), then pbrt's world, then the light's frame.
      float phi = 2.0f * kPi * ((float(column) + 0.5f) / float(map.width) - 0.5f);
      float theta = kPi * (float(row) + 0.5f) / float(map.height);
      Vec3 d{std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
      if (mirrorX) d.x = -d.x;
      glm::vec4 l = lightFromWorld * glm::vec4(d.x, d.y, d.z, 0.0f);
      Vec3 dl = normalize(Vec3{l.x, l.y, l.z});
      Vec3 value{0, 0, 0};
      if (isFinite(dl)) {
        if (octahedral) {
          Vec2 uv = equalAreaSphereToSquare(dl);
          value = sampleClamped(source, uv.x, uv.y);
        } else {
          float lightPhi = std::atan2(dl.y, dl.x);
          if (lightPhi < 0.0f) lightPhi += 2.0f * kPi;
          value = sampleClamped(source, lightPhi / (2.0f * kPi), std::acos(std::clamp(dl.z, -1.0f, 1.0f)) / kPi);
        }
      }
      if (isFinite(dl) && dl.z > 0.0f) {
        const double solidAngle = (2.0 * kPi / double(map.width)) * (kPi / double(map.height)) * std::sin(theta);
        mapIlluminance += double(luminance(value)) * dl.z * solidAngle;
      }
      float* out = map.floats.data() + (size_t(row) * map.width + column) * 3;
      out[0] = value.x * scale;
      out[1] = value.y * scale;
      out[2] = value.z * scale;
    }
  // As pbrt-v4: the map is scaled to give `illuminance` (times `scale`) on a surface facing the light's +z.
  if (illuminance > 0.0f && mapIlluminance > 0.0 && std::isfinite(mapIlluminance))
    for (float& f : map.floats) f *= float(illuminance / mapIlluminance);
  return env;
}

}  // namespace candela
