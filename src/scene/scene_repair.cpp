#include "scene/scene_repair.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "core/bounds.h"

namespace candela {

namespace {

// Per-mesh warnings beyond this many are summed up in one line.
constexpr size_t kMaxMeshWarnings = 10;

std::string compact(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

std::string describe(Vec3 v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", double(v.x), double(v.y), double(v.z));
  return text;
}

// False for NaN and infinities too.
bool withinRange(float x, float limit) { return std::fabs(x) <= limit; }
bool withinRange(Vec3 v, float limit) {
  return withinRange(v.x, limit) && withinRange(v.y, limit) && withinRange(v.z, limit);
}

enum class TriangleFault : uint8_t { None, OutOfRange, NoArea };

// Whether the renderer can use a triangle: in range, with an area whose float normal is representable (its
// squared length a normal float, so that normalising it cannot divide by zero).
TriangleFault triangleFault(const Mesh& mesh, size_t t) {
  const uint32_t* i = &mesh.indices[3 * t];
  const size_t vertices = mesh.positions.size();
  if (i[0] >= vertices || i[1] >= vertices || i[2] >= vertices) return TriangleFault::OutOfRange;
  Vec3 a = mesh.positions[i[0]], b = mesh.positions[i[1]], c = mesh.positions[i[2]];
  if (!withinRange(a, kMaxSceneCoordinate) || !withinRange(b, kMaxSceneCoordinate) ||
      !withinRange(c, kMaxSceneCoordinate))
    return TriangleFault::OutOfRange;
  Vec3 n = cross(b - a, c - a);
  return dot(n, n) >= std::numeric_limits<float>::min() ? TriangleFault::None : TriangleFault::NoArea;
}

// The same direction at unit length, computed without overflow or underflow; zero stays zero.
Vec3 unitLength(Vec3 v) {
  float largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  if (largest == 0.0f) return v;
  // Divided component by component: the reciprocal of a subnormal largest component overflows to infinity.
  v = {v.x / largest, v.y / largest, v.z / largest};
  const float l = length(v);
  return {v.x / l, v.y / l, v.z / l};
}

// Normals and tangents of a reasonable length are left exactly as they are; the others would overflow or
// underflow when the renderer squares them.
bool needsRescaling(Vec3 v) {
  float largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  return largest != 0.0f && !(largest >= 1e-6f && largest <= 1e6f);
}

template <class T>
void keepSelected(std::vector<T>& values, const std::vector<uint32_t>& newIndex, size_t count) {
  if (values.size() != newIndex.size()) return;  // none, or a count validateScene names
  std::vector<T> kept(count);
  for (size_t v = 0; v < values.size(); ++v)
    if (newIndex[v] != ~0u) kept[newIndex[v]] = values[v];
  values = std::move(kept);
}

// Removes the vertices no triangle uses (those out of range among them), renumbering the indices.
void dropUnusedVertices(Mesh& mesh) {
  std::vector<uint32_t> newIndex(mesh.positions.size(), ~0u);
  for (uint32_t i : mesh.indices) newIndex[i] = 0;
  uint32_t count = 0;
  for (uint32_t& n : newIndex)
    if (n == 0) n = count++;
  for (uint32_t& i : mesh.indices) i = newIndex[i];
  keepSelected(mesh.positions, newIndex, count);
  keepSelected(mesh.normals, newIndex, count);
  keepSelected(mesh.uvs, newIndex, count);
  keepSelected(mesh.tangents, newIndex, count);
}

struct DroppedTriangles {
  size_t outOfRange = 0, noArea = 0;
};

// Drops the triangles triangleFault finds fault with.
DroppedTriangles dropUnusableTriangles(Mesh& mesh) {
  const size_t n = mesh.triangleCount();
  std::vector<TriangleFault> faults(n);
  const DroppedTriangles dropped = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, n), DroppedTriangles{},
      [&](const tbb::blocked_range<size_t>& r, DroppedTriangles d) {
        for (size_t t = r.begin(); t < r.end(); ++t) {
          faults[t] = triangleFault(mesh, t);
          d.outOfRange += faults[t] == TriangleFault::OutOfRange ? 1 : 0;
          d.noArea += faults[t] == TriangleFault::NoArea ? 1 : 0;
        }
        return d;
      },
      [](DroppedTriangles a, DroppedTriangles b) {
        return DroppedTriangles{a.outOfRange + b.outOfRange, a.noArea + b.noArea};
      });
  if (dropped.outOfRange + dropped.noArea == 0) return dropped;
  const bool materialsPerTriangle = mesh.triangleMaterials.size() == n;
  size_t out = 0;
  for (size_t t = 0; t < n; ++t) {
    if (faults[t] != TriangleFault::None) continue;
    for (int k = 0; k < 3; ++k) mesh.indices[3 * out + k] = mesh.indices[3 * t + k];
    if (materialsPerTriangle) mesh.triangleMaterials[out] = mesh.triangleMaterials[t];
    ++out;
  }
  mesh.indices.resize(3 * out);
  if (materialsPerTriangle) mesh.triangleMaterials.resize(out);
  const bool anyVertexOutOfRange = std::any_of(mesh.positions.begin(), mesh.positions.end(),
                                               [](Vec3 p) { return !withinRange(p, kMaxSceneCoordinate); });
  if (anyVertexOutOfRange) dropUnusedVertices(mesh);
  return dropped;
}

// Counts what `repair` replaced in `values`, repaired in parallel.
template <class T, class Repair>
size_t repairEach(std::vector<T>& values, Repair repair) {
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, values.size()), size_t(0),
      [&](const tbb::blocked_range<size_t>& r, size_t bad) {
        for (size_t i = r.begin(); i < r.end(); ++i) bad += repair(values[i]) ? 1 : 0;
        return bad;
      },
      std::plus<size_t>());
}

