#pragma once
#include <cstddef>
#include <string>

#include "core/bounds.h"
#include "io/load_diagnostics.h"
#include "scene/scene.h"

namespace candela {

// The range of numbers a scene may hold, chosen so that float ray arithmetic stays finite and meaningful
// (docs/scene-file.md, "Limits"). Embree, for one, refuses rays with coordinates beyond about 1.8e18.
//
// Vertex positions, in object and in world space.
constexpr float kMaxSceneCoordinate = 1e8f;
// The camera's position and target: room to frame a scene of the largest extent from outside it.
constexpr float kMaxCameraCoordinate = 1e9f;
// An instance transform may shrink no direction by more than this factor (its inverse stays bounded).
constexpr float kMinInstanceScale = 1e-8f;
// Emitted radiance per channel (W/(m^2 sr)): emission times strength, emission texels times emission, environment
// texels times intensity. Far above the emitters of scenes candela is meant for (a frosted 100 W bulb: about 3e3),
// yet small enough that the sum of millions of samples stays finite in float.
constexpr float kMaxRadiance = 1e6f;
// Instances over the whole scene.
constexpr size_t kMaxInstances = 10'000'000;

// Whether an instance transform is usable: finite, and neither singular nor so close to it that its inverse
// (which transforms normals, and rays into the instance) has an entry beyond 1 / kMinInstanceScale.
bool usableTransform(const Affine3x4& transform);
// Whether `transform` keeps the corners of `objectBounds` within kMaxSceneCoordinate.
bool boundsWithinRange(const Bounds3& objectBounds, const Affine3x4& transform);
// The box around a mesh's vertices and curves (widened by their radii), in object space.
Bounds3 meshBounds(const Mesh& mesh);

// Zeroes non-finite normals, texture coordinates and tangents, in meshes and in the rest shapes of skinned and
// morphed meshes, and rescales normals and tangents of extreme length to unit length (a zero normal makes the
// renderer use the geometric one); non-finite vertex colours become white; one warning naming `file` counts the values
// that were not finite. Models go through it as they load, before the scene cache stores them (the cache holds finite
// attributes only), and repairScene again, which changes nothing then.
void repairVertexAttributes(Scene& scene, const std::string& file, LoadWarnings& warnings);

// Repairs a loaded scene once, before it is rendered, so that no number in it can make a backend fail:
// - triangles that use a non-finite vertex or one beyond kMaxSceneCoordinate are dropped (one warning per mesh
//   with the count, for the first ten meshes), and so are triangles without area (one warning for the scene);
//   meshes left without triangles are removed;
// - instances whose transform is not finite, is singular or shrinks some direction below kMinInstanceScale, or
//   that would place their mesh beyond kMaxSceneCoordinate, are dropped (one warning);
// - vertex attributes as repairVertexAttributes says;
// - emitted radiance (material emission, float texels of emission textures, the environment) is clamped to
//   kMaxRadiance per channel (one warning each); float texels that are not finite or negative become 0.
// - punctual lights with a position not finite or beyond kMaxSceneCoordinate, or without a direction, are dropped,
//   and their intensities clamped to kMaxRadiance per channel (one warning each);
// Warnings name `file`. Throws LoadError naming `file` for what cannot be repaired: an impossible camera (the
// field and why), more than kMaxInstances instances, or a scene with triangles none of which survive.
// Afterwards validateScene holds.
void repairScene(Scene& scene, const std::string& file, LoadWarnings& warnings);

}  // namespace candela
