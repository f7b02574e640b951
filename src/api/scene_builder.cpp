#include <cmath>
#include <cstdio>
#include <string>

#include "api/error_translation.h"
#include "api/scene_data.h"
#include "app/scene_loading.h"
#include "io/images/image_decoding.h"
#include "kernel/bsdf/material_type_names.h"
#include "scene/scene_repair.h"

namespace candela::api {

namespace {

candela::Vec3 vec3(const Vec3& v) { return {v[0], v[1], v[2]}; }

// A direction of unit length; Error naming `what` where it has none.
candela::Vec3 unitDirection(const Vec3& v, const char* what) {
  const candela::Vec3 d = vec3(v);
  const float l = length(d);
  if (!(l > 0.0f) || !std::isfinite(l)) throw Error(std::string(what) + ": the direction has no length");
  return d * (1.0f / l);
}

}  // namespace

struct SceneBuilder::State {
  candela::Scene scene;
};

SceneBuilder::SceneBuilder(const std::string& name) : state_(std::make_unique<State>()) {
  state_->scene.name = name;
  state_->scene.cameraMissing = true;
}
SceneBuilder::~SceneBuilder() = default;
SceneBuilder::SceneBuilder(SceneBuilder&&) noexcept = default;
SceneBuilder& SceneBuilder::operator=(SceneBuilder&&) noexcept = default;

uint32_t SceneBuilder::addMaterial(const Material& material) {
  std::optional<MaterialType> type = materialTypeNamed(material.type);
  if (!type)
    throw Error("unknown material type '" + printableText(material.type) + "' (use " + materialTypeNameList() + ")");
  candela::Material m;
  m.type = *type;
  m.baseColor = vec3(material.baseColor);
  m.emission = vec3(material.emission);
  m.roughness = material.roughness;
  m.metallic = material.metallic;
  m.ior = material.ior;
  state_->scene.materials.push_back(m);
  state_->scene.materialNames.push_back("material " + std::to_string(state_->scene.materials.size() - 1));
  return uint32_t(state_->scene.materials.size() - 1);
}

uint32_t SceneBuilder::addMesh(const MeshArrays& arrays) {
  candela::Scene& scene = state_->scene;
  const std::string name = "mesh " + std::to_string(scene.meshes.size());
  if (arrays.triangleCount == 0 || arrays.vertexCount == 0) throw Error(name + ": no triangles");
  if (!arrays.positions || !arrays.indices) throw Error(name + ": positions and indices are required");
  if (arrays.vertexCount > UINT32_MAX) throw Error(name + ": more than 2^32 - 1 vertices");
  Mesh mesh;
  mesh.name = name;
  mesh.positions.resize(arrays.vertexCount);
  for (size_t v = 0; v < arrays.vertexCount; ++v) {
    const float* p = arrays.positions + 3 * v;
    mesh.positions[v] = {p[0], p[1], p[2]};
  }
  mesh.indices.assign(arrays.indices, arrays.indices + 3 * arrays.triangleCount);
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= arrays.vertexCount)
      throw Error(name + ": triangle " + std::to_string(i / 3) + " names vertex " + std::to_string(mesh.indices[i]) +
                  ", beyond its " + std::to_string(arrays.vertexCount) + " vertices");
  if (arrays.normals) {
    mesh.normals.resize(arrays.vertexCount);
    for (size_t v = 0; v < arrays.vertexCount; ++v) {
      const float* n = arrays.normals + 3 * v;
      mesh.normals[v] = {n[0], n[1], n[2]};
    }
  }
  if (arrays.uvs) {
    mesh.uvs.resize(arrays.vertexCount);
    for (size_t v = 0; v < arrays.vertexCount; ++v) mesh.uvs[v] = {arrays.uvs[2 * v], arrays.uvs[2 * v + 1]};
  }
  if (arrays.triangleMaterials)
    mesh.triangleMaterials.assign(arrays.triangleMaterials, arrays.triangleMaterials + arrays.triangleCount);
  else
    mesh.triangleMaterials.assign(arrays.triangleCount, arrays.material);
  Instance instance;
  instance.meshId = uint32_t(scene.meshes.size());
  for (int i = 0; i < 12; ++i) instance.objectToWorld.m[i] = arrays.transform[size_t(i)];
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back(instance);
  return instance.meshId;
}