// Non-finite normals become zero (the renderer then takes the geometric one), extreme ones unit length; true
// where the normal was not finite. Tangents alike (zero with handedness 1), texture coordinates zeroed.
bool repairNormal(Vec3& n) {
  if (!isFinite(n)) {
    n = {};
    return true;
  }
  if (needsRescaling(n)) n = unitLength(n);
  return false;
}
bool repairTangent(Vec4& t) {
  Vec3 xyz{t.x, t.y, t.z};
  if (!isFinite(xyz) || !std::isfinite(t.w)) {
    t = {0, 0, 0, 1};
    return true;
  }
  if (needsRescaling(xyz)) {
    xyz = unitLength(xyz);
    t = {xyz.x, xyz.y, xyz.z, t.w};
  }
  return false;
}
bool repairUv(Vec2& uv) {
  if (std::isfinite(uv.x) && std::isfinite(uv.y)) return false;
  uv = {};
  return true;
}
// A vertex colour that is not finite becomes white, which leaves the base colour as it is.
bool repairColor(Vec3& c) {
  if (isFinite(c)) return false;
  c = {1, 1, 1};
  return true;
}

}  // namespace

bool usableTransform(const Affine3x4& transform) {
  for (float x : transform.m)
    if (!std::isfinite(x)) return false;
  double a[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a[r][c] = transform.m[4 * r + c];
  // The inverse is the transposed cofactor matrix over the determinant; cofactor(r, c) from the cyclic minors.
  double cofactor[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      cofactor[r][c] = a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1];
    }
  const double det = a[0][0] * cofactor[0][0] + a[0][1] * cofactor[0][1] + a[0][2] * cofactor[0][2];
  if (!(std::fabs(det) > 0.0)) return false;
  for (const auto& row : cofactor)
    for (double c : row)
      if (!(std::fabs(c / det) <= 1.0 / kMinInstanceScale)) return false;
  return true;
}

