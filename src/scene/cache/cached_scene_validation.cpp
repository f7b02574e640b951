#include "scene/cache/cached_scene_validation.h"

#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>

#include "kernel/scene_arrays.h"
#include "scene/material_checks.h"

namespace candela {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what); }

bool finite(float x) { return std::isfinite(x); }
bool finite(uint32_t) { return true; }             // indices and material ids, whose ranges validateScene checks
bool finite(const CurveSegment&) { return true; }  // validateScene checks its ranges and type
bool finite(Vec2 v) { return finite(v.x) && finite(v.y); }
bool finite(Vec3 v) { return finite(v.x) && finite(v.y) && finite(v.z); }
bool finite(Vec4 v) { return finite(v.x) && finite(v.y) && finite(v.z) && finite(v.w); }
bool finite(const Affine3x4& a) {
  for (float x : a.m)
    if (!finite(x)) return false;
  return true;
}
template <class T>
bool allFinite(const std::vector<T>& values) {
  for (const T& v : values)
    if (!finite(v)) return false;
  return true;
}

// width * height * channels, or nothing when the product does not fit in 64 bits (then no array can hold it).
bool texelValues(const Texture& t, uint64_t& values) {
  const uint64_t max = std::numeric_limits<uint64_t>::max();
  const uint64_t pixels = uint64_t(t.width) * t.height;  // fits: both are 32-bit
  if (t.channels != 0 && pixels > max / t.channels) return false;
  values = pixels * t.channels;
  return true;
}

void checkTexture(const Texture& t) {
  const std::string name = "texture '" + t.name + "'";
  if (uint32_t(t.wrapU) > uint32_t(TextureWrap::Mirror) || uint32_t(t.wrapV) > uint32_t(TextureWrap::Mirror))
    fail(name + " has an unknown wrap mode");
  if (t.width == 0 || t.height == 0 || t.channels < 1 || t.channels > 4)
    fail(name + " has no texels or an unsupported channel count");
  uint64_t values = 0;
  if (!texelValues(t, values)) fail(name + " is too large");
  // One of the two arrays holds the texels, the other is empty.
  const bool bytes = t.bytes.size() == values && t.floats.empty();
  const bool floats = t.floats.size() == values && t.bytes.empty();
  if (!bytes && !floats) fail(name + " holds the wrong number of values for its size");
  if (!allFinite(t.floats)) fail(name + " has non-finite values");
}

// Every per-mesh array of kernel/scene_arrays.h; validateScene has checked the indices' ranges.
void checkMeshes(const Scene& scene) {
  for (const Mesh& m : scene.meshes) {
#define CANDELA_CHECK_MESH_ARRAY(Type, member, upload, count, description) \
  if (!allFinite(m.member)) fail("mesh '" + m.name + "' has non-finite " + description);
    CANDELA_MESH_ARRAYS(CANDELA_CHECK_MESH_ARRAY)
#undef CANDELA_CHECK_MESH_ARRAY
  }
  for (const Instance& instance : scene.instances)
    if (!finite(instance.objectToWorld)) fail("an instance has a non-finite transform");
}

void checkMaterials(const Scene& scene) {
  for (const Material& m : scene.materials) {
    if (uint32_t(m.type) > uint32_t(MaterialType::Mix)) fail("a material has an unknown type");
    if (uint32_t(m.alphaMode) > uint32_t(AlphaMode::Blend)) fail("a material has an unknown alpha mode");
    if (m.doubleSided > 1) fail("a material's double-sided flag is neither 0 nor 1");
    if (m.interfaceOnly > 1) fail("a material's interface flag is neither 0 nor 1");
    if (std::string problem = materialMemberProblem(m, scene.textures.size()); !problem.empty()) fail(problem);
  }
  if (!scene.materialNames.empty() && scene.materialNames.size() != scene.materials.size())
    fail(std::to_string(scene.materialNames.size()) + " material names for " + std::to_string(scene.materials.size()) +
         " materials");
}

void checkEnvironment(const Environment& e) {
  auto nonNegative = [](Vec3 v) { return finite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f; };
  if (!nonNegative(e.radiance)) fail("the environment radiance is negative or not finite");
  if (!finite(e.intensity) || e.intensity < 0.0f) fail("the environment intensity is negative or not finite");
  if (!finite(e.rotationDegrees)) fail("the environment rotation is not finite");
  const Texture& map = e.map;
  const bool empty = map.width == 0 && map.height == 0 && map.bytes.empty() && map.floats.empty();
  if (empty) return;
  checkTexture(map);
  if (map.channels < 3 || map.floats.empty()) fail("the environment map is not a float RGB image");
  for (float x : map.floats)
    if (x < 0.0f) fail("the environment map has negative values");
}

void checkCamera(const CameraDescription& c) {
  if (!finite(c.eye) || !finite(c.target) || !finite(c.up)) fail("the camera has non-finite vectors");
  if (!(c.verticalFovDegrees > 0.0f && c.verticalFovDegrees < 180.0f))
    fail("the camera's field of view is not between 0 and 180 degrees");
  if (!(finite(c.apertureRadius) && c.apertureRadius >= 0.0f && finite(c.focusDistance) && c.focusDistance >= 0.0f))
    fail("the camera's aperture or focus distance is negative or not finite");
  if (!(c.projection == Projection::Perspective || c.projection == Projection::Orthographic))
    fail("the camera's projection is unknown");
  if (!(finite(c.orthographicHalfHeight) && c.orthographicHalfHeight > 0.0f && finite(c.imageShift.x) &&
        finite(c.imageShift.y)))
    fail("the camera's orthographic size or image shift is not positive or not finite");
  const Vec3 forward = c.target - c.eye;
  if (!(length(forward) > 0.0f) || !(length(cross(forward, c.up)) > 0.0f))
    fail("the camera's position, target and up do not make a view");
}

void checkPunctualLights(const std::vector<PunctualLight>& lights) {
  for (const PunctualLight& l : lights) {
    if (uint32_t(l.type) > uint32_t(PunctualLightType::Directional)) fail("a punctual light has an unknown type");
    if (!finite(l.cosInner) || !finite(l.cosOuter)) fail("a punctual light has a non-finite cone");
  }
}

void checkRenderHints(const RenderHints& h) {
  auto within = [](const std::optional<uint32_t>& v, uint32_t max) { return !v || (*v >= 1 && *v <= max); };
  // The ranges the scene file accepts (scene_file.cpp).
  if (!within(h.width, 16384) || !within(h.height, 16384) || !within(h.samplesPerPixel, 1u << 24) ||
      !within(h.maxDepth, 1024))
    fail("the render settings are out of range");
}

}  // namespace

void validateCachedScene(const Scene& scene) {
  // Texture sizes first: validateScene multiplies them without guarding against overflow.
  for (const Texture& t : scene.textures) checkTexture(t);
  validateScene(scene);
  checkMeshes(scene);
  checkMaterials(scene);
  checkEnvironment(scene.environment);
  checkCamera(scene.camera);
  for (const NamedCamera& c : scene.cameras) checkCamera(c.description);
  checkPunctualLights(scene.punctualLights);
  checkRenderHints(scene.renderHints);
  if (scene.cameraIndex < -1 || scene.cameraIndex >= int64_t(scene.cameras.size()))
    fail("the scene's camera is not one of its cameras");
  validateAnimation(scene);
}

}  // namespace candela
