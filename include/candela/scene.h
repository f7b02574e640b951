#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace candela::api {

using Vec3 = std::array<float, 3>;

// How a scene file is read (the options of `candela render` of the same names).
struct LoadOptions {
  std::string environment;         // --env: an .hdr or .exr map that replaces the scene's environment
  std::string camera;              // --camera: the name or index of the scene's camera to take; empty: the first
  bool cache = false;              // read and write the scene cache (the command's default; the library's is off)
  bool allowOutsidePaths = false;  // --allow-outside-paths: models may read files outside their own folders
};

// A scene ready to render: loaded from a file or a built-in name, or built by SceneBuilder. Immutable; copies
// share it, so one scene serves many renders and many threads.
class Scene {
 public:
  // A built-in scene's name ("cornell-box", ...) or a file (.obj, .gltf, .glb, .pbrt, .json). Warnings go to
  // stderr, one line each, as the command prints them. Throws Error.
  static Scene load(const std::string& spec, const LoadOptions& options = {});

  std::string name() const;
  size_t triangleCount() const;  // over the instances

  struct Data;  // the library's scene
  explicit Scene(std::shared_ptr<const Data> data);
  const Data& data() const { return *data_; }

 private:
  std::shared_ptr<const Data> data_;
};

// A material by the parameters most scenes need; the type is a scene file's model name (docs/materials.md):
// diffuse, blinn-phong, pbr, disney, mirror or glass.
struct Material {
  std::string type = "pbr";
  Vec3 baseColor{0.8f, 0.8f, 0.8f};  // linear RGB
  Vec3 emission{0.0f, 0.0f, 0.0f};   // emitted radiance, W/(m^2 sr): an area light
  float roughness = 0.5f;
  float metallic = 0.0f;
  float ior = 1.5f;  // glass, and the specular layer of pbr and disney
};

// One triangle mesh from arrays the caller owns (they are copied): `vertexCount` positions as x, y, z floats and
// `triangleCount` triangles as three vertex indices each. Normals (x, y, z per vertex) and texture coordinates (u, v
// per vertex) are optional; so are per-triangle material ids, without which every triangle takes `material`.
struct MeshArrays {
  const float* positions = nullptr;
  size_t vertexCount = 0;
  const uint32_t* indices = nullptr;
  size_t triangleCount = 0;
  const float* normals = nullptr;
  const float* uvs = nullptr;
  const uint32_t* triangleMaterials = nullptr;
  uint32_t material = 0;
  // Object to world, a row-major 3x4 matrix (the linear part, then the translation in the last column).
  std::array<float, 12> transform{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
};

struct Camera {
  Vec3 eye{0.0f, 0.0f, 5.0f};
  Vec3 target{0.0f, 0.0f, 0.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};
  float verticalFovDegrees = 40.0f;
};

// Builds a Scene from arrays: materials, meshes, lights, an environment and a camera. Without a camera, build()
// frames the scene's bounds as the command does for a model without one.
class SceneBuilder {
 public:
  explicit SceneBuilder(const std::string& name = "arrays");
  ~SceneBuilder();
  SceneBuilder(SceneBuilder&&) noexcept;
  SceneBuilder& operator=(SceneBuilder&&) noexcept;

  // Each returns the new entry's index. Throws Error on a bad value (an unknown material type, an index beyond the
  // vertices), naming it.
  uint32_t addMaterial(const Material& material);
  uint32_t addMesh(const MeshArrays& mesh);
  void addPointLight(const Vec3& position, const Vec3& intensity);  // intensity: W/sr per channel
  // A spot light at `position` pointing along `direction`: full intensity within `innerDegrees` of its axis, none
  // beyond `outerDegrees`.
  void addSpotLight(const Vec3& position, const Vec3& direction, const Vec3& intensity, float innerDegrees,
                    float outerDegrees);
  void addDirectionalLight(const Vec3& direction, const Vec3& irradiance);  // direction: where the light travels
  void setEnvironment(const Vec3& radiance);                                // a constant sky
  // An equirectangular .hdr or .exr map, scaled by `intensity` and turned `rotationDegrees` about +Y.
  void setEnvironmentMap(const std::string& path, float intensity = 1.0f, float rotationDegrees = 0.0f);
  void setCamera(const Camera& camera);

  // The scene, repaired as a loaded one is (docs/scene-file.md, 'Limits'); the builder can go on and build again.
  // Throws Error where a triangle names a material that was not added, or nothing renderable is left.
  Scene build() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace candela::api
