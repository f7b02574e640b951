#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "app/scene_loading.h"
#include "scene/scene_repair.h"
#include "scene/scene_test_files.h"

namespace candela {
namespace {

using test::TempFolder;

const float kNan = std::numeric_limits<float>::quiet_NaN();
const float kInfinity = std::numeric_limits<float>::infinity();

// One unit quad as two triangles, one material, one instance at the origin, a camera looking at it.
Scene quadScene() {
  Scene s;
  s.name = "quad";
  Mesh m;
  m.name = "quad";
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.indices = {0, 1, 2, 0, 2, 3};
  m.triangleMaterials = {0, 0};
  s.meshes.push_back(m);
  s.materials.push_back(Material{});
  s.instances.push_back({0, Affine3x4{}});
  s.camera.eye = {0.5f, 0.5f, 3};
  s.camera.target = {0.5f, 0.5f, 0};
  return s;
}

std::string repairError(Scene s) {
  LoadWarnings warnings;
  try {
    repairScene(s, "hostile.json", warnings);
  } catch (const LoadError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneRepair, AnUsableSceneIsLeftAsItIs) {
  Scene s = quadScene();
  LoadWarnings warnings;
  repairScene(s, "quad.obj", warnings);
  EXPECT_TRUE(warnings.messages.empty());
  EXPECT_EQ(s.meshes[0].indices, quadScene().meshes[0].indices);
  EXPECT_EQ(s.meshes[0].positions.size(), 4u);
}

TEST(SceneRepair, TrianglesOutOfRangeOrWithoutAreaAreDroppedWithAWarning) {
  for (Vec3 bad : {Vec3{1e19f, 0, 0}, Vec3{0, kNan, 0}, Vec3{0, 0, -kInfinity}, Vec3{2e8f, 1, 1}}) {
    Scene s = quadScene();
    Mesh& m = s.meshes[0];
    m.positions.push_back(bad);
    m.normals.push_back({0, 0, 1});
    m.uvs.push_back({0, 0});
    m.indices.insert(m.indices.end(), {0, 1, 4, 0, 2, 2});  // out of range; no area
    m.triangleMaterials.insert(m.triangleMaterials.end(), {0, 0});
    LoadWarnings warnings;
    repairScene(s, "model.obj", warnings);
    ASSERT_EQ(warnings.messages.size(), 2u);
    EXPECT_EQ(warnings.messages[0],
              "model.obj: mesh 'quad': 1 triangles dropped: a vertex not finite or beyond +-1e+08");
    EXPECT_EQ(warnings.messages[1], "model.obj: 1 triangles without area dropped (in 1 meshes)");
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(m.triangleMaterials.size(), 2u);
    EXPECT_EQ(m.positions.size(), 4u) << "the vertex out of range goes too";
    EXPECT_EQ(m.normals.size(), 4u);
    validateScene(s);
  }
}

TEST(SceneRepair, OutOfRangeTrianglesAreNamedForTenMeshesThenCounted) {
  Scene s = quadScene();
  Mesh& m = s.meshes[0];
  m.positions.push_back({kNan, 0, 0});
  m.indices.insert(m.indices.end(), {0, 1, 4});
  m.triangleMaterials.push_back(0);
  m.normals.clear();
  m.uvs.clear();
  s.meshes.assign(12, m);
  LoadWarnings warnings;
  repairScene(s, "many.gltf", warnings);
  ASSERT_EQ(warnings.messages.size(), 11u);
  EXPECT_EQ(warnings.messages[10],
            "many.gltf: 2 triangles of 2 more meshes dropped: a vertex not finite or beyond +-1e+08");
}

TEST(SceneRepair, TrianglesTooSmallForAFloatNormalAreDropped) {
  Scene s = quadScene();
  for (Vec3& p : s.meshes[0].positions) p = p * 1e-25f;
  s.camera.eye = {0, 0, 1};
  s.camera.target = {0, 0, 0};
  EXPECT_NE(repairError(s).find("no triangle is usable"), std::string::npos);
}

TEST(SceneRepair, SingularNonFiniteOrOutOfRangeInstancesAreDropped) {
  Affine3x4 flat;  // glTF's scale [1, 1, 0]
  flat.m[10] = 0.0f;
  Affine3x4 zero;
  for (float& x : zero.m) x = 0.0f;
  Affine3x4 notFinite;
  notFinite.m[3] = kNan;
  Affine3x4 tiny;  // a scene file's scale 1e-38
  tiny.m[0] = tiny.m[5] = tiny.m[10] = 1e-38f;
  Affine3x4 far;
  far.m[7] = 3e8f;
  for (const Affine3x4& bad : {flat, zero, notFinite, tiny, far}) {
    Scene s = quadScene();
    s.instances.push_back({0, bad});
    LoadWarnings warnings;
    repairScene(s, "model.gltf", warnings);
    ASSERT_EQ(s.instances.size(), 1u);
    ASSERT_EQ(warnings.messages.size(), 1u);
    EXPECT_NE(warnings.messages[0].find("model.gltf: 1 instances dropped"), std::string::npos) << warnings.messages[0];

    Scene only = quadScene();
    only.instances[0].objectToWorld = bad;
    EXPECT_NE(repairError(only).find("hostile.json: no instance is usable"), std::string::npos);
  }
  Scene mirrored = quadScene();  // a mirror is not singular
  mirrored.instances[0].objectToWorld.m[0] = -1.0f;
  EXPECT_EQ(repairError(mirrored), "");
}

TEST(SceneRepair, NonFiniteAttributesAreZeroedAndExtremeOnesRescaled) {
  Scene s = quadScene();
  Mesh& m = s.meshes[0];
  m.normals[0] = {kNan, 0, 1};
  m.normals[1] = {0, 0, 3e38f};
  m.uvs[2] = {kInfinity, 0};
  m.tangents = {{1, 0, 0, 1}, {kNan, 0, 0, 1}, {1e-30f, 0, 0, -1}, {1, 0, 0, 1}};
  m.colors = {{0.5f, 0.5f, 0.5f}, {0.5f, kInfinity, 0.5f}, {0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}};
  LoadWarnings warnings;
  repairScene(s, "model.obj", warnings);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("4 non-finite normals, texture coordinates or tangents"), std::string::npos);
  EXPECT_EQ(m.colors[1].y, 1.0f);
  EXPECT_EQ(m.colors[0].y, 0.5f);
  EXPECT_EQ(m.normals[0].x, 0.0f);
  EXPECT_EQ(m.normals[0].z, 0.0f);
  EXPECT_EQ(m.normals[1].z, 1.0f);
  EXPECT_EQ(m.uvs[2].x, 0.0f);
  EXPECT_EQ(m.tangents[1].x, 0.0f);
  EXPECT_EQ(m.tangents[2].x, 1.0f);
  EXPECT_EQ(m.tangents[2].w, -1.0f);
}

TEST(SceneRepair, EmittedRadianceIsClampedWithOneWarning) {
  Scene s = quadScene();
  s.materials[0].emission = {3e38f, kInfinity, 2.0f};
  Material second;
  second.emission = {5e6f, 0, 0};
  s.materials.push_back(second);
  LoadWarnings warnings;
  repairScene(s, "lamp.obj", warnings);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("emission of 2 materials is clamped to 1e+06"), std::string::npos);
  EXPECT_EQ(s.materials[0].emission.x, kMaxRadiance);
  EXPECT_EQ(s.materials[0].emission.y, kMaxRadiance);
  EXPECT_EQ(s.materials[0].emission.z, 2.0f);
  EXPECT_EQ(s.materials[1].emission.x, kMaxRadiance);
}

TEST(SceneRepair, FloatEmissionTexelsAreClampedSoThatTheirProductWithTheEmissionStaysInRange) {
  Scene s = quadScene();
  Texture hdr;
  hdr.name = "glow.hdr";
  hdr.width = 2;
  hdr.height = 1;
  hdr.channels = 3;
  hdr.floats = {1.7e38f, 2.0f, 0.5f, 3.0f, 3.0f, 3.0f};
  s.textures.push_back(hdr);
  s.materials[0].emission = {1000, 10, 1};
  s.materials[0].emissionTexture = 0;
  LoadWarnings warnings;
  repairScene(s, "lamp.obj", warnings);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("lamp.obj: 1 float texture values clamped"), std::string::npos);
  EXPECT_EQ(s.textures[0].floats[0], kMaxRadiance / 1000);
  EXPECT_EQ(s.textures[0].floats[1], 2.0f);
}