bool boundsWithinRange(const Bounds3& objectBounds, const Affine3x4& transform) {
  for (int corner = 0; corner < 8; ++corner) {
    Vec3 p{corner & 1 ? objectBounds.hi.x : objectBounds.lo.x, corner & 2 ? objectBounds.hi.y : objectBounds.lo.y,
           corner & 4 ? objectBounds.hi.z : objectBounds.lo.z};
    if (!withinRange(transform.point(p), kMaxSceneCoordinate)) return false;
  }
  return true;
}

Bounds3 meshBounds(const Mesh& mesh) {
  Bounds3 bounds = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, mesh.positions.size()), Bounds3{},
      [&](const tbb::blocked_range<size_t>& r, Bounds3 b) {
        for (size_t v = r.begin(); v < r.end(); ++v) b.extend(mesh.positions[v]);
        return b;
      },
      [](Bounds3 a, const Bounds3& b) {
        if (!b.empty()) {
          a.extend(b.lo);
          a.extend(b.hi);
        }
        return a;
      });
  // A curve lies within its control points' hull, widened by their largest radius.
  for (const Vec4& v : mesh.curveVertices) {
    bounds.extend(Vec3{v.x, v.y, v.z} - Vec3{v.w, v.w, v.w});
    bounds.extend(Vec3{v.x, v.y, v.z} + Vec3{v.w, v.w, v.w});
  }
  return bounds;
}

namespace {

// What repairing one mesh did, and the bounds of what is left of it.
struct MeshRepair {
  DroppedTriangles dropped;
  Bounds3 bounds;
};

// Meshes are repaired in parallel, and each one's triangles and vertices in parallel too. Triangles out of range
// are worth a warning for each mesh (up to kMaxMeshWarnings); triangles without area, common in ordinary models
// (the poles of a UV sphere), one line for the scene.
std::vector<MeshRepair> repairMeshes(Scene& scene, const std::string& file, LoadWarnings& warnings) {
  std::vector<MeshRepair> repairs(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes)
    if (mesh.indices.size() % 3 != 0) return repairs;  // validateScene names this
  tbb::parallel_for(size_t(0), scene.meshes.size(), [&](size_t m) {
    Mesh& mesh = scene.meshes[m];
    repairs[m].dropped = dropUnusableTriangles(mesh);
    repairs[m].bounds = meshBounds(mesh);
  });

  size_t meshesWarned = 0, meshesNotNamed = 0, outOfRangeNotNamed = 0, noArea = 0, meshesWithoutArea = 0;
  size_t trianglesLeft = 0, trianglesDropped = 0;
  const std::string range = "a vertex not finite or beyond +-" + compact(kMaxSceneCoordinate);
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const DroppedTriangles& dropped = repairs[m].dropped;
    trianglesLeft += scene.meshes[m].triangleCount();
    trianglesDropped += dropped.outOfRange + dropped.noArea;
    noArea += dropped.noArea;
    meshesWithoutArea += dropped.noArea > 0 ? 1 : 0;
    if (dropped.outOfRange == 0) continue;
    if (meshesWarned++ < kMaxMeshWarnings) {
      warnings.add(file, "mesh '" + scene.meshes[m].name + "': " + std::to_string(dropped.outOfRange) +
                             " triangles dropped: " + range);
    } else {
      ++meshesNotNamed;
      outOfRangeNotNamed += dropped.outOfRange;
    }
  }
  if (meshesNotNamed > 0)
    warnings.add(file, std::to_string(outOfRangeNotNamed) + " triangles of " + std::to_string(meshesNotNamed) +
                           " more meshes dropped: " + range);
  if (noArea > 0)
    warnings.add(file, std::to_string(noArea) + " triangles without area dropped (in " +
                           std::to_string(meshesWithoutArea) + " meshes)");
  if (trianglesDropped > 0 && trianglesLeft == 0)
    failLoad(file, "no triangle is usable: all have no area or lie beyond +-" + compact(kMaxSceneCoordinate));
  return repairs;
}

