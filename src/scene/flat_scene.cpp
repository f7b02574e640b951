#include "scene/flat_scene.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "kernel/bsdf/material_models.h"
#include "kernel/lights.h"
#include "kernel/pass_through.h"
#include "scene/emission_average.h"
#include "scene/light_bvh.h"
#include "scene/mip_pyramid.h"
#include "scene/tangents.h"
#include "scene/transform.h"

namespace candela {

namespace {

// How often next-event estimation picks each kind of light, as pbrt-v4's BVHLightSampler: each infinite light (an
// emitting environment, each directional light) and the bounded lights together alike.
void setLightSelectProbabilities(FlatScene& flat) {
  bool environmentEmits = flat.environmentTexels.empty()
                              ? !isBlack(flat.environment.scale)
                              : flat.environmentDistribution.funcAverage > 0.0f && !isBlack(flat.environment.scale);
  const size_t directional = flat.punctualLights.size() - flat.boundedPunctualLightCount;
  const size_t infinite = (environmentEmits ? 1 : 0) + directional;
  const bool bounded = !flat.lights.empty() || flat.boundedPunctualLightCount > 0;
  const float each = infinite + (bounded ? 1 : 0) > 0 ? 1.0f / float(infinite + (bounded ? 1 : 0)) : 0.0f;
  flat.environmentSelectProbability = environmentEmits ? each : 0.0f;
  flat.directionalSelectProbability = directional > 0 ? each : 0.0f;
  flat.boundedSelectProbability = bounded ? 1.0f - float(infinite) * each : 0.0f;
}

// The power table and the light BVH over the bounded lights: the emissive triangles, which this collects, then
// the point and spot lights at the front of flat.punctualLights. Each triangle is weighed by what it emits on
// average (its material's emission times the mean of its emission texture over it); those that emit nothing
// there are left out. The textures must be packed already.
void buildLightTable(const Scene& scene, FlatScene& flat) {
  struct Candidate {
    const Mesh* mesh;
    uint32_t triangle;
  };
  std::vector<Candidate> candidates;
  std::vector<LightTriangle> lights;
  // Which meshes emit, found once per mesh rather than once per instance.
  std::vector<bool> emits(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    for (uint32_t material : scene.meshes[m].triangleMaterials)
      if (luminance(scene.materials[material].emission) > 0.0f) {
        emits[m] = true;
        break;
      }
  for (uint32_t instanceId = 0; instanceId < flat.instances.size(); ++instanceId) {
    const InstanceRecord& inst = flat.instances[instanceId];
    if (!emits[inst.meshId]) continue;
    const Mesh& mesh = scene.meshes[inst.meshId];
    // Kernel code takes a triangle's front from its object-space winding carried by the normal transform, which
    // a mirroring transform does not flip, while it reverses the world-space winding of the corners kept here.
    const float frontSign = inst.objectToWorld.determinant() < 0.0f ? -1.0f : 1.0f;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      const Material& m = scene.materials[mesh.triangleMaterials[t]];
      if (luminance(m.emission) <= 0.0f) continue;
      Vec3 p0 = inst.objectToWorld.point(mesh.positions[mesh.indices[3 * t]]);
      Vec3 p1 = inst.objectToWorld.point(mesh.positions[mesh.indices[3 * t + 1]]);
      Vec3 p2 = inst.objectToWorld.point(mesh.positions[mesh.indices[3 * t + 2]]);
      LightTriangle light{p0,         p1 - p0,     p2 - p0,  m.emission, 0.5f * length(cross(p1 - p0, p2 - p0)),
                          instanceId, uint32_t(t), frontSign};
      if (!(light.area > 0.0f)) continue;  // degenerate: can neither be sampled nor hit
      lights.push_back(light);
      candidates.push_back({&mesh, uint32_t(t)});
    }
  }
  const TexelArrays texels{flat.textures.data(), uint32_t(flat.textures.size()), flat.texelBytes.data(),
                           flat.texelFloats.data()};
  tbb::parallel_for(size_t(0), lights.size(), [&](size_t i) {
    const Mesh& mesh = *candidates[i].mesh;
    const uint32_t t = candidates[i].triangle;
    const Material& m = scene.materials[mesh.triangleMaterials[t]];
    Vec3 mean = m.emission;
    if (m.emissionTexture != kNoTexture) {
      Vec2 uv[3] = {};
      if (!mesh.uvs.empty())
        for (int k = 0; k < 3; ++k) uv[k] = mesh.uvs[mesh.indices[3 * t + k]];
      mean *= meanTextureOverTriangle(texels, m.emissionTexture, uv[0], uv[1], uv[2]);
    }
    lights[i].power = trianglePower(mean, lights[i].area);
  });
  double totalPower = 0.0;
  std::vector<double> powers;
  for (const LightTriangle& light : lights) {
    if (!(light.power > 0.0f)) continue;
    flat.lights.push_back(light);
    powers.push_back(light.power);
    totalPower += light.power;
  }
  const std::vector<PunctualLight> bounded(flat.punctualLights.begin(),
                                           flat.punctualLights.begin() + long(flat.boundedPunctualLightCount));
  for (const PunctualLight& light : bounded) {
    powers.push_back(punctualLightPower(light));
    totalPower += powers.back();
  }
  flat.lightCdf.assign(1, 0.0f);
  double running = 0.0;
  for (double p : powers) {
    running += p;
    flat.lightCdf.push_back(float(running / totalPower));
  }
  flat.inverseLightPower = 0.0f;
  if (!powers.empty()) {
    flat.lightCdf.back() = 1.0f;
    flat.inverseLightPower = float(1.0 / totalPower);
  }
  LightBvh bvh = buildLightBvh(flat.lights, bounded);
  flat.lightBvh = std::move(bvh.nodes);
  flat.lightBitTrails = std::move(bvh.bitTrails);
  setLightSelectProbabilities(flat);
}

// The scene's punctual lights that emit, the point and spot lights first (in their order), then the directional
// ones, as SceneView orders them.
void collectPunctualLights(const Scene& scene, FlatScene& flat) {
  flat.punctualLights.clear();
  for (const PunctualLight& light : scene.punctualLights)
    if (light.type != PunctualLightType::Directional && punctualLightPower(light) > 0.0f)
      flat.punctualLights.push_back(light);
  flat.boundedPunctualLightCount = uint32_t(flat.punctualLights.size());
  for (const PunctualLight& light : scene.punctualLights)
    if (light.type == PunctualLightType::Directional && luminance(light.intensity) > 0.0f)
      flat.punctualLights.push_back(light);
}

// Tangents are needed where a normal map or an anisotropic lobe must be oriented on the surface.
bool needsTangents(const Material& m) { return m.normalTexture != kNoTexture || isOrientedByTangent(m); }

// Per material, whether it or a material it may choose (through mixes: validation bounds their chains) needs
// tangents.
std::vector<bool> materialsNeedingTangents(const std::vector<Material>& materials) {
  std::vector<bool> needed(materials.size());
  for (size_t i = 0; i < materials.size(); ++i) needed[i] = needsTangents(materials[i]);
  for (uint32_t round = 0; round < kMaxMixDepth; ++round)
    for (size_t i = 0; i < materials.size(); ++i)
      if (materials[i].type == MaterialType::Mix)
        needed[i] = needed[materials[i].mixedMaterials[0]] || needed[materials[i].mixedMaterials[1]];
  return needed;
}

bool needsTangents(const std::vector<bool>& materialsNeeding, const Mesh& mesh) {
  if (mesh.uvs.empty()) return false;
  for (uint32_t id : mesh.triangleMaterials)
    if (materialsNeeding[id]) return true;
  return false;
}

bool anyCutouts(const std::vector<Material>& materials) {
  for (const Material& m : materials)
    if (canPassThrough(m)) return true;
  return false;
}

// Each texture's levels back to back in the array of its format: the finest, then the pyramid (kernel/texture.h).
// Places are assigned first, then the textures are copied and their pyramids built in parallel, straight into
// the arrays. A texture whose texels do not fill its size keeps just the one level.
void packTextures(const Scene& scene, FlatScene& flat) {
  std::vector<bool> pyramids;
  size_t bytes = 0, floats = 0;
  for (const Texture& t : scene.textures) {
    TextureView view;
    view.width = t.width;
    view.height = t.height;
    view.channels = t.channels;
    view.srgb = t.srgb ? 1u : 0u;
    view.wrapU = t.wrapU;
    view.wrapV = t.wrapV;
    const bool isBytes = !t.bytes.empty();
    const size_t texels = size_t(t.width) * t.height * t.channels;
    const bool pyramid = texels > 0 && (isBytes ? t.bytes.size() : t.floats.size()) == texels;
    view.levels = pyramid ? fullMipLevelCount(t.width, t.height) : 1u;
    const size_t values = (isBytes ? t.bytes.size() : t.floats.size()) +
                          (pyramid ? coarserMipLevelsSize(t.width, t.height, t.channels) : 0);
    view.format = isBytes ? TexelFormat::Unorm8 : TexelFormat::Float32;
    view.offset = isBytes ? bytes : floats;
    (isBytes ? bytes : floats) += values;
    flat.textures.push_back(view);
    pyramids.push_back(pyramid);
  }
  flat.texelBytes.resize(bytes);
  flat.texelFloats.resize(floats);
  tbb::parallel_for(size_t(0), scene.textures.size(), [&](size_t i) {
    const Texture& t = scene.textures[i];
    const TextureView& view = flat.textures[i];
    if (view.format == TexelFormat::Unorm8) {
      uint8_t* out = std::copy(t.bytes.begin(), t.bytes.end(), flat.texelBytes.data() + view.offset);
      if (pyramids[i]) writeCoarserMipLevels(t.bytes.data(), t.width, t.height, t.channels, t.srgb, out);
    } else {
      float* out = std::copy(t.floats.begin(), t.floats.end(), flat.texelFloats.data() + view.offset);
      if (pyramids[i]) writeCoarserMipLevels(t.floats.data(), t.width, t.height, t.channels, out);
    }
  });
}

// A mesh's curves after the scene's others; only ribbons carry normals.
void appendCurves(const Mesh& mesh, MeshRecord& record, FlatScene& flat) {
  record.firstCurveVertex = uint32_t(flat.curveVertices.size());
  record.firstCurveNormal = uint32_t(flat.curveNormals.size());
  record.firstCurveSegment = uint32_t(flat.curveSegments.size());
  record.curveSegmentCount = uint32_t(mesh.curveSegments.size());
  record.hasCurveNormals = mesh.curveNormals.empty() ? 0u : 1u;
  flat.curveVertices.insert(flat.curveVertices.end(), mesh.curveVertices.begin(), mesh.curveVertices.end());
  flat.curveNormals.insert(flat.curveNormals.end(), mesh.curveNormals.begin(), mesh.curveNormals.end());
  flat.curveSegments.insert(flat.curveSegments.end(), mesh.curveSegments.begin(), mesh.curveSegments.end());
}

void buildEnvironment(const Environment& env, FlatScene& flat) {
  EnvironmentView& view = flat.environment;
  // Reduced exactly first: a rotation near the largest float would overflow to infinity in radians.
  float angle = std::fmod(env.rotationDegrees, 360.0f) * kPi / 180.0f;
  view.rotationCos = std::cos(angle);
  view.rotationSin = std::sin(angle);
  view.visibleToCamera = env.visibleToCamera ? 1u : 0u;
  if (!env.hasMap()) {
    view.scale = env.radiance * env.intensity;
    return;
  }
  view.scale = Vec3{1, 1, 1} * env.intensity;
  view.width = env.map.width;
  view.height = env.map.height;
  flat.environmentTexels = environmentTexels(env.map);
  flat.environmentDistribution = EnvironmentDistribution::build(flat.environmentTexels, view.width, view.height);
  view.funcAverage = flat.environmentDistribution.funcAverage;
}

}  // namespace

FlatScene FlatScene::build(const Scene& scene) {
  validateScene(scene);
  FlatScene flat;
  flat.materials = scene.materials;
  buildEnvironment(scene.environment, flat);
  const std::vector<bool> materialsNeeding = materialsNeedingTangents(scene.materials);
  const bool anyColors =
      std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return !m.colors.empty(); });
  for (const Mesh& mesh : scene.meshes) {
    MeshRecord record;
    record.firstVertex = uint32_t(flat.positions.size());
    record.vertexCount = uint32_t(mesh.positions.size());
    record.firstTriangle = uint32_t(flat.triangleMaterials.size());
    record.triangleCount = uint32_t(mesh.triangleCount());
    record.hasNormals = mesh.normals.empty() ? 0u : 1u;
    record.hasUvs = mesh.uvs.empty() ? 0u : 1u;
    flat.positions.insert(flat.positions.end(), mesh.positions.begin(), mesh.positions.end());
    if (mesh.normals.empty())
      flat.normals.resize(flat.positions.size());
    else
      flat.normals.insert(flat.normals.end(), mesh.normals.begin(), mesh.normals.end());
    if (mesh.uvs.empty())
      flat.uvs.resize(flat.positions.size());
    else
      flat.uvs.insert(flat.uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
    std::vector<Vec4> generated;
    const std::vector<Vec4>* meshTangents = &mesh.tangents;
    if (mesh.tangents.empty() && needsTangents(materialsNeeding, mesh))
      meshTangents = &(generated = generateTangents(mesh));
    record.hasTangents = meshTangents->empty() ? 0u : 1u;
    if (meshTangents->empty())
      flat.tangents.resize(flat.positions.size());
    else
      flat.tangents.insert(flat.tangents.end(), meshTangents->begin(), meshTangents->end());
    record.hasColors = mesh.colors.empty() ? 0u : 1u;
    if (anyColors) {
      if (mesh.colors.empty())
        flat.colors.resize(flat.positions.size(), Vec3{1, 1, 1});
      else
        flat.colors.insert(flat.colors.end(), mesh.colors.begin(), mesh.colors.end());
    }
    flat.meshes.push_back(record);
    flat.indices.insert(flat.indices.end(), mesh.indices.begin(), mesh.indices.end());
    flat.triangleMaterials.insert(flat.triangleMaterials.end(), mesh.triangleMaterials.begin(),
                                  mesh.triangleMaterials.end());
    appendCurves(mesh, flat.meshes.back(), flat);
  }
  for (const Instance& inst : scene.instances)
    flat.instances.push_back({inst.meshId, inst.objectToWorld, normalTransform(inst.objectToWorld), inst.media});
  flat.media = scene.media;
  flat.mediumGrids = scene.mediumGrids;
  flat.mediumGridValues = scene.mediumGridValues;
  flat.cameraMedium = scene.cameraMedium;
  collectPunctualLights(scene, flat);
  packTextures(scene, flat);
  buildLightTable(scene, flat);
  flat.hasCutouts = anyCutouts(flat.materials);
  return flat;
}

