#pragma once
// Scenes with participating media whose answers are known, for tests/media.
#include <sstream>
#include <string>

#include "scene/mesh_builders.h"
#include "scene/scene.h"

namespace candela::test {

// pbrt's `interface` material as its loader makes it: it only bounds media.
inline Material interfaceMaterial() {
  Material m;
  m.interfaceOnly = 1;
  m.alphaMode = AlphaMode::Mask;
  m.opacity = 0.0f;
  return m;
}

// The six faces of the box [lo, hi], wound outwards.
inline void appendBox(Mesh& mesh, Vec3 lo, Vec3 hi, uint32_t materialId) {
  const Vec3 c = (lo + hi) * 0.5f;
  auto face = [&](Vec3 a, Vec3 b, Vec3 d, Vec3 e) {
    const Vec3 centre = (a + b + d + e) * 0.25f;
    appendQuad(mesh, a, b, d, e, centre + (centre - c), materialId);
  };
  face({lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z});
  face({lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z});
  face({lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {lo.x, lo.y, hi.z});
  face({hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z});
  face({lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z});
  face({lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z});
}

// The box [-50, 50] x [-50, 50] x [0, depth] as a pbrt trianglemesh, wound outwards.
inline std::string pbrtBox(float depth) {
  Mesh box;
  appendBox(box, {-50, -50, 0}, {50, 50, depth}, 0);
  std::ostringstream text;
  text << "Shape \"trianglemesh\" \"point3 P\" [";
  for (Vec3 p : box.positions) text << ' ' << p.x << ' ' << p.y << ' ' << p.z;
  text << " ] \"integer indices\" [";
  for (uint32_t i : box.indices) text << ' ' << i;
  text << " ]\n";
  return text.str();
}

// A 16 x 16 orthographic view down the z axis under a white environment, up to WorldBegin and the light.
constexpr const char* kOrthographicView =
    "LookAt 0 0 -2  0 0 0  0 1 0\nCamera \"orthographic\"\nFilm \"rgb\" \"integer xresolution\" 16 "
    "\"integer yresolution\" 16\nWorldBegin\nLightSource \"infinite\" \"rgb L\" [1 1 1]\n";

// An orthographic camera looks along +z through a slab, `depth` thick between z = 0 and z = depth and far wider
// than the image, of `medium`, bounded by an interface box, at an environment of radiance 1 behind it. Every
// camera ray crosses the slab straight: each pixel is exp(-sigma_t depth) per channel, what is not absorbed or
// scattered out, plus what the slab scatters towards the camera (none where sigma_s is 0).
inline Scene makeMediumSlab(const Medium& medium, float depth) {
  Scene scene;
  scene.name = "medium-slab";
  scene.materials = {interfaceMaterial()};
  scene.meshes.emplace_back();
  appendBox(scene.meshes[0], {-50, -50, 0}, {50, 50, depth}, 0);
  scene.media = {medium};
  scene.instances.push_back({0, Affine3x4{}, {0, kNoMedium}});
  scene.environment.radiance = {1, 1, 1};
  scene.camera.projection = Projection::Orthographic;
  scene.camera.orthographicHalfHeight = 1.0f;
  scene.camera.eye = {0, 0, -2};
  scene.camera.target = {0, 0, 0};
  return scene;
}

// A closed sphere of radius 1 whose inner side is black and emits 1, filled with `medium`, the camera at its
// centre in the medium. Where the medium's albedo is 1 (sigma_a 0), or where it emits Le = 1 as well, the
// radiance is 1 in every direction at every point: what a ray loses to the medium the medium gives back.
inline Scene makeMediumFurnace(const Medium& medium) {
  Scene scene;
  scene.name = "medium-furnace";
  scene.materials = {diffuseMaterial({0, 0, 0}, {1, 1, 1})};
  scene.meshes.push_back(makeUvSphere(1.0f, 48, 24, 0, /*inward=*/true));
  scene.meshes.back().normals.clear();
  scene.instances.push_back({0, Affine3x4{}});
  scene.media = {medium};
  scene.cameraMedium = 0;
  scene.camera.eye = {0, 0, 0};
  scene.camera.target = {0, 0, 1};
  scene.camera.verticalFovDegrees = 90.0f;
  return scene;
}

}  // namespace candela::test