void SceneBuilder::addPointLight(const Vec3& position, const Vec3& intensity) {
  PunctualLight light;
  light.type = PunctualLightType::Point;
  light.position = vec3(position);
  light.intensity = vec3(intensity);
  state_->scene.punctualLights.push_back(light);
}

void SceneBuilder::addSpotLight(const Vec3& position, const Vec3& direction, const Vec3& intensity, float innerDegrees,
                                float outerDegrees) {
  if (!(0.0f <= innerDegrees && innerDegrees <= outerDegrees && outerDegrees <= 180.0f))
    throw Error("spot light: the angles must satisfy 0 <= inner <= outer <= 180 degrees");
  PunctualLight light;
  light.type = PunctualLightType::Spot;
  light.position = vec3(position);
  light.direction = unitDirection(direction, "spot light");
  light.intensity = vec3(intensity);
  light.cosInner = std::cos(innerDegrees * kPi / 180.0f);
  light.cosOuter = std::cos(outerDegrees * kPi / 180.0f);
  state_->scene.punctualLights.push_back(light);
}

void SceneBuilder::addDirectionalLight(const Vec3& direction, const Vec3& irradiance) {
  PunctualLight light;
  light.type = PunctualLightType::Directional;
  light.direction = unitDirection(direction, "directional light");
  light.intensity = vec3(irradiance);
  state_->scene.punctualLights.push_back(light);
}

void SceneBuilder::setEnvironment(const Vec3& radiance) {
  state_->scene.environment = Environment{};
  state_->scene.environment.radiance = vec3(radiance);
}

void SceneBuilder::setEnvironmentMap(const std::string& path, float intensity, float rotationDegrees) {
  withErrorsTranslated("load", [&] {
    Environment environment;
    environment.map = loadEnvironmentImage(path);
    environment.intensity = intensity;
    environment.rotationDegrees = rotationDegrees;
    state_->scene.environment = std::move(environment);
  });
}

void SceneBuilder::setCamera(const Camera& camera) {
  CameraDescription& c = state_->scene.camera;
  c = CameraDescription{};
  c.eye = vec3(camera.eye);
  c.target = vec3(camera.target);
  c.up = vec3(camera.up);
  c.verticalFovDegrees = camera.verticalFovDegrees;
  state_->scene.cameraMissing = false;
}

Scene SceneBuilder::build() const {
  return withErrorsTranslated("load", [&] {
    candela::Scene scene = state_->scene;
    const size_t materials = scene.materials.size();
    for (const Mesh& mesh : scene.meshes)
      for (size_t t = 0; t < mesh.triangleMaterials.size(); ++t)
        if (mesh.triangleMaterials[t] >= materials)
          throw Error(mesh.name + ": triangle " + std::to_string(t) + " names material " +
                      std::to_string(mesh.triangleMaterials[t]) + ", but " + std::to_string(materials) +
                      " materials were added");
    LoadWarnings warnings;
    repairScene(scene, scene.name, warnings);
    if (!hasLightSource(scene))
      warnings.add(scene.name,
                   "the scene has no light source (no emissive material, light or environment): the image will be "
                   "black");
    for (const std::string& w : warnings.messages) std::fprintf(stderr, "candela: warning: %s\n", w.c_str());
    if (scene.cameraMissing) frameSceneBounds(scene);
    validateScene(scene);
    return Scene(std::make_shared<const Scene::Data>(Scene::Data{std::move(scene)}));
  });
}

}  // namespace candela::api
