#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "image/texture.h"
#include "kernel/camera.h"
#include "kernel/material.h"
#include "kernel/scene_view.h"
#include "kernel/texture.h"
#include "scene/animation.h"

namespace candela {

struct Mesh {
  std::string name;
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;      // empty, or one per position
  std::vector<Vec2> uvs;          // empty, or one per position; v runs down the image rows (glTF's convention)
  std::vector<Vec4> tangents;     // empty, or one per position: unit tangent along +u and the bitangent sign
  std::vector<Vec3> colors;       // empty, or one per position: linear RGB that multiplies the base colour
  std::vector<uint32_t> indices;  // 3 per triangle
  std::vector<uint32_t> triangleMaterials;  // one per triangle
  // Or curves instead of triangles (kernel/curve.h), all of one type: 4 control points (xyz, radius) per segment,
  // the ribbons' normals (empty, or one per control point) and the segments.
  std::vector<Vec4> curveVertices;
  std::vector<Vec3> curveNormals;
  std::vector<CurveSegment> curveSegments;

  size_t triangleCount() const { return indices.size() / 3; }
};

struct Instance {
  uint32_t meshId = 0;
  Affine3x4 objectToWorld;
  MediumInterface media = {};  // into Scene::media; none on either side by default
};

// How a camera projects the scene onto the image. A byte, so that any value read from a cache file is defined.
enum class Projection : uint32_t { Perspective, Orthographic };  // 32 bits: CameraDescription has no padding

struct CameraDescription {
  Vec3 eye{0, 0, 0};
  Vec3 target{0, 0, 1};
  Vec3 up{0, 1, 0};
  float verticalFovDegrees = 40.0f;
  float apertureRadius = 0.0f;  // 0: pinhole
  float focusDistance = 0.0f;   // 0: the distance from eye to target
  // Where the image's centre lies off the view axis, in units of half the image's height (a shifted lens or
  // pbrt's off-centre screen window); 0 0 centres it.
  Vec2 imageShift{0, 0};
  float orthographicHalfHeight = 1.0f;  // orthographic: half the image's height in world units
  Projection projection = Projection::Perspective;

  Camera toCamera(float aspect) const {
    Camera c = Camera::lookAt(eye, target, up, verticalFovDegrees, aspect);
    const bool orthographic = projection == Projection::Orthographic;
    if (orthographic) {
      // lookAt scaled right and up to the image plane at distance 1; here they span the image itself.
      c.right = normalize(c.right) * (orthographicHalfHeight * aspect);
      c.up = normalize(c.up) * orthographicHalfHeight;
      c.orthographic = true;
    }
    const Vec3 shift = normalize(c.right) * (imageShift.x * length(c.up)) + c.up * imageShift.y;
    if (orthographic)
      c.position = c.position + shift;
    else
      c.forward = c.forward + shift;
    c.lensRadius = apertureRadius;
    c.focusDistance = focusDistance > 0.0f ? focusDistance : length(target - eye);
    return c;
  }
};

// A camera an input file defines, under the name it gives (or a description of where it is).
struct NamedCamera {
  std::string name;
  CameraDescription description;
};

// Light from infinitely far away: a constant `radiance`, or an equirectangular `map` (float RGB, top row the
// zenith, see kernel/environment.h for the orientation) scaled by `intensity` and turned about +Y.
struct Environment {
  Vec3 radiance{0, 0, 0};  // used when `map` is empty
  Texture map;
  float intensity = 1.0f;
  float rotationDegrees = 0.0f;
  bool visibleToCamera = true;

  bool hasMap() const { return map.width > 0 && map.height > 0; }
};

// Render settings a scene file asks for; the command line overrides them.
struct RenderHints {
  std::optional<uint32_t> width, height, samplesPerPixel, maxDepth;
};

// A scene as loaders produce it and backends consume it.
struct Scene {
  std::string name;
  std::vector<Mesh> meshes;
  std::vector<Instance> instances;
  std::vector<Material> materials;
  std::vector<std::string> materialNames;  // as the input file names them, one per material (may be empty)
  std::vector<Texture> textures;
  Environment environment;
  std::vector<PunctualLight> punctualLights;  // in world space
  std::vector<Medium> media;                  // participating media
  std::vector<MediumGrid> mediumGrids;        // the grids of heterogeneous media (kernel/media/medium_grid.h)
  std::vector<float> mediumGridValues;        // their samples and majorant grids
  CameraDescription camera;
  uint32_t cameraMedium = kNoMedium;  // the medium the camera is in, an index into `media`
  RenderHints renderHints;
  bool cameraMissing = false;        // the input had no camera: `camera` is to be framed around the scene's bounds
  std::vector<NamedCamera> cameras;  // every camera the input defines, in order
  int32_t cameraIndex = -1;          // the entry of `cameras` that `camera` is (and moves with), or -1
  // Keyframed node transforms (glTF animations); `instances`, `cameras` and `punctualLights` hold the rest pose.
  // See animation_player.h.
  SceneAnimation animation;
  // The files the scene was read from: the model, its material libraries, buffers and images (what the scene
  // cache checks for changes).
  std::vector<std::string> inputFiles;

  size_t triangleCount() const;  // over instances
};

// Bytes held by the scene's arrays (meshes, materials, textures, environment map).
size_t sceneMemoryBytes(const Scene& scene);

// Checks the invariants backends rely on (index ranges, material ids, finite numbers); throws
// std::runtime_error naming the first problem.
void validateScene(const Scene& scene);

}  // namespace candela
