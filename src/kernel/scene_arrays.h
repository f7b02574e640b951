#pragma once
// The scene's flat arrays of plain elements, declared once. Every mirror of them is generated from these lists:
// FlatScene's vectors and hostView(), SceneView's pointers (and counts), DeviceScene's device copies, and, for the
// per-mesh arrays, the scene cache's mesh records and their validation. Adding an array here adds it to all of
// them; what fills it stays to write (FlatScene::build, or Mesh and the loaders for a per-mesh array).
//
// X(Type, member, upload, count, description):
//   Type         the element, trivially copyable (the arrays are copied as bytes);
//   member       the name in FlatScene (std::vector<Type>), in SceneView (const Type*, null when the array is
//                empty) and, for the per-mesh arrays, in Mesh (std::vector<Type>);
//   upload       when DeviceScene copies it to the device (SceneArrayUpload);
//   count        counted(name) where SceneView also holds the array's length, as uint32_t `name`; else uncounted;
//   description  what it holds, for messages (a device allocation that fails).
//
// Left out, with reasons: the textures (TextureView descriptions and their texel arrays: SceneView reaches them
// through TexelArrays, and a GPU samples texture objects made from them instead of copies) and the environment
// (its texels and sampling distribution sit in EnvironmentView and are replaced with it).
//
// Only macros and an enum: usable from host and CUDA code, before the element types are declared.

// Per mesh: Mesh's vertex and triangle arrays, which FlatScene concatenates over the meshes and the scene cache
// writes mesh by mesh in this order (a change here changes the cache's layout: bump kCacheFormatVersion).
#define CANDELA_MESH_ARRAYS(X)                                                                 \
  /* object space, all meshes back to back */                                                  \
  X(Vec3, positions, WithScene, uncounted, "vertex positions")                                 \
  /* zeros where a mesh has none */                                                            \
  X(Vec3, normals, WithScene, uncounted, "vertex normals")                                     \
  /* zeros where a mesh has none */                                                            \
  X(Vec2, uvs, WithScene, uncounted, "texture coordinates")                                    \
  /* unit tangent and bitangent sign (MikkTSpace convention); zeros where a mesh needs none */ \
  X(Vec4, tangents, WithScene, uncounted, "vertex tangents")                                   \
  /* linear RGB; empty when no mesh has colours, white for the meshes without otherwise */     \
  X(Vec3, colors, WithScene, uncounted, "vertex colours")                                      \
  /* mesh-local vertex indices, 3 per triangle */                                              \
  X(uint32_t, indices, WithScene, uncounted, "triangle indices")                               \
  X(uint32_t, triangleMaterials, WithScene, uncounted, "triangle materials")                   \
  /* curves (kernel/curve.h): control points in object space, xyz and radius, 4 per segment */ \
  X(Vec4, curveVertices, WithScene, uncounted, "curve control points")                         \
  /* one per control point of a mesh of ribbons; none for other meshes */                      \
  X(Vec3, curveNormals, WithScene, uncounted, "curve normals")                                 \
  X(CurveSegment, curveSegments, WithScene, uncounted, "curve segments")

// Built by FlatScene::build from the scene as a whole.
#define CANDELA_BUILT_ARRAYS(X)                                                                          \
  /* where each mesh's data starts in the arrays above */                                                \
  X(MeshRecord, meshes, WithScene, uncounted, "mesh records")                                            \
  X(InstanceRecord, instances, WithInstances, uncounted, "instance records")                             \
  X(Material, materials, WithMaterials, uncounted, "materials")                                          \
  /* participating media, which instances' MediumInterface and the camera name by index */               \
  X(Medium, media, WithScene, counted(mediumCount), "the participating media")                           \
  /* the heterogeneous media's grids (kernel/media/medium_grid.h), named by Medium::grid */              \
  X(MediumGrid, mediumGrids, WithScene, uncounted, "the media's grids")                                  \
  /* their samples and majorant grids, named by offset */                                                \
  X(float, mediumGridValues, WithScene, uncounted, "the media's grid samples")                           \
  /* the emissive triangles that emit something on average, in world space */                            \
  X(LightTriangle, lights, WithInstances, counted(lightCount), "the light table")                        \
  /* the point and spot lights first, then the directional ones (SceneView) */                           \
  X(PunctualLight, punctualLights, WithInstances, counted(punctualLightCount), "the punctual lights")    \
  /* one entry per bounded light and one more, by emitted power */                                       \
  X(float, lightCdf, WithInstances, uncounted, "the light distribution")                                 \
  /* the light BVH over the bounded lights (2n - 1 nodes for n of them) */                               \
  X(LightBvhNode, lightBvh, WithInstances, uncounted, "the light BVH")                                   \
  /* per bounded light, its path from the root: bit i is 1 where it takes the second child at depth i */ \
  X(uint64_t, lightBitTrails, WithInstances, uncounted, "the light BVH's bit trails")

#define CANDELA_SCENE_ARRAYS(X) CANDELA_MESH_ARRAYS(X) CANDELA_BUILT_ARRAYS(X)

// A list entry's `count` as SceneView's member declaration, or nothing.
#define CANDELA_SCENE_ARRAY_COUNT_MEMBER(count) CANDELA_SCENE_ARRAY_COUNT_MEMBER_##count
#define CANDELA_SCENE_ARRAY_COUNT_MEMBER_uncounted
#define CANDELA_SCENE_ARRAY_COUNT_MEMBER_counted(name) uint32_t name = 0;
// ... as a pointer to that member of SceneView, or null (for setSceneArrayCount, kernel/scene_view.h).
#define CANDELA_SCENE_ARRAY_COUNT_FIELD(count) CANDELA_SCENE_ARRAY_COUNT_FIELD_##count
#define CANDELA_SCENE_ARRAY_COUNT_FIELD_uncounted nullptr
#define CANDELA_SCENE_ARRAY_COUNT_FIELD_counted(name) &SceneView::name

// For counting a list's entries: `0 CANDELA_MESH_ARRAYS(CANDELA_SCENE_ARRAY_ONE)`.
#define CANDELA_SCENE_ARRAY_ONE(Type, member, upload, count, description) +1

namespace candela {

// When DeviceScene copies an array to the device: with the scene (upload), copied over in place with the
// materials (updateMaterials: the same size), or again with the instance transforms (updateInstances).
enum class SceneArrayUpload { WithScene, WithMaterials, WithInstances };

}  // namespace candela