TEST(SceneRepair, EnvironmentRadianceTimesIntensityIsClamped) {
  Scene constant = quadScene();
  constant.environment.radiance = {3e38f, 1, 1};
  constant.environment.intensity = 100.0f;
  LoadWarnings warnings;
  repairScene(constant, "sky.json", warnings);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("environment radiance clamped"), std::string::npos);
  EXPECT_EQ(constant.environment.radiance.x * constant.environment.intensity, kMaxRadiance);
  EXPECT_EQ(constant.environment.radiance.y, 1.0f);

  Scene mapped = quadScene();
  mapped.environment.map.width = 1;
  mapped.environment.map.height = 1;
  mapped.environment.map.channels = 3;
  mapped.environment.map.floats = {1.7e38f, 1.7e38f, 0.25f};
  repairScene(mapped, "sky.json", warnings);
  EXPECT_EQ(mapped.environment.map.floats[0], kMaxRadiance);
  EXPECT_EQ(mapped.environment.map.floats[2], 0.25f);
}

TEST(SceneRepair, ImpossibleCamerasAreRejectedNamingTheField) {
  struct Case {
    const char* field;
    void (*spoil)(CameraDescription&);
  };
  const Case cases[] = {
      {"camera.position",
       [](CameraDescription& c) {
         c.eye = {3e38f, 0, 0};
       }},
      {"camera.position",
       [](CameraDescription& c) {
         c.eye = {0, kNan, 0};
       }},
      {"camera.target",
       [](CameraDescription& c) {
         c.target = {0, 0, -2e9f};
       }},
      {"camera.target", [](CameraDescription& c) { c.target = c.eye; }},
      {"camera.up", [](CameraDescription& c) { c.up = c.target - c.eye; }},
      {"camera.up",
       [](CameraDescription& c) {
         c.up = {0, 0, 0};
       }},
      {"camera.up",
       [](CameraDescription& c) {
         c.up = {0, 1e-30f, 0};
       }},
      {"camera.target",
       [](CameraDescription& c) {
         c.eye = {0, 0, 0};
         c.target = {0, 0, 1e-30f};
       }},
      {"camera.fov_degrees", [](CameraDescription& c) { c.verticalFovDegrees = 180.0f; }},
      {"camera.fov_degrees", [](CameraDescription& c) { c.verticalFovDegrees = 0.0f; }},
      {"camera.aperture_radius", [](CameraDescription& c) { c.apertureRadius = 1e30f; }},
      {"camera.focus_distance", [](CameraDescription& c) { c.focusDistance = kInfinity; }},
      {"camera.orthographic_half_height",
       [](CameraDescription& c) {
         c.projection = Projection::Orthographic;
         c.orthographicHalfHeight = 1e30f;
       }},
      {"camera.orthographic_half_height", [](CameraDescription& c) { c.orthographicHalfHeight = 0.0f; }},
      {"camera.image_shift",
       [](CameraDescription& c) {
         c.imageShift = {kInfinity, 0};
       }},
  };
  for (const Case& c : cases) {
    Scene s = quadScene();
    c.spoil(s.camera);
    std::string error = repairError(s);
    EXPECT_EQ(error.rfind(std::string("hostile.json: ") + c.field + ":", 0), 0u) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos);
  }
  Scene framedLater = quadScene();  // a camera yet to be framed is not checked
  framedLater.cameraMissing = true;
  framedLater.camera.eye = framedLater.camera.target;
  EXPECT_EQ(repairError(framedLater), "");
}