void repairInstances(Scene& scene, const std::vector<MeshRepair>& repairs, const std::string& file,
                     LoadWarnings& warnings) {
  if (scene.instances.size() > kMaxInstances)
    failLoad(file, "has " + std::to_string(scene.instances.size()) + " instances; at most " +
                       std::to_string(kMaxInstances) + " are supported");
  // Meshes left without triangles or curves go; the instances of the others are renumbered.
  std::vector<uint32_t> newMeshId(scene.meshes.size(), ~0u);
  std::vector<Bounds3> bounds;
  size_t kept = 0;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    if (scene.meshes[m].triangleCount() == 0 && scene.meshes[m].curveSegments.empty()) continue;
    newMeshId[m] = uint32_t(kept);
    bounds.push_back(repairs[m].bounds);
    if (kept != m) scene.meshes[kept] = std::move(scene.meshes[m]);
    ++kept;
  }
  scene.meshes.resize(kept);

  size_t unusable = 0, outOfRange = 0, out = 0;
  // The animation refers to instances by index: each instance's new one, or ~0u where it was dropped.
  std::vector<uint32_t> newInstanceIndex(scene.animation.empty() ? 0 : scene.instances.size(), ~0u);
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance inst = scene.instances[i];
    if (!newInstanceIndex.empty()) newInstanceIndex[i] = uint32_t(out);
    if (inst.meshId >= newMeshId.size()) {
      scene.instances[out++] = inst;  // validateScene names this
      continue;
    }
    const uint32_t mesh = newMeshId[inst.meshId];
    bool keep = mesh != ~0u;
    if (keep && !usableTransform(inst.objectToWorld)) {
      ++unusable;
      keep = false;
    } else if (keep && !boundsWithinRange(bounds[mesh], inst.objectToWorld)) {
      ++outOfRange;
      keep = false;
    }
    if (!keep) {
      if (!newInstanceIndex.empty()) newInstanceIndex[i] = ~0u;
      continue;
    }
    scene.instances[out++] = {mesh, inst.objectToWorld, inst.media};
  }
  scene.instances.resize(out);
  if (!newInstanceIndex.empty()) scene.animation.renumberInstances(newInstanceIndex);
  if (!scene.animation.deformations.empty()) {
    std::vector<size_t> vertexCounts;
    for (const Mesh& mesh : scene.meshes) vertexCounts.push_back(mesh.positions.size());
    if (const size_t dropped = scene.animation.renumberMeshes(newMeshId, vertexCounts); dropped > 0)
      warnings.add(file, std::to_string(dropped) +
                             " skinned or morphed meshes keep their rest shape: vertices beyond the coordinate "
                             "range were dropped from them");
  }
  if (unusable > 0)
    warnings.add(file, std::to_string(unusable) +
                           " instances dropped: their transform is not finite, is singular, or shrinks some "
                           "direction by more than a factor of " +
                           compact(1.0 / kMinInstanceScale));
  if (outOfRange > 0)
    warnings.add(file, std::to_string(outOfRange) + " instances dropped: their transform places them beyond +-" +
                           compact(kMaxSceneCoordinate));
  if (scene.instances.empty() && (unusable > 0 || outOfRange > 0))
    failLoad(file, "no instance is usable: every transform is singular, not finite or out of range");
}

// NaN and negative values become 0, larger ones `limit`.
float clampRadiance(float x, float limit) { return x >= 0.0f ? std::min(x, limit) : 0.0f; }

// Returns how many values changed.
size_t clampValues(float* values, size_t count, float limit) {
  size_t changed = 0;
  for (size_t i = 0; i < count; ++i) {
    float clamped = clampRadiance(values[i], limit);
    if (clamped != values[i] || std::isnan(values[i])) ++changed;
    values[i] = clamped;
  }
  return changed;
}
size_t clampValues(Vec3& v, float limit) {
  return clampValues(&v.x, 1, limit) + clampValues(&v.y, 1, limit) + clampValues(&v.z, 1, limit);
}

