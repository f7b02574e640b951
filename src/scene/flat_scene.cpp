#include "scene/flat_scene.h"

#include <cmath>

#include "scene/transform.h"

namespace candela {

namespace {

void buildLightTable(const Scene& scene, FlatScene& flat) {
  double totalPower = 0.0;
  std::vector<double> powers;
  for (const InstanceRecord& inst : flat.instances) {
    const Mesh& mesh = scene.meshes[inst.meshId];
    // Kernel code takes a triangle's front from its object-space winding carried by the normal transform, which
    // a mirroring transform does not flip; the world-space corners here must be wound the same way.
    const float* a = inst.objectToWorld.m;
    float det = a[0] * (a[5] * a[10] - a[6] * a[9]) - a[1] * (a[4] * a[10] - a[6] * a[8]) +
                a[2] * (a[4] * a[9] - a[5] * a[8]);
    const int second = det < 0.0f ? 2 : 1, third = det < 0.0f ? 1 : 2;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      const Material& m = scene.materials[mesh.triangleMaterials[t]];
      if (luminance(m.emission) <= 0.0f) continue;
      Vec3 p0 = inst.objectToWorld.point(mesh.positions[mesh.indices[3 * t]]);
      Vec3 p1 = inst.objectToWorld.point(mesh.positions[mesh.indices[3 * t + second]]);
      Vec3 p2 = inst.objectToWorld.point(mesh.positions[mesh.indices[3 * t + third]]);
      LightTriangle light{p0, p1 - p0, p2 - p0, m.emission, 0.5f * length(cross(p1 - p0, p2 - p0))};
      if (!(light.area > 0.0f)) continue;  // degenerate: can neither be sampled nor hit
      double power = double(light.area) * kPi * luminance(m.emission);
      flat.lights.push_back(light);
      powers.push_back(power);
      totalPower += power;
    }
  }
  flat.lightCdf.assign(1, 0.0f);
  double running = 0.0;
  for (double p : powers) {
    running += p;
    flat.lightCdf.push_back(float(running / totalPower));
  }
  if (!flat.lights.empty()) {
    flat.lightCdf.back() = 1.0f;
    flat.lightAreaPdfScale = float(kPi / totalPower);
  }
  bool environmentEmits = flat.environmentTexels.empty() ? !isBlack(flat.environment.scale)
                                                         : flat.environmentDistribution.funcAverage > 0.0f &&
                                                               !isBlack(flat.environment.scale);
  flat.environmentSelectProbability = environmentEmits ? (flat.lights.empty() ? 1.0f : 0.5f) : 0.0f;
}

void buildEnvironment(const Environment& env, FlatScene& flat) {
  EnvironmentView& view = flat.environment;
  float angle = env.rotationDegrees * kPi / 180.0f;
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
  for (const Mesh& mesh : scene.meshes) {
    MeshRecord record;
    record.firstVertex = uint32_t(flat.positions.size());
    record.vertexCount = uint32_t(mesh.positions.size());
    record.firstTriangle = uint32_t(flat.triangleMaterials.size());
    record.triangleCount = uint32_t(mesh.triangleCount());
    record.hasNormals = mesh.normals.empty() ? 0u : 1u;
    flat.meshes.push_back(record);
    flat.positions.insert(flat.positions.end(), mesh.positions.begin(), mesh.positions.end());
    if (mesh.normals.empty())
      flat.normals.resize(flat.positions.size());
    else
      flat.normals.insert(flat.normals.end(), mesh.normals.begin(), mesh.normals.end());
    flat.indices.insert(flat.indices.end(), mesh.indices.begin(), mesh.indices.end());
    flat.triangleMaterials.insert(flat.triangleMaterials.end(), mesh.triangleMaterials.begin(),
                                  mesh.triangleMaterials.end());
  }
  for (const Instance& inst : scene.instances)
    flat.instances.push_back({inst.meshId, inst.objectToWorld, normalTransform(inst.objectToWorld)});
  buildLightTable(scene, flat);
  return flat;
}

SceneView FlatScene::hostView() const {
  SceneView v;
  v.positions = positions.data();
  v.normals = normals.data();
  v.indices = indices.data();
  v.triangleMaterials = triangleMaterials.data();
  v.meshes = meshes.data();
  v.instances = instances.data();
  v.materials = materials.data();
  v.lights = lights.data();
  v.lightCdf = lightCdf.data();
  v.lightCount = uint32_t(lights.size());
  v.lightAreaPdfScale = lightAreaPdfScale;
  v.environmentSelectProbability = environmentSelectProbability;
  v.environment = environment;
  if (!environmentTexels.empty()) {
    v.environment.texels = environmentTexels.data();
    v.environment.func = environmentDistribution.func.data();
    v.environment.conditionalCdf = environmentDistribution.conditionalCdf.data();
    v.environment.marginalCdf = environmentDistribution.marginalCdf.data();
  }
  return v;
}

}  // namespace candela
