#pragma once
// Shared by the denoising tests: renders with AOVs on the CPU backend, the error metric, test scenes.
#include <utility>

#include "backends/cpu/cpu_backend.h"
#include "scene/mesh_builders.h"

namespace candela::test {

struct RenderWithAovs {
  Image image;
  AovImages aovs;
};

// A CPU render with AOVs, read as it accumulates.
class ProgressiveRender {
 public:
  ProgressiveRender(const Scene& scene, uint32_t width, uint32_t height, uint32_t seed,
                    SamplerKind sampler = SamplerKind::Sobol) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.seed = seed;
    settings.sampler = sampler;
    backend_.setScene(scene);
    backend_.setSettings(settings);
    backend_.setAovsEnabled(true);
    backend_.setCamera(scene.camera.toCamera(float(width) / float(height)));
  }
  // Renders until every pixel has `spp` samples (no fewer than it has already) and reads the image.
  RenderWithAovs renderUpTo(uint32_t spp) {
    if (spp > backend_.accumulatedSamples()) backend_.render(spp - backend_.accumulatedSamples());
    return {backend_.readImage(), backend_.readAovs()};
  }

 private:
  CpuBackend backend_;
};

inline RenderWithAovs renderWithAovs(const Scene& scene, uint32_t width, uint32_t height, uint32_t spp, uint32_t seed) {
  return ProgressiveRender(scene, width, height, seed).renderUpTo(spp);
}

// Mean over pixels and channels of (x - ref)^2 / (ref^2 + 1e-2).
inline double relativeMse(const Image& x, const Image& reference) {
  double sum = 0.0;
  for (size_t i = 0; i < x.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(x.pixels[i][c]) - reference.pixels[i][c];
      sum += d * d / (double(reference.pixels[i][c]) * reference.pixels[i][c] + 1e-2);
    }
  return sum / double(3 * x.pixels.size());
}

inline Material diffuseMaterial(Vec3 albedo) {
  Material m;
  m.baseColor = albedo;
  return m;
}

// A square diffuse card facing the camera head-on under a uniform environment of radiance 1, its left half of
// albedo `left`, its right half of albedo `right`, the edge along the image's middle column. The card sees
// only the sky, so its radiance is exactly its albedo. It fills the image.
inline Scene albedoEdgeCard(float left, float right) {
  Scene scene;
  scene.name = "albedo-edge";
  scene.materials = {diffuseMaterial({left, left, left}), diffuseMaterial({right, right, right})};
  Mesh mesh;
  // Seen from z = -4 looking along +z, +x is on the image's left (the camera's right is -x for a y-up view).
  appendQuad(mesh, {0, -2, 0}, {2, -2, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, -1}, 0);
  appendQuad(mesh, {-2, -2, 0}, {0, -2, 0}, {0, 2, 0}, {-2, 2, 0}, {0, 0, -1}, 1);
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back({0, Affine3x4{}});
  scene.environment.radiance = {1, 1, 1};
  scene.camera.eye = {0, 0, -4};
  scene.camera.target = {0, 0, 0};
  scene.camera.verticalFovDegrees = 40.0f;
  return scene;
}

}  // namespace candela::test