void clampEmittedRadiance(Scene& scene, const std::string& file, LoadWarnings& warnings) {
  const std::string limit = compact(kMaxRadiance);
  size_t materials = 0;
  // The largest emission each float texture multiplies, so that texel times emission stays within the limit.
  std::vector<float> largestEmission(scene.textures.size(), 1.0f);
  for (Material& m : scene.materials) {
    if (clampValues(m.emission, kMaxRadiance) > 0) ++materials;
    if (m.emissionTexture >= 0 && size_t(m.emissionTexture) < scene.textures.size())
      largestEmission[size_t(m.emissionTexture)] =
          std::max(largestEmission[size_t(m.emissionTexture)], maxComponent(m.emission));
  }
  if (materials > 0)
    warnings.add(file, "the emission of " + std::to_string(materials) + " materials is clamped to " + limit +
                           " per channel, the largest radiance candela supports");

  size_t texels = 0;
  for (size_t t = 0; t < scene.textures.size(); ++t) {
    std::vector<float>& f = scene.textures[t].floats;
    texels += clampValues(f.data(), f.size(), kMaxRadiance / largestEmission[t]);
  }
  if (texels > 0)
    warnings.add(file, std::to_string(texels) + " float texture values clamped to [0, " + limit + "] (to " + limit +
                           " times the emission they scale)");

  Environment& env = scene.environment;
  size_t environmentValues = clampValues(&env.intensity, 1, std::numeric_limits<float>::max());
  const float envLimit = kMaxRadiance / std::max(env.intensity, 1.0f);
  environmentValues +=
      clampValues(env.radiance, envLimit) + clampValues(env.map.floats.data(), env.map.floats.size(), envLimit);
  if (!std::isfinite(env.rotationDegrees)) {
    env.rotationDegrees = 0.0f;
    ++environmentValues;
  }
  if (environmentValues > 0)
    warnings.add(file, "environment radiance clamped to " + limit + " per channel (times the intensity)");
}

// Punctual lights outside the coordinate range, without a direction or with non-finite numbers are dropped;
// intensities are clamped like emitted radiance.
void repairPunctualLights(Scene& scene, const std::string& file, LoadWarnings& warnings) {
  size_t dropped = 0, clamped = 0;
  std::vector<PunctualLight> kept;
  // The animation refers to lights by index: each light's new one, or ~0u where it was dropped.
  std::vector<uint32_t> newLightIndex(scene.punctualLights.size(), ~0u);
  for (size_t i = 0; i < scene.punctualLights.size(); ++i) {
    PunctualLight light = scene.punctualLights[i];
    const bool usable = withinRange(light.position, kMaxSceneCoordinate) && withinRange(light.direction, 2.0f) &&
                        length(light.direction) > 0.5f && std::isfinite(light.cosInner) &&
                        std::isfinite(light.cosOuter);
    if (!usable) {
      ++dropped;
      continue;
    }
    light.direction = normalize(light.direction);
    light.cosOuter = std::clamp(light.cosOuter, -1.0f, 1.0f);
    light.cosInner = std::clamp(light.cosInner, light.cosOuter, 1.0f);
    if (clampValues(light.intensity, kMaxRadiance) > 0) ++clamped;
    newLightIndex[i] = uint32_t(kept.size());
    kept.push_back(light);
  }
  scene.punctualLights = std::move(kept);
  scene.animation.renumberLights(newLightIndex);
  if (dropped > 0)
    warnings.add(file, std::to_string(dropped) + " punctual lights dropped: a position not finite or beyond +-" +
                           compact(kMaxSceneCoordinate) + ", or no direction");
  if (clamped > 0)
    warnings.add(file, "the intensity of " + std::to_string(clamped) + " punctual lights is clamped to " +
                           compact(kMaxRadiance) + " per channel");
}