bool FlatScene::replaceMaterials(const std::vector<Material>& replacement) {
  if (replacement.size() != materials.size()) return false;
  for (size_t i = 0; i < materials.size(); ++i) {
    const Material &was = materials[i], &is = replacement[i];
    if (is.emission.x != was.emission.x || is.emission.y != was.emission.y || is.emission.z != was.emission.z)
      return false;
    if (needsTangents(is) && !needsTangents(was)) return false;
  }
  materials = replacement;
  hasCutouts = anyCutouts(materials);
  return true;
}

bool FlatScene::replaceInstanceTransforms(const Scene& scene) {
  if (scene.instances.size() != instances.size()) return false;
  for (size_t i = 0; i < instances.size(); ++i)
    if (scene.instances[i].meshId != instances[i].meshId) return false;
  for (size_t i = 0; i < instances.size(); ++i) {
    instances[i].objectToWorld = scene.instances[i].objectToWorld;
    instances[i].normalToWorld = normalTransform(scene.instances[i].objectToWorld);
  }
  collectPunctualLights(scene, *this);
  lights.clear();
  lightCdf.clear();
  buildLightTable(scene, *this);
  return true;
}

bool FlatScene::replaceMeshVertices(const Scene& scene, const std::vector<uint32_t>& deformed) {
  if (scene.meshes.size() != meshes.size()) return false;
  for (uint32_t m : deformed)
    if (m >= meshes.size() || scene.meshes[m].positions.size() != meshes[m].vertexCount ||
        scene.meshes[m].triangleCount() != meshes[m].triangleCount ||
        scene.meshes[m].normals.empty() == bool(meshes[m].hasNormals))
      return false;
  for (uint32_t m : deformed) {
    const Mesh& mesh = scene.meshes[m];
    const MeshRecord& record = meshes[m];
    std::copy(mesh.positions.begin(), mesh.positions.end(), positions.begin() + record.firstVertex);
    std::copy(mesh.normals.begin(), mesh.normals.end(), normals.begin() + record.firstVertex);
    if (!record.hasTangents) continue;
    const std::vector<Vec4> generated = mesh.tangents.empty() ? generateTangents(mesh) : std::vector<Vec4>{};
    const std::vector<Vec4>& meshTangents = mesh.tangents.empty() ? generated : mesh.tangents;
    std::copy(meshTangents.begin(), meshTangents.end(), tangents.begin() + record.firstVertex);
  }
  return true;
}

