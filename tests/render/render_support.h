#pragma once
#include <cmath>

#include "backends/cpu/cpu_backend.h"
#include "scene/mesh_builders.h"

namespace candela::test {

struct PixelStatistics {
  double mean = 0.0;
  double standardError = 0.0;  // of the mean, from the spread of the pixels (independent estimates)
  double min = 0.0, max = 0.0;
};

inline PixelStatistics luminanceStatistics(const Image& image) {
  PixelStatistics s;
  double sum = 0.0, sum2 = 0.0;
  s.min = 1e30;
  s.max = -1e30;
  for (const Vec3& p : image.pixels) {
    double l = luminance(p);
    sum += l;
    sum2 += l * l;
    s.min = std::fmin(s.min, l);
    s.max = std::fmax(s.max, l);
  }
  double n = double(image.pixels.size());
  s.mean = sum / n;
  s.standardError = std::sqrt(std::fmax(0.0, sum2 / n - s.mean * s.mean) / n);
  return s;
}

inline Image renderCpu(const Scene& scene, RenderSettings settings, uint32_t spp) {
  CpuBackend backend;
  backend.setScene(scene);
  backend.setSettings(settings);
  backend.setCamera(scene.camera.toCamera(float(settings.width) / float(settings.height)));
  backend.render(spp);
  return backend.readImage();
}

// A unit sphere of `material` under a uniform environment of radiance 1, seen head-on through a 1-degree field
// of view: every pixel looks at the surface within 2 degrees of normal incidence.
inline Scene furnaceSphere(const Material& material) {
  Scene scene;
  scene.name = "furnace-sphere";
  scene.materials = {material};
  scene.meshes.push_back(makeUvSphere(1.0f, 256, 128, 0, /*inward=*/false));
  scene.instances.push_back({0, Affine3x4{}});
  scene.environment.radiance = {1, 1, 1};
  scene.camera.eye = {0, 0, -4};
  scene.camera.target = {0, 0, 0};
  scene.camera.verticalFovDegrees = 1.0f;
  return scene;
}

}  // namespace candela::test