void checkCamera(const CameraDescription& c, const std::string& file) {
  auto fail = [&](const char* field, const std::string& why) {
    failLoad(file, std::string("camera.") + field + ": " + why);
  };
  const std::string range = "not finite or beyond +-" + compact(kMaxCameraCoordinate);
  if (!withinRange(c.eye, kMaxCameraCoordinate)) fail("position", describe(c.eye) + " is " + range);
  if (!withinRange(c.target, kMaxCameraCoordinate)) fail("target", describe(c.target) + " is " + range);
  if (!withinRange(c.up, kMaxCameraCoordinate)) fail("up", describe(c.up) + " is " + range);
  // As Camera::lookAt computes its frame: neither normalisation may divide by zero.
  const Vec3 forward = c.target - c.eye;
  if (!(dot(forward, forward) >= std::numeric_limits<float>::min()))
    fail("target", "the camera's position and target coincide");
  const Vec3 right = cross(normalize(forward), c.up);
  const float rightSquared = dot(right, right);
  if (!(rightSquared >= std::numeric_limits<float>::min() && rightSquared > 1e-12f * dot(c.up, c.up)))
    fail("up", describe(c.up) + " is zero or parallel to the viewing direction");
  if (!(c.verticalFovDegrees > 0.0f && c.verticalFovDegrees < 180.0f))
    fail("fov_degrees", compact(c.verticalFovDegrees) + " is not between 0 and 180 degrees");
  if (!(c.apertureRadius >= 0.0f && c.apertureRadius <= kMaxCameraCoordinate))
    fail("aperture_radius", compact(c.apertureRadius) + " is negative, " + range);
  if (!(c.focusDistance >= 0.0f && c.focusDistance <= kMaxCameraCoordinate))
    fail("focus_distance", compact(c.focusDistance) + " is negative, " + range);
  // The image's extent and shift are bounded alike, so that rays start within kMaxCameraRayOrigin.
  if (!(c.orthographicHalfHeight > 0.0f && c.orthographicHalfHeight <= kMaxCameraCoordinate))
    fail("orthographic_half_height", compact(c.orthographicHalfHeight) + " is not positive, " + range);
  if (!(std::fabs(c.imageShift.x) <= kMaxCameraCoordinate && std::fabs(c.imageShift.y) <= kMaxCameraCoordinate))
    fail("image_shift", compact(c.imageShift.x) + " " + compact(c.imageShift.y) + " is " + range);
}

}  // namespace

void repairVertexAttributes(Scene& scene, const std::string& file, LoadWarnings& warnings) {
  std::vector<size_t> bad(scene.meshes.size());
  tbb::parallel_for(size_t(0), scene.meshes.size(), [&](size_t m) {
    Mesh& mesh = scene.meshes[m];
    bad[m] = repairEach(mesh.normals, repairNormal) + repairEach(mesh.uvs, repairUv) +
             repairEach(mesh.tangents, repairTangent) + repairEach(mesh.colors, repairColor);
  });
  // The rest shapes of skinned and morphed meshes alike, which the player writes back when it poses a mesh (not
  // counted: they start as copies of their meshes').
  for (MeshDeformation& d : scene.animation.deformations) {
    repairEach(d.normals, repairNormal);
    repairEach(d.tangents, repairTangent);
  }
  size_t total = 0;
  for (size_t b : bad) total += b;
  if (total > 0)
    warnings.add(file, std::to_string(total) +
                           " non-finite normals, texture coordinates or tangents replaced with zero, or colours "
                           "with white");
}

void repairScene(Scene& scene, const std::string& file, LoadWarnings& warnings) {
  repairVertexAttributes(scene, file, warnings);
  const std::vector<MeshRepair> repairs = repairMeshes(scene, file, warnings);
  repairInstances(scene, repairs, file, warnings);
  clampEmittedRadiance(scene, file, warnings);
  repairPunctualLights(scene, file, warnings);
  if (!scene.cameraMissing) checkCamera(scene.camera, file);
  validateScene(scene);
}

}  // namespace candela