void FlatScene::replaceEnvironment(const Environment& replacement) {
  environment = EnvironmentView{};
  environmentTexels.clear();
  environmentDistribution = EnvironmentDistribution{};
  buildEnvironment(replacement, *this);
  setLightSelectProbabilities(*this);
}

SceneView FlatScene::hostView() const {
  SceneView v;
#define CANDELA_POINT_AT_HOST_ARRAY(Type, member, upload, count, description) \
  v.member = member.empty() ? nullptr : member.data();                        \
  setSceneArrayCount(v, CANDELA_SCENE_ARRAY_COUNT_FIELD(count), member.size());
  CANDELA_SCENE_ARRAYS(CANDELA_POINT_AT_HOST_ARRAY)
#undef CANDELA_POINT_AT_HOST_ARRAY
  v.texels = {textures.data(), uint32_t(textures.size()), texelBytes.data(), texelFloats.data()};
  v.hasCutouts = hasCutouts ? 1u : 0u;
  v.boundedPunctualLightCount = boundedPunctualLightCount;
  v.inverseLightPower = inverseLightPower;
  v.environmentSelectProbability = environmentSelectProbability;
  v.directionalSelectProbability = directionalSelectProbability;
  v.boundedSelectProbability = boundedSelectProbability;
  v.environment = environment;
  v.cameraMedium = cameraMedium;
  if (!environmentTexels.empty()) {
    v.environment.texels = environmentTexels.data();
    environmentDistribution.attach(v.environment);
  }
  return v;
}

}  // namespace candela
