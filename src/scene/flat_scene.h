#pragma once
#include <vector>

#include "kernel/scene_view.h"
#include "scene/environment_distribution.h"
#include "scene/scene.h"

namespace candela {

// A Scene packed into the flat arrays kernel code reads, with the light table and the light BVH built. Backends either
// point a SceneView at these arrays (CPU) or copy them to device memory (GPU).
struct FlatScene {
  // The arrays of kernel/scene_arrays.h, in its order. The lights are as SceneView describes them: the point and
  // spot lights first in punctualLights, lights that emit nothing left out.
#define CANDELA_FLAT_SCENE_ARRAY(Type, member, upload, count, description) std::vector<Type> member;
  CANDELA_SCENE_ARRAYS(CANDELA_FLAT_SCENE_ARRAY)
#undef CANDELA_FLAT_SCENE_ARRAY
  // The textures, left out of the list (kernel/scene_arrays.h says why), like the environment below.
  std::vector<TextureView> textures;
  std::vector<uint8_t> texelBytes;  // every 8-bit texture back to back, each with its mip levels
  std::vector<float> texelFloats;   // every float texture back to back, each with its mip levels
  bool hasCutouts = false;
  uint32_t cameraMedium = kNoMedium;       // into `media`
  uint32_t boundedPunctualLightCount = 0;  // the point and spot lights at the front of punctualLights
  float inverseLightPower = 0.0f;
  float environmentSelectProbability = 0.0f;
  float directionalSelectProbability = 0.0f;
  float boundedSelectProbability = 0.0f;
  // The environment's parameters; its pointers are set by hostView() (or by a backend, to device copies of
  // the arrays below).
  EnvironmentView environment;
  std::vector<Vec3> environmentTexels;  // empty for a constant environment
  EnvironmentDistribution environmentDistribution;

  static FlatScene build(const Scene& scene);

  // Replaces the materials, and the cut-out flag that follows from them, when nothing else was built from
  // what changed: the same count, the same emission (the light table) and no material newly needing tangents.
  // Returns false, changing nothing, when the scene must be built again instead.
  bool replaceMaterials(const std::vector<Material>& replacement);
  // Takes the instance transforms and punctual lights of `scene`, the scene this was built from with only those
  // changed, and builds the light table again. Returns false, changing nothing, when the instances differ in
  // number or meshes.
  bool replaceInstanceTransforms(const Scene& scene);
  // Takes the vertices (positions, normals and tangents) of the meshes `deformed` of `scene`, the scene this was
  // built from with only those (and what replaceInstanceTransforms takes) changed; tangents this built are built
  // again. Returns false, changing nothing, when a mesh's vertex or triangle count differs. Call
  // replaceInstanceTransforms afterwards: the light table depends on the vertices.
  bool replaceMeshVertices(const Scene& scene, const std::vector<uint32_t>& deformed);
  // Rebuilds the environment's parameters, texels and sampling distribution, and how often light sampling
  // picks it; the geometry and the light table stay.
  void replaceEnvironment(const Environment& replacement);

  // A view whose pointers refer to this object's host arrays.
  SceneView hostView() const;
};

}  // namespace candela
