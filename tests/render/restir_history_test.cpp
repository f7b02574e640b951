// ReSTIR's temporal reuse across a camera move (kernel/restir/restir_passes.h, temporalHistoryPixel): a camera that
// slides sideways past a table top uncovers floor it hid. A pixel that sees that floor now projects onto a pixel that
// saw the box before; it must not reuse that pixel's reservoir (ghosting). Every history a pixel does reuse lies
// within the depth test's bound of the pixel's own point.
#include <gtest/gtest.h>

#include "backends/cpu/embree_scene.h"
#include "backends/cpu/embree_tracer.h"
#include "backends/cpu/host_restir_buffers.h"
#include "kernel/restir/restir_passes.h"
#include "scene/flat_scene.h"
#include "scene/mesh_builders.h"

namespace candela::test {
namespace {

Scene tableOverFloor() {
  Scene scene;
  scene.materials = {diffuseMaterial({0.5f, 0.5f, 0.5f}), diffuseMaterial({0, 0, 0}, {4, 4, 4})};
  Mesh mesh;
  appendQuad(mesh, {-20, 0, -20}, {20, 0, -20}, {20, 0, 20}, {-20, 0, 20}, {0, 1, 0}, 0);
  // A table top: it faces up as the floor does, so only the depth test tells the two apart.
  appendQuad(mesh, {-1.5f, 2, -1.5f}, {1.5f, 2, -1.5f}, {1.5f, 2, 1.5f}, {-1.5f, 2, 1.5f}, {0, 1, 0}, 0);
  appendQuad(mesh, {-2, 8, -2}, {2, 8, -2}, {2, 8, 2}, {-2, 8, 2}, {0, -1, 0}, 1);
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, Affine3x4{}});
  return scene;
}

struct Frame {
  std::vector<PrimarySurface> surfaces;
  std::vector<Vec3> points;
};

TEST(RestirHistory, CameraMovingPastAnOccluderReusesNoHistoryAcrossTheDisocclusion) {
  const Scene scene = tableOverFloor();
  const FlatScene flat = FlatScene::build(scene);
  EmbreeScene embree;
  embree.build(flat);
  const SceneView view = flat.hostView();
  const EmbreeTracer tracer(embree.topLevel(), view);
  RenderSettings settings;
  settings.width = 96;
  settings.height = 64;
  settings.restir = RestirMode::Di;
  HostRestirBuffers buffers;
  buffers.reset(settings.width, settings.height);

  const size_t pixels = size_t(settings.width) * settings.height;
  auto render = [&](const Camera& camera, uint32_t sample) {
    const RestirView restir = buffers.view(true);
    for (uint32_t y = 0; y < settings.height; ++y)
      for (uint32_t x = 0; x < settings.width; ++x)
        restirPrimaryPass(view, tracer, camera, settings, restir, x, y, sample);
    Frame frame;
    frame.surfaces.assign(restir.surfaces, restir.surfaces + pixels);
    for (const PrimarySurface& s : frame.surfaces) frame.points.push_back(s.ray.origin + s.ray.direction * s.hit.t);
    return frame;
  };
  const float aspect = float(settings.width) / float(settings.height);
  const Camera before = Camera::lookAt({0, 6, 6}, {0, 0, 0}, {0, 1, 0}, 50.0f, aspect);
  const Camera after = Camera::lookAt({0.8f, 6, 6}, {0.8f, 0, 0}, {0, 1, 0}, 50.0f, aspect);
  const Frame first = render(before, 0);
  buffers.endSample(before);
  const RestirView restir = buffers.view(true);
  const Frame second = render(after, 1);

  size_t reused = 0, uncovered = 0, uncoveredRejected = 0;
  for (size_t i = 0; i < pixels; ++i) {
    const PrimarySurface& now = second.surfaces[i];
    if (!now.found) continue;
    const Vec3 p = second.points[i];
    uint32_t column, row;
    if (!projectToPixel(before, settings.width, settings.height, p, column, row)) continue;
    const size_t projected = size_t(row) * settings.width + column;
    const float depth = length(p - first.surfaces[projected].ray.origin);
    // Where the pixel that saw this point before saw something much nearer, the point was hidden then.
    const bool wasHidden = first.surfaces[projected].found &&
                           first.surfaces[projected].hit.t < (1.0f - 2.0f * kRestirDepthSimilarity) * depth;
    const uint32_t history = temporalHistoryPixel(settings, restir, now, p);
    if (wasHidden) {
      ++uncovered;
      if (history == kNoHistory) ++uncoveredRejected;
    }
    if (history == kNoHistory) continue;
    ++reused;
    // Reused history lies on the same surface, within the depth test's bound.
    EXPECT_LE(length(first.points[history] - p), 2.0f * kRestirDepthSimilarity * depth) << "pixel " << i;
  }
  // The move uncovers floor (so the test can fail), and every uncovered pixel drops its history...
  EXPECT_GT(uncovered, 20u);
  EXPECT_EQ(uncoveredRejected, uncovered);
  // ...while most of the image keeps it.
  EXPECT_GT(reused, pixels / 2);
}

}  // namespace
}  // namespace candela::test