// The repair runs on every load: models, scene files and models read back from the scene cache.
TEST(SceneRepair, LoadSceneRepairsModelsAlsoFromTheCache) {
  TempFolder dir;
  std::string obj =
      dir.write("far.obj", "mtllib far.mtl\nusemtl lamp\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1e19 0 0\nf 1 2 3\nf 1 2 4\n");
  dir.write("far.mtl", "newmtl lamp\nKe 3e38 3e38 3e38\n");
  SceneLoadOptions options;
  options.cache = {true, dir.file("cache")};
  for (int load = 0; load < 2; ++load) {
    Scene s = loadScene(obj, options);
    ASSERT_EQ(s.triangleCount(), 1u) << "load " << load;
    EXPECT_EQ(s.materials[s.meshes[0].triangleMaterials[0]].emission.x, kMaxRadiance);
  }
  EXPECT_FALSE(std::filesystem::is_empty(dir.file("cache")));
}

TEST(SceneRepair, LoadSceneClampsSceneFileEmissionOverridesAndMaximalRgbeEnvironments) {
  TempFolder dir;
  dir.write("lamp.obj", "mtllib lamp.mtl\nusemtl lamp\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  dir.write("lamp.mtl", "newmtl lamp\nKd 0.5 0.5 0.5\n");
  // Flat RGBE pixels with the largest mantissa and exponent: about 1.7e38 each.
  std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n" + std::string(8, '\xff');
  dir.write("max.hdr", hdr);
  std::string scene = dir.write("scene.json", R"({"models": [{"file": "lamp.obj",
      "materials": {"lamp": {"emission": [3e38, 3e38, 1]}}}], "environment": {"map": "max.hdr", "intensity": 2}})");
  Scene s = loadScene(scene);
  EXPECT_EQ(s.materials[0].emission.x, kMaxRadiance);
  EXPECT_EQ(s.materials[0].emission.z, 1.0f);
  ASSERT_TRUE(s.environment.hasMap());
  for (float texel : s.environment.map.floats) EXPECT_LE(texel * s.environment.intensity, kMaxRadiance);

  SceneLoadOptions replaced;
  replaced.environmentPath = dir.file("max.hdr");
  Scene lit = loadScene(dir.file("lamp.obj"), replaced);
  ASSERT_TRUE(lit.environment.hasMap());
  EXPECT_EQ(lit.environment.map.floats[0], kMaxRadiance);
}

TEST(SceneRepair, SceneFileCamerasAndTransformsOutOfRangeFailWithOneLine) {
  TempFolder dir;
  dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  auto errorOf = [&](const std::string& json) {
    try {
      loadScene(dir.write("scene.json", json));
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string model = R"({"models": [{"file": "tri.obj"}], )";
  EXPECT_NE(errorOf(model + R"("camera": {"position": [3e38, 0, 0], "target": [0, 0, 0]}})")
                .find("scene.json: camera.position"),
            std::string::npos);
  EXPECT_NE(errorOf(model + R"("camera": {"position": [0, 0, 5], "target": [0, 0, 0], "aperture_radius": 1e30}})")
                .find("scene.json: camera.aperture_radius"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"models": [{"file": "tri.obj", "transform": {"scale": 1e-38}}]})")
                .find("scene.json: no instance is usable"),
            std::string::npos);
}

}  // namespace
}  // namespace candela
