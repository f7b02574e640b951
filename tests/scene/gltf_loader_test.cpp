#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <limits>
#include <set>

#include "app/scene_loading.h"
#include "io/available_memory.h"
#include "io/file_bytes.h"
#include "io/load_budget.h"
#include "kernel/bsdf/ggx.h"
#include "scene/loaders/gltf/gltf_draco.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/loaders/gltf/gltf_specular_glossiness.h"
#include "scene/scene_test_files.h"
#include "scene/webp_test_image.h"
#include "support/glb_file.h"

namespace candela {
namespace {

using nlohmann::json;
using test::TempFolder;

std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = uint32_t(bytes[i]) << 16 | (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0) |
                 (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[v & 63] : '=';
  }
  return out;
}

template <class T>
void append(std::vector<uint8_t>& bytes, const std::vector<T>& values) {
  size_t at = bytes.size();
  bytes.resize(at + values.size() * sizeof(T));
  std::memcpy(bytes.data() + at, values.data(), values.size() * sizeof(T));
}

// A glTF with one triangle mesh (positions, normals, uvs, indices in one data-URI buffer) and whatever nodes,
// materials and extensions a test adds.
json triangleGltf() {
  std::vector<uint8_t> buffer;
  append(buffer, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});  // 36 bytes of positions
  append(buffer, std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1});  // normals
  append(buffer, std::vector<float>{0, 0, 1, 0, 0, 1});           // 24 bytes of uvs
  append(buffer, std::vector<uint16_t>{0, 1, 2});                 // 6 bytes of indices
  return {
      {"asset", {{"version", "2.0"}}},
      {"buffers", {{{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 72}},
        {{"buffer", 0}, {"byteOffset", 72}, {"byteLength", 24}},
        {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 6}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
        {{"bufferView", 0}, {"byteOffset", 36}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}},
        {{"bufferView", 2}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
      {"meshes",
       {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}}, {"indices", 3}}}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"scenes", {{{"nodes", {0}}}}},
  };
}

Scene load(const json& gltf, LoadWarnings& warnings) {
  std::string text = gltf.dump();
  return loadGltfBytes("test.gltf", reinterpret_cast<const uint8_t*>(text.data()), text.size(), warnings);
}

Scene load(const json& gltf) {
  LoadWarnings warnings;
  return load(gltf, warnings);
}

std::string errorOf(const std::string& text) {
  LoadWarnings warnings;
  try {
    loadGltfBytes("test.gltf", reinterpret_cast<const uint8_t*>(text.data()), text.size(), warnings);
  } catch (const LoadError& e) {
    std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what.rfind("test.gltf: ", 0), 0u) << what;
    return what;
  }
  ADD_FAILURE() << "expected a LoadError";
  return {};
}
std::string errorOf(const json& gltf) { return errorOf(gltf.dump()); }

TEST(GltfLoader, LoadsATriangle) {
  Scene s = load(triangleGltf());
  ASSERT_EQ(s.meshes.size(), 1u);
  ASSERT_EQ(s.instances.size(), 1u);
  const Mesh& m = s.meshes[0];
  EXPECT_EQ(m.triangleCount(), 1u);
  EXPECT_EQ(m.normals.size(), 3u);
  EXPECT_EQ(m.uvs.size(), 3u);
  EXPECT_FLOAT_EQ(m.positions[1].x, 1.0f);
  ASSERT_EQ(s.materials.size(), 1u);  // glTF's default material
  EXPECT_EQ(s.materials[0].type, MaterialType::Pbr);
  EXPECT_FLOAT_EQ(s.materials[0].metallic, 1.0f);
  EXPECT_TRUE(s.cameraMissing);
  validateScene(s);
}

TEST(GltfLoader, SharedMeshesBecomeInstancesEvenWhenMirrored) {
  json g = triangleGltf();
  g["nodes"] = {{{"mesh", 0}, {"translation", {5, 0, 0}}},
                {{"children", {2}}, {"scale", {2, 2, 2}}},
                {{"mesh", 0}, {"translation", {0, 1, 0}}},
                {{"mesh", 0}, {"scale", {-1, 1, 1}}},
                {{"mesh", 0}, {"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}}};
  g["scenes"] = {{{"nodes", {0, 1, 3, 4}}}};
  Scene s = load(g);
  ASSERT_EQ(s.instances.size(), 4u);
  ASSERT_EQ(s.meshes.size(), 1u);
  // The child's transform composes with its parent's: scale 2 then translate (0, 1, 0) -> (0, 2, 0).
  EXPECT_FLOAT_EQ(s.instances[1].objectToWorld.point({0, 0, 0}).y, 2.0f);
  EXPECT_FLOAT_EQ(s.instances[1].objectToWorld.point({1, 0, 0}).x, 2.0f);
  // Both mirroring forms (TRS scale and matrix) flip x.
  EXPECT_FLOAT_EQ(s.instances[2].objectToWorld.point({1, 0, 0}).x, -1.0f);
  EXPECT_FLOAT_EQ(s.instances[3].objectToWorld.point({1, 0, 0}).x, -1.0f);
}

TEST(GltfLoader, CameraLightsAndMaterials) {
  json g = triangleGltf();
  g["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
  g["nodes"] = {{{"mesh", 0}},
                {{"camera", 0}, {"translation", {0, 0, 3}}},
                {{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}};
  g["scenes"] = {{{"nodes", {0, 1, 2}}}};
  g["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}}}}}}};
  g["materials"] = {{{"emissiveFactor", {1, 0.5, 0.25}},
                     {"alphaMode", "MASK"},
                     {"alphaCutoff", 0.3},
                     {"doubleSided", true},
                     {"pbrMetallicRoughness",
                      {{"baseColorFactor", {0.5, 0.6, 0.7, 0.8}}, {"metallicFactor", 0.1}, {"roughnessFactor", 0.2}}},
                     {"extensions",
                      {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}},
                       {"KHR_materials_transmission", {{"transmissionFactor", 0.9}}},
                       {"KHR_materials_ior", {{"ior", 1.4}}},
                       {"KHR_materials_clearcoat", {{"clearcoatFactor", 0.7}, {"clearcoatRoughnessFactor", 0.25}}}}}}};
  g["meshes"][0]["primitives"][0]["material"] = 0;
  LoadWarnings warnings;
  Scene s = load(g, warnings);
  EXPECT_FALSE(s.cameraMissing);
  EXPECT_FLOAT_EQ(s.camera.eye.z, 3.0f);
  EXPECT_FLOAT_EQ(s.camera.target.z, 2.0f);
  EXPECT_NEAR(s.camera.verticalFovDegrees, 0.5f * 180.0f / kPi, 1e-4f);
  ASSERT_EQ(s.materials.size(), 1u);
  const Material& m = s.materials[0];
  EXPECT_EQ(m.type, MaterialType::Disney);
  EXPECT_FLOAT_EQ(m.emission.x, 4.0f);
  EXPECT_FLOAT_EQ(m.emission.z, 1.0f);
  EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
  EXPECT_EQ(m.doubleSided, 1u);
  EXPECT_FLOAT_EQ(m.opacity, 0.8f);
  EXPECT_FLOAT_EQ(m.metallic, 0.1f);
  EXPECT_FLOAT_EQ(m.specTrans, 0.9f);
  EXPECT_FLOAT_EQ(m.ior, 1.4f);
  EXPECT_FLOAT_EQ(m.clearcoat, 0.7f);
  EXPECT_FLOAT_EQ(m.clearcoatGloss, 0.75f);
  ASSERT_EQ(s.punctualLights.size(), 1u);
  EXPECT_EQ(s.punctualLights[0].type, PunctualLightType::Point);
  EXPECT_FLOAT_EQ(s.punctualLights[0].intensity.y, 1.0f);  // glTF's default colour and intensity
}

// An orthographic camera views ymag to either side of its axis vertically; one without a usable ymag, or of another
// type, is skipped with a warning that names it, and the next camera is taken.
TEST(GltfLoader, OrthographicCameras) {
  json g = triangleGltf();
  g["cameras"] = {{{"type", "orthographic"}, {"orthographic", {{"xmag", 3}, {"ymag", 0}, {"znear", 0}, {"zfar", 9}}}},
                  {{"type", "orthographic"}, {"orthographic", {{"xmag", 3}, {"ymag", 2}, {"znear", 0}, {"zfar", 9}}}}};
  g["nodes"] = {{{"mesh", 0}}, {{"camera", 0}}, {{"camera", 1}, {"translation", {0, 0, 5}}}};
  g["scenes"] = {{{"nodes", {0, 1, 2}}}};
  LoadWarnings warnings;
  Scene s = load(g, warnings);
  EXPECT_EQ(s.camera.projection, Projection::Orthographic);
  EXPECT_FLOAT_EQ(s.camera.orthographicHalfHeight, 2.0f);
  EXPECT_FLOAT_EQ(s.camera.eye.z, 5.0f);
  ASSERT_EQ(s.cameras.size(), 1u);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("cameras[0]: orthographic ymag must be positive"), std::string::npos)
      << warnings.messages[0];
  // Rays leave the image rectangle in parallel: 2 x (2 x aspect) world units at the camera.
  const Camera camera = s.camera.toCamera(1.5f);
  EXPECT_TRUE(camera.orthographic);
  EXPECT_NEAR(length(camera.up), 2.0f, 1e-5f);
  EXPECT_NEAR(length(camera.right), 3.0f, 1e-5f);
}

// KHR_lights_punctual: each kind, placed by its node (at the origin, shining along -Z), with its colour,
// intensity and cone; a range is ignored with a warning.
TEST(GltfLoader, PunctualLightsArePlacedByTheirNodes) {
  json g = triangleGltf();
  const float s2 = std::sqrt(0.5f);
  g["nodes"] = {{{"mesh", 0}},
                {{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
                {{"rotation", {-s2, 0, 0, s2}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}},
                {{"translation", {0, 5, 0}},
                 {"rotation", {-s2, 0, 0, s2}},
                 {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}}};
  g["scenes"] = {{{"nodes", {0, 1, 2, 3}}}};
  g["extensions"] = {{"KHR_lights_punctual",
                      {{"lights",
                        {{{"type", "point"}, {"color", {1, 0.5, 0}}, {"intensity", 10}, {"range", 4}},
                         {{"type", "directional"}, {"intensity", 3}},
                         {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}}}}}}};
  LoadWarnings warnings;
  Scene s = load(g, warnings);
  ASSERT_EQ(s.punctualLights.size(), 3u);
  const PunctualLight &point = s.punctualLights[0], &sun = s.punctualLights[1], &spot = s.punctualLights[2];
  EXPECT_EQ(point.type, PunctualLightType::Point);
  EXPECT_FLOAT_EQ(point.position.z, 3.0f);
  EXPECT_FLOAT_EQ(point.intensity.x, 10.0f);
  EXPECT_FLOAT_EQ(point.intensity.y, 5.0f);
  EXPECT_EQ(sun.type, PunctualLightType::Directional);
  EXPECT_NEAR(sun.direction.y, -1.0f, 1e-6f);  // -Z turned by -90 degrees about X points down
  EXPECT_EQ(spot.type, PunctualLightType::Spot);
  EXPECT_FLOAT_EQ(spot.position.y, 5.0f);
  EXPECT_NEAR(spot.direction.y, -1.0f, 1e-6f);
  EXPECT_NEAR(spot.cosInner, std::cos(0.2f), 1e-6f);
  EXPECT_NEAR(spot.cosOuter, std::cos(0.5f), 1e-6f);
  bool rangeWarning = false;
  for (const auto& w : warnings.messages) rangeWarning |= w.find("have a range, which is ignored") != std::string::npos;
  EXPECT_TRUE(rangeWarning);
}

TEST(GltfLoader, UniformTextureTransformIsBakedIntoUvs) {
  json g = triangleGltf();
  std::vector<uint8_t> png = readFileBytes(std::string(CANDELA_SOURCE_DIR) + "/tests/scene/data/checker.png");
  g["images"] = {{{"uri", "data:image/png;base64," + base64(png)}}};
  g["textures"] = {{{"source", 0}}};
  json transform = {{"KHR_texture_transform", {{"offset", {0.5, 0}}, {"scale", {2, 2}}}}};
  g["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"extensions", transform}}}}}}};
  g["meshes"][0]["primitives"][0]["material"] = 0;
  Scene s = load(g);
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.materials[0].baseColorTexture, 0);
  EXPECT_TRUE(s.textures[0].srgb);
  // uv (1, 0) -> scale (2, 0) -> offset (2.5, 0).
  EXPECT_FLOAT_EQ(s.meshes[0].uvs[1].x, 2.5f);
  EXPECT_FLOAT_EQ(s.meshes[0].uvs[2].y, 2.0f);
}

// EXT_texture_webp: the texture's image is the extension's source, whether or not `source` names a fallback.
TEST(GltfLoader, WebpTexturesAreTheExtensionsSource) {
  TempFolder dir;
  const std::vector<uint8_t> webp = test::losslessWebp({200, 100, 50, 255}, 1, 1);
  dir.write("colour.webp", std::string(webp.begin(), webp.end()));
  std::filesystem::copy_file(std::string(CANDELA_SOURCE_DIR) + "/tests/scene/data/checker.png", dir.file("c.png"));
  json g = triangleGltf();
  g["images"] = {{{"uri", "c.png"}}, {{"uri", "colour.webp"}}};
  g["textures"] = {{{"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}}};
  g["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  g["meshes"][0]["primitives"][0]["material"] = 0;
  g["extensionsUsed"] = g["extensionsRequired"] = {"EXT_texture_webp"};
  for (bool fallback : {false, true}) {
    if (fallback) g["textures"][0]["source"] = 0;
    LoadWarnings warnings;
    Scene s = loadGltf(dir.write("a.gltf", g.dump()), warnings);
    EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.materials[0].baseColorTexture, 0);
    ASSERT_EQ(s.textures[0].width, 1u);
    EXPECT_EQ(s.textures[0].bytes[0], 200);
    EXPECT_EQ(s.textures[0].bytes[1], 100);
  }
}

TEST(GltfLoader, SamplerWrapModesArePerAxis) {
  json g = triangleGltf();
  std::vector<uint8_t> png = readFileBytes(std::string(CANDELA_SOURCE_DIR) + "/tests/scene/data/checker.png");
  g["images"] = {{{"uri", "data:image/png;base64," + base64(png)}}};
  g["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}}};  // clamp to edge across, mirrored repeat down
  g["textures"] = {{{"source", 0}, {"sampler", 0}}};
  g["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  g["meshes"][0]["primitives"][0]["material"] = 0;
  Scene s = load(g);
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.textures[0].wrapU, TextureWrap::Clamp);
  EXPECT_EQ(s.textures[0].wrapV, TextureWrap::Mirror);
}

TEST(GltfLoader, RequiredExtensionsCandelaLacksStopTheLoadNamingThem) {
  // As a meshopt-compressed file looks: the accessors' bufferViews hold compressed data.
  json g = triangleGltf();
  g["bufferViews"][0]["extensions"] = {{"KHR_meshopt_compression", {{"buffer", 0}, {"byteLength", 72}}}};
  g["extensionsUsed"] = {"KHR_meshopt_compression", "KHR_texture_transform"};
  g["extensionsRequired"] = {"KHR_meshopt_compression", "KHR_texture_transform"};
  std::string e = errorOf(g);
  EXPECT_NE(e.find("requires the glTF extension KHR_meshopt_compression, which candela does not support"),
            std::string::npos)
      << e;
  EXPECT_EQ(e.find("KHR_texture_transform"), std::string::npos) << e;

  // As a Draco-compressed file looks: the accessors have no bufferView, the data are in the extension. A build
  // without Draco refuses it, saying so; one with Draco reads the extension's data.
  g = triangleGltf();
  for (json& a : g["accessors"]) a.erase("bufferView");
  g["meshes"][0]["primitives"][0]["extensions"] = {
      {"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
  g["extensionsUsed"] = g["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  e = errorOf(g);
  EXPECT_EQ(e.find("accessor"), std::string::npos) << e;
  if (gltfDracoAvailable())
    EXPECT_NE(e.find("KHR_draco_mesh_compression: the Draco data cannot be decoded"), std::string::npos) << e;
  else
    EXPECT_NE(e.find("requires the glTF extension KHR_draco_mesh_compression, which this build of candela does not "
                     "support: it was built without Draco"),
              std::string::npos)
        << e;

  g = triangleGltf();
  g["extensionsUsed"] = {"KHR_texture_basisu", "KHR_mesh_quantization"};
  LoadWarnings warnings;
  load(g, warnings);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("uses the glTF extension KHR_texture_basisu"), std::string::npos)
      << warnings.messages[0];
}

// A meshopt-compressed file without fallback data: the buffer the decoder would fill has no URI. The refusal names
// the extension, not the buffer.
TEST(GltfLoader, RequiredExtensionIsNamedBeforeABufferWithoutUri) {
  json g = triangleGltf();
  g["buffers"].push_back({{"byteLength", 72}});
  g["bufferViews"][0] = {{"buffer", 1},
                         {"byteLength", 72},
                         {"extensions", {{"KHR_meshopt_compression", {{"buffer", 0}, {"byteLength", 72}}}}}};
  g["extensionsUsed"] = g["extensionsRequired"] = {"KHR_meshopt_compression"};
  TempFolder dir;
  const std::string file = dir.write("meshopt.gltf", g.dump());
  LoadWarnings warnings;
  try {
    loadGltf(file, warnings);
    ADD_FAILURE() << "expected a LoadError";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("requires the glTF extension KHR_meshopt_compression"), std::string::npos)
        << e.what();
  }
}

// KHR_materials_variants (which Blender lists as required): the primitives' default materials are rendered.
TEST(GltfLoader, MaterialVariantsRenderTheDefaultMaterials) {
  json g = triangleGltf();
  g["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.2, 0.3, 1}}}}},
                    {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.8, 0.7, 1}}}}}};
  json& primitive = g["meshes"][0]["primitives"][0];
  primitive["material"] = 0;
  primitive["extensions"] = {{"KHR_materials_variants", {{"mappings", {{{"material", 1}, {"variants", {0}}}}}}}};
  g["extensions"] = {{"KHR_materials_variants", {{"variants", {{{"name", "other"}}}}}}};
  g["extensionsUsed"] = g["extensionsRequired"] = {"KHR_materials_variants"};
  LoadWarnings warnings;
  Scene s = load(g, warnings);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("KHR_materials_variants: each primitive's default material is rendered"),
            std::string::npos)
      << warnings.messages[0];
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_FLOAT_EQ(s.materials[s.meshes[0].triangleMaterials[0]].baseColor.x, 0.1f);
}

TEST(GltfLoader, BufferWithoutUriInAGltfIsNamedSo) {
  json g = triangleGltf();
  g["buffers"][0].erase("uri");
  TempFolder dir;
  LoadWarnings warnings;
  try {
    loadGltf(dir.write("no-uri.gltf", g.dump()), warnings);
    ADD_FAILURE() << "expected a LoadError";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("no-uri.gltf: a buffer has no 'uri'"), std::string::npos) << e.what();
  }
}

// Buffers are charged to the load's memory budget at their byteLength before tinygltf reads any of them: a file
// that claims more than the load may use is refused in one line naming the buffer, with nothing allocated.
TEST(GltfLoader, BuffersBeyondTheLoadBudgetAreRefusedBeforeTheyAreRead) {
  setProcessMemoryLimit(uint64_t(1) << 30);
  beginLoadBudget();
  const uint64_t left = loadMemoryLeft();
  load(triangleGltf());
  EXPECT_EQ(loadMemoryLeft(), left);  // a loaded model's buffers are given back with the model

  // An external buffer of 2 GiB (a sparse file: no disk taken), more than the budget of half of --max-memory.
  TempFolder dir;
  const std::string bin = dir.write("large.bin", "");
  std::filesystem::resize_file(bin, uint64_t(2) << 30);
  json g = triangleGltf();
  g["buffers"].push_back({{"byteLength", uint64_t(2) << 30}, {"uri", "large.bin"}});
  LoadWarnings warnings;
  std::string error = "(no error)";
  try {
    loadGltf(dir.write("large.gltf", g.dump()), warnings);
  } catch (const LoadError& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("large.gltf: buffers[1] needs about 2.0 GiB"), std::string::npos) << error;
  EXPECT_NE(error.find("--max-memory"), std::string::npos) << error;

  // A data: URI that claims a terabyte.
  g = triangleGltf();
  g["buffers"][0]["byteLength"] = uint64_t(1) << 40;
  error = errorOf(g);
  EXPECT_NE(error.find("test.gltf: buffers[0] (a data: URI) needs about 1024.0 GiB"), std::string::npos) << error;

  // With no room at all, even the triangle's own data: URI is refused.
  setProcessMemoryLimit(1);
  beginLoadBudget();
  error = errorOf(triangleGltf());
  EXPECT_NE(error.find("test.gltf: buffers[0] (a data: URI) needs about"), std::string::npos) << error;
  setProcessMemoryLimit(0);
  beginLoadBudget();
}

// A .glb whose BIN buffer has a byteLength of 0: tinygltf reads the first byte of the empty buffer, which throws;
// the load stops with one line naming the file.
TEST(GltfLoader, GlbBufferOfNoBytesIsOneLine) {
  const std::vector<uint8_t> file =
      test::glbFile({{"asset", {{"version", "2.0"}}}, {"buffers", {{{"byteLength", 0}}}}}, {0, 0, 0, 0});
  LoadWarnings warnings;
  try {
    loadGltfBytes("test.glb", file.data(), file.size(), warnings);
    ADD_FAILURE() << "expected a LoadError";
  } catch (const LoadError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("test.glb: ", 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

// KHR_mesh_quantization: integer positions (not normalised, scaled by the node), normalised byte normals and
// normalised unsigned-short texture coordinates.
TEST(GltfLoader, QuantizedAttributes) {
  std::vector<uint8_t> buffer;
  append(buffer, std::vector<uint16_t>{0, 0, 0, 0, 100, 0, 0, 0, 0, 100, 0, 0});  // 3 x (x, y, z, pad): 24 bytes
  append(buffer, std::vector<int8_t>{0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127, 0});  // 12 bytes
  append(buffer, std::vector<uint16_t>{0, 0, 65535, 0, 0, 65535});                // 12 bytes
  json g = triangleGltf();
  g["buffers"][0] = {{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}};
  g["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 24}, {"byteStride", 8}},
                      {{"buffer", 0}, {"byteOffset", 24}, {"byteLength", 12}, {"byteStride", 4}},
                      {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 12}}};
  g["accessors"] = {{{"bufferView", 0}, {"componentType", 5123}, {"count", 3}, {"type", "VEC3"}},
                    {{"bufferView", 1}, {"componentType", 5120}, {"normalized", true}, {"count", 3}, {"type", "VEC3"}},
                    {{"bufferView", 2}, {"componentType", 5123}, {"normalized", true}, {"count", 3}, {"type", "VEC2"}}};
  g["meshes"][0]["primitives"][0].erase("indices");
  g["nodes"][0]["scale"] = {0.01, 0.01, 0.01};
  g["extensionsUsed"] = g["extensionsRequired"] = {"KHR_mesh_quantization"};
  Scene s = load(g);
  validateScene(s);
  const Mesh& m = s.meshes[0];
  EXPECT_FLOAT_EQ(m.positions[1].x, 100.0f);
  EXPECT_FLOAT_EQ(m.normals[2].z, 1.0f);
  EXPECT_FLOAT_EQ(m.uvs[1].x, 1.0f);
  EXPECT_FLOAT_EQ(s.instances[0].objectToWorld.point(m.positions[2]).y, 1.0f);
}

TEST(GltfLoader, SparseAccessorsReplaceTheListedElements) {
  json g = triangleGltf();
  std::vector<uint8_t> buffer = [] {
    std::vector<uint8_t> b;
    append(b, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});  // the base positions
    append(b, std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1});  // normals
    append(b, std::vector<float>{0, 0, 1, 0, 0, 1});
    append(b, std::vector<uint16_t>{0, 1, 2, 2});  // indices, padded to 8 bytes
    append(b, std::vector<uint8_t>{2, 0, 0, 0});   // sparse indices: element 2
    append(b, std::vector<float>{0, 5, 0});        // its new value
    return b;
  }();
  g["buffers"][0] = {{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}};
  g["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 104}, {"byteLength", 4}});
  g["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 108}, {"byteLength", 12}});
  json sparse = {{"count", 1},
                 {"indices", {{"bufferView", 3}, {"componentType", 5121}}},
                 {"values", {{"bufferView", 4}}}};
  g["accessors"][0]["sparse"] = sparse;
  Scene s = load(g);
  EXPECT_FLOAT_EQ(s.meshes[0].positions[2].y, 5.0f);
  EXPECT_FLOAT_EQ(s.meshes[0].positions[1].x, 1.0f);

  // Without a bufferView the base is zeros.
  g["accessors"][0].erase("bufferView");
  s = load(g);
  EXPECT_FLOAT_EQ(s.meshes[0].positions[1].x, 0.0f);
  EXPECT_FLOAT_EQ(s.meshes[0].positions[2].y, 5.0f);

  g["accessors"][0]["sparse"]["count"] = 4;
  EXPECT_NE(errorOf(g).find("sparse: count 4 is not within the accessor's 3"), std::string::npos);
  g["accessors"][0]["sparse"]["count"] = 1;
  g["accessors"][0]["count"] = 1u << 30;
  EXPECT_NE(errorOf(g).find("without a bufferView are more than candela reads"), std::string::npos);
}

TEST(GltfLoader, TexturesReadingTexcoord1GetThatSet) {
  json g = triangleGltf();
  std::vector<uint8_t> png = readFileBytes(std::string(CANDELA_SOURCE_DIR) + "/tests/scene/data/checker.png");
  g["images"] = {{{"uri", "data:image/png;base64," + base64(png)}}};
  g["textures"] = {{{"source", 0}}};
  g["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}}}};
  g["meshes"][0]["primitives"][0]["material"] = 0;
  g["accessors"].push_back(
      {{"bufferView", 0}, {"byteOffset", 12}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}});
  g["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = 4;
  Scene s = load(g);
  // TEXCOORD_1 reads the positions from the second one on as pairs: (1, 0), (0, 0), (1, 0).
  EXPECT_FLOAT_EQ(s.meshes[0].uvs[0].x, 1.0f);
  EXPECT_FLOAT_EQ(s.meshes[0].uvs[2].x, 1.0f);
  EXPECT_FLOAT_EQ(s.meshes[0].uvs[2].y, 0.0f);

  // A transform naming a set the primitive lacks (here an absurd one) leaves the primitive untextured-by-uv,
  // with a warning, and nothing overflows.
  g["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {
      {"KHR_texture_transform", {{"texCoord", 1e300}}}};
  LoadWarnings warnings;
  s = load(g, warnings);
  EXPECT_TRUE(s.meshes[0].uvs.empty());
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("TEXCOORD_255, which the primitive lacks"), std::string::npos)
      << warnings.messages[0];
}

TEST(GltfLoader, VertexColoursAreLoaded) {
  json g = triangleGltf();
  std::vector<uint8_t> buffer;
  append(buffer, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
  append(buffer, std::vector<uint16_t>{0, 1, 2, 0});
  append(buffer, std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 128});  // normalised RGBA
  g["buffers"][0] = {{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}};
  g["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 104}, {"byteLength", 12}});
  g["accessors"].push_back(
      {{"bufferView", 3}, {"componentType", 5121}, {"normalized", true}, {"count", 3}, {"type", "VEC4"}});
  json coloured = g["meshes"][0]["primitives"][0];
  coloured["attributes"]["COLOR_0"] = 4;
  g["meshes"][0]["primitives"] = {coloured, g["meshes"][0]["primitives"][0]};  // the second has no colours
  LoadWarnings warnings;
  Scene s = load(g, warnings);
  validateScene(s);
  const Mesh& m = s.meshes[0];
  ASSERT_EQ(m.colors.size(), 6u);
  EXPECT_FLOAT_EQ(m.colors[0].x, 1.0f);
  EXPECT_FLOAT_EQ(m.colors[1].y, 1.0f);
  EXPECT_FLOAT_EQ(m.colors[2].x, 0.0f);
  EXPECT_FLOAT_EQ(m.colors[4].x, 1.0f);  // white where the primitive has none
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("COLOR_0: the alpha of vertex colours is ignored"), std::string::npos);
}

TEST(GltfLoader, GpuInstancingMakesAnInstancePerElement) {
  json g = triangleGltf();
  std::vector<uint8_t> buffer;
  append(buffer, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
  append(buffer, std::vector<uint16_t>{0, 1, 2, 0});
  append(buffer, std::vector<float>{0, 0, 0, 5, 0, 0, 0, 7, 0});  // translations
  append(buffer, std::vector<float>{1, 1, 1, 2, 2, 2, 1, 1, 1});  // scales
  g["buffers"][0] = {{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}};
  g["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 104}, {"byteLength", 72}});
  g["accessors"].push_back({{"bufferView", 3}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  g["accessors"].push_back(
      {{"bufferView", 3}, {"byteOffset", 36}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  g["nodes"][0]["translation"] = {0, 0, 10};
  g["nodes"][0]["extensions"] = {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", 4}, {"SCALE", 5}}}}}};
  g["extensionsUsed"] = g["extensionsRequired"] = {"EXT_mesh_gpu_instancing"};
  Scene s = load(g);
  ASSERT_EQ(s.meshes.size(), 1u);
  ASSERT_EQ(s.instances.size(), 3u);
  // Each instance's transform comes before the node's: vertex (1, 0, 0) of instance 1 is scaled by 2, moved by
  // (5, 0, 0), then by the node's (0, 0, 10).
  Vec3 p = s.instances[1].objectToWorld.point({1, 0, 0});
  EXPECT_FLOAT_EQ(p.x, 7.0f);
  EXPECT_FLOAT_EQ(p.z, 10.0f);
  EXPECT_FLOAT_EQ(s.instances[2].objectToWorld.point({0, 0, 0}).y, 7.0f);

  g["accessors"][5]["count"] = 2;
  EXPECT_NE(errorOf(g).find("the attributes have different counts"), std::string::npos);
}

TEST(GltfLoader, UnlitMaterialsEmitTheirBaseColour) {
  json g = triangleGltf();
  g["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1}}}},
                     {"extensions", {{"KHR_materials_unlit", json::object()}}}}};
  g["meshes"][0]["primitives"][0]["material"] = 0;
  g["extensionsUsed"] = {"KHR_materials_unlit"};
  LoadWarnings warnings;
  Scene s = load(g, warnings);
  EXPECT_TRUE(warnings.messages.empty());
  EXPECT_FLOAT_EQ(s.materials[0].emission.z, 0.6f);
  EXPECT_TRUE(isBlack(s.materials[0].baseColor));
}

// KHR_materials_volume: the absorption coefficient is -ln(attenuationColor) / attenuationDistance; a thickness
// of 0 (thin-walled) or no distance means none.
TEST(GltfLoader, VolumeAttenuationBecomesTheAbsorptionCoefficient) {
  json g = triangleGltf();
  json volume = {{"thicknessFactor", 0.5}, {"attenuationDistance", 2.0}, {"attenuationColor", {0.5, 1.0, 0.25}}};
  g["materials"] = {
      {{"extensions",
        {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}, {"KHR_materials_volume", volume}}}}};
  g["meshes"][0]["primitives"][0]["material"] = 0;
  g["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_volume"};
  LoadWarnings warnings;
  Scene s = load(g, warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  EXPECT_FLOAT_EQ(s.materials[0].absorption.x, std::log(2.0f) / 2.0f);
  EXPECT_FLOAT_EQ(s.materials[0].absorption.y, 0.0f);
  EXPECT_FLOAT_EQ(s.materials[0].absorption.z, std::log(4.0f) / 2.0f);

  g["materials"][0]["extensions"]["KHR_materials_volume"].erase("thicknessFactor");
  EXPECT_EQ(load(g).materials[0].absorption.x, 0.0f);
  g["materials"][0]["extensions"]["KHR_materials_volume"] = {{"thicknessFactor", 1.0},
                                                             {"attenuationColor", {0.5, 0.5, 0.5}}};
  EXPECT_EQ(load(g).materials[0].absorption.x, 0.0f);
  g["materials"][0]["extensions"]["KHR_materials_volume"] = {{"thicknessFactor", 1.0},
                                                             {"attenuationDistance", 1.0},
                                                             {"attenuationColor", {0.0, -1.0, 1e300}}};
  const Vec3 black = load(g).materials[0].absorption;
  EXPECT_FLOAT_EQ(black.x, -std::log(1e-6f));
  EXPECT_FLOAT_EQ(black.y, -std::log(1e-6f));
  EXPECT_EQ(black.z, 0.0f);
}

TEST(SpecularGlossiness, DielectricsAndMetalsConvertExactly) {
  // A 4% specular over a diffuse colour is a dielectric of that base colour.
  const MetallicRoughness plastic =
      metallicRoughnessFromSpecularGlossiness({0.5f, 0.2f, 0.1f}, {0.04f, 0.04f, 0.04f}, 0.75f);
  EXPECT_FLOAT_EQ(plastic.metallic, 0.0f);
  EXPECT_NEAR(plastic.baseColor.x, 0.5f, 1e-6f);
  EXPECT_NEAR(plastic.baseColor.z, 0.1f, 1e-6f);
  EXPECT_FLOAT_EQ(plastic.roughness, 0.25f);
  // Gold: no diffuse, a coloured specular: a metal whose base colour is the specular colour.
  const Vec3 gold{1.0f, 0.766f, 0.336f};
  const MetallicRoughness metal = metallicRoughnessFromSpecularGlossiness({0, 0, 0}, gold, 1.0f);
  EXPECT_NEAR(metal.metallic, 1.0f, 1e-4f);
  EXPECT_NEAR(metal.baseColor.y, gold.y, 1e-3f);
  EXPECT_NEAR(metal.baseColor.z, gold.z, 1e-3f);
  EXPECT_FLOAT_EQ(metal.roughness, 0.0f);
  // A specular below 4% is still a dielectric; out-of-range input is clamped.
  EXPECT_FLOAT_EQ(metallicRoughnessFromSpecularGlossiness({2, 2, 2}, {0.01f, 0.01f, 0.01f}, 3.0f).metallic, 0.0f);
  EXPECT_FLOAT_EQ(metallicRoughnessFromSpecularGlossiness({2, 2, 2}, {0.01f, 0.01f, 0.01f}, 3.0f).roughness, 0.0f);
}

TEST(GltfLoader, SpecularGlossinessMaterialsBecomeMetallicRoughness) {
  json g = triangleGltf();
  std::vector<uint8_t> png = readFileBytes(std::string(CANDELA_SOURCE_DIR) + "/tests/scene/data/checker.png");
  g["images"] = {{{"uri", "data:image/png;base64," + base64(png)}}};
  g["textures"] = {{{"source", 0}}};
  json plastic = {{"diffuseFactor", {0.5, 0.5, 0.5, 0.8}},
                  {"specularFactor", {0.04, 0.04, 0.04}},
                  {"glossinessFactor", 0.7},
                  {"diffuseTexture", {{"index", 0}}}};
  json gold = {{"diffuseFactor", {0, 0, 0, 1}}, {"specularFactor", {1.0, 0.766, 0.336}}, {"glossinessFactor", 0.9}};
  json glossMapped = {{"specularGlossinessTexture", {{"index", 0}}}};
  g["materials"] = json::array();
  for (const json& e : {plastic, gold, glossMapped})
    g["materials"].push_back({{"extensions", {{"KHR_materials_pbrSpecularGlossiness", e}}}});
  g["meshes"][0]["primitives"][0]["material"] = 0;
  g["extensionsUsed"] = {"KHR_materials_pbrSpecularGlossiness"};
  g["extensionsRequired"] = {"KHR_materials_pbrSpecularGlossiness"};
  LoadWarnings warnings;
  const Scene s = load(g, warnings);
  const Material& p = s.materials[0];
  EXPECT_EQ(p.type, MaterialType::Pbr);
  EXPECT_FLOAT_EQ(p.metallic, 0.0f);
  EXPECT_NEAR(p.roughness, 0.3f, 1e-6f);
  EXPECT_EQ(p.baseColorTexture, 0);  // the diffuse texture, whose mean the factor keeps at the converted colour
  EXPECT_NEAR(p.baseColor.x, 0.5f, 1e-5f);
  EXPECT_FLOAT_EQ(p.opacity, 0.8f);
  const Material& m = s.materials[1];
  EXPECT_NEAR(m.metallic, 1.0f, 1e-4f);
  EXPECT_NEAR(m.baseColor.z, 0.336f, 1e-3f);
  EXPECT_NEAR(m.roughness, 0.1f, 1e-6f);
  EXPECT_EQ(m.baseColorTexture, kNoTexture);
  EXPECT_EQ(m.metallicRoughnessTexture, kNoTexture);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("materials[2]: KHR_materials_pbrSpecularGlossiness.specularGlossinessTexture is "
                                      "reduced to its mean"),
            std::string::npos)
      << warnings.messages[0];
}

TEST(GltfLoader, AnisotropyStretchesTheLobeAlongTheTangentAsGltfDoes) {
  json g = triangleGltf();
  json slightly = {{"anisotropyStrength", 0.5}};
  json rotated = {{"anisotropyStrength", 1.0}, {"anisotropyRotation", 0.5}};
  json first = {{"pbrMetallicRoughness", {{"roughnessFactor", 0.4}}}};
  json second = {{"pbrMetallicRoughness", {{"roughnessFactor", 0.2}}}};
  first["extensions"]["KHR_materials_anisotropy"] = slightly;
  second["extensions"]["KHR_materials_anisotropy"] = rotated;
  g["materials"] = {first, second};
  g["meshes"][0]["primitives"][0]["material"] = 0;
  g["extensionsUsed"] = {"KHR_materials_anisotropy"};
  LoadWarnings warnings;
  const Scene s = load(g, warnings);
  const Material& m = s.materials[0];
  EXPECT_EQ(m.type, MaterialType::Disney);
  // glTF: alpha 0.16 across the tangent, mix(0.16, 1, 0.25) = 0.37 along it.
  const GgxDistribution lobe = GgxDistribution::anisotropic(m.roughness, m.anisotropic);
  EXPECT_NEAR(lobe.alphaX, 0.37f, 1e-5f);
  EXPECT_NEAR(lobe.alphaY, 0.16f, 1e-5f);
  // Alpha 0.04 across and 1 along the tangent is beyond Disney's widest stretch: the alpha along it is kept.
  const GgxDistribution widest = GgxDistribution::anisotropic(s.materials[1].roughness, s.materials[1].anisotropic);
  EXPECT_FLOAT_EQ(s.materials[1].anisotropic, 1.0f);
  EXPECT_NEAR(widest.alphaX, 1.0f, 1e-5f);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("materials[1]: KHR_materials_anisotropy.anisotropyRotation is ignored"),
            std::string::npos);
}

// KHR_materials_iridescence: factor, film index, thickness range and both textures (with the textures' texCoord
// and transform, which the material's other textures share), on the metallic-roughness model or on Disney where
// another extension maps there; defaults where the file gives none; no warning naming the extension.
TEST(GltfLoader, IridescenceIsReadWithItsTextures) {
  json g = triangleGltf();
  std::vector<uint8_t> png = readFileBytes(std::string(CANDELA_SOURCE_DIR) + "/tests/scene/data/checker.png");
  g["images"] = {{{"uri", "data:image/png;base64," + base64(png)}}};
  g["textures"] = {{{"source", 0}}, {{"source", 0}, {"sampler", 0}}};
  g["samplers"] = {{{"wrapS", 33071}}};
  const json transform = {{"KHR_texture_transform", {{"scale", {2, 2}}}}};
  json full = {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"extensions", transform}}}}}};
  full["extensions"]["KHR_materials_iridescence"] = {{"iridescenceFactor", 0.8},
                                                     {"iridescenceIor", 1.6},
                                                     {"iridescenceThicknessMinimum", 250},
                                                     {"iridescenceThicknessMaximum", 650},
                                                     {"iridescenceTexture", {{"index", 0}, {"extensions", transform}}},
                                                     {"iridescenceThicknessTexture",
                                                      {{"index", 1}, {"extensions", transform}}}};
  json defaults = {{"extensions", {{"KHR_materials_iridescence", {{"iridescenceFactor", 1}}}}}};
  json onDisney = {{"extensions",
                    {{"KHR_materials_iridescence", {{"iridescenceFactor", 0.5}, {"iridescenceIor", -3}}},
                     {"KHR_materials_clearcoat", {{"clearcoatFactor", 1}}}}}};
  json hostile = {{"extensions",
                   {{"KHR_materials_iridescence",
                     {{"iridescenceFactor", 7}, {"iridescenceThicknessMaximum", 1e300}, {"iridescenceTexture", 3}}}}}};
  g["materials"] = {full, defaults, onDisney, hostile};
  g["meshes"][0]["primitives"][0]["material"] = 0;
  g["extensionsUsed"] = {"KHR_materials_iridescence", "KHR_texture_transform", "KHR_materials_clearcoat"};
  LoadWarnings warnings;
  const Scene s = load(g, warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  ASSERT_EQ(s.materials.size(), 4u);
  const Material& m = s.materials[0];
  EXPECT_EQ(m.type, MaterialType::Pbr);
  EXPECT_FLOAT_EQ(m.iridescence, 0.8f);
  EXPECT_FLOAT_EQ(m.iridescenceIor, 1.6f);
  EXPECT_FLOAT_EQ(m.iridescenceThicknessMinimum, 250.0f);
  EXPECT_FLOAT_EQ(m.iridescenceThickness, 650.0f);
  ASSERT_NE(m.iridescenceTexture, kNoTexture);
  ASSERT_NE(m.iridescenceThicknessTexture, kNoTexture);
  // Single channels in linear space: the base colour's image is another texture for them.
  EXPECT_NE(m.iridescenceTexture, m.baseColorTexture);
  EXPECT_FALSE(s.textures[size_t(m.iridescenceTexture)].srgb);
  EXPECT_FALSE(s.textures[size_t(m.iridescenceThicknessTexture)].srgb);
  EXPECT_EQ(s.textures[size_t(m.iridescenceThicknessTexture)].wrapU, TextureWrap::Clamp);
  // The shared transform is baked into the uvs: (1, 0) becomes (2, 0).
  EXPECT_FLOAT_EQ(s.meshes[0].uvs[1].x, 2.0f);

  const Material& d = s.materials[1];
  EXPECT_FLOAT_EQ(d.iridescence, 1.0f);
  EXPECT_FLOAT_EQ(d.iridescenceIor, 1.3f);
  EXPECT_FLOAT_EQ(d.iridescenceThicknessMinimum, 100.0f);
  EXPECT_FLOAT_EQ(d.iridescenceThickness, 400.0f);
  EXPECT_EQ(d.iridescenceTexture, kNoTexture);
  EXPECT_EQ(d.iridescenceThicknessTexture, kNoTexture);

  EXPECT_EQ(s.materials[2].type, MaterialType::Disney);
  EXPECT_FLOAT_EQ(s.materials[2].iridescence, 0.5f);
  EXPECT_FLOAT_EQ(s.materials[2].iridescenceIor, 1.0f);  // an index below the outside's is taken as 1

  EXPECT_FLOAT_EQ(s.materials[3].iridescence, 1.0f);
  EXPECT_FLOAT_EQ(s.materials[3].iridescenceThickness, 1e5f);
  EXPECT_EQ(s.materials[3].iridescenceTexture, kNoTexture);  // not a textureInfo
}

TEST(GltfLoader, NonFiniteNormalsDoNotRejectTheFile) {
  json g = triangleGltf();
  std::vector<uint8_t> buffer;
  float nan = std::numeric_limits<float>::quiet_NaN();
  append(buffer, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, nan, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
  append(buffer, std::vector<uint16_t>{0, 1, 2});
  g["buffers"][0] = {{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}};
  Scene s = load(g);
  EXPECT_EQ(s.meshes[0].triangleCount(), 1u);
}

TEST(GltfLoader, BadInputNamesFileAndJsonPath) {
  EXPECT_NE(errorOf(std::string("{\"asset\": {\"version\": \"2.0\"")).find("test.gltf: "), std::string::npos);
  EXPECT_NE(errorOf(std::string("not json at all")).find("test.gltf: "), std::string::npos);
  EXPECT_NE(errorOf(std::string(100000, '[')).find("nests deeper"), std::string::npos);

  json g = triangleGltf();
  g["accessors"][0]["count"] = 1000;
  EXPECT_NE(errorOf(g).find("meshes[0].primitives[0].attributes.POSITION (accessors[0]): 1000 elements do not fit"),
            std::string::npos);
  g = triangleGltf();
  g["accessors"][3]["count"] = 3;
  g["bufferViews"][2]["byteLength"] = 6;
  g["meshes"][0]["primitives"][0]["indices"] = 7;
  std::string e = errorOf(g);
  EXPECT_NE(e.find("indices accessor out of bounds"), std::string::npos) << e;

  g = triangleGltf();
  std::vector<uint8_t> buffer;
  append(buffer, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
  append(buffer, std::vector<uint16_t>{0, 1, 9});
  g["buffers"][0] = {{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}};
  EXPECT_NE(errorOf(g).find("meshes[0].primitives[0].indices: index 9 (element 2) is beyond the 3 vertices"),
            std::string::npos);

  g = triangleGltf();
  g["bufferViews"][0]["byteLength"] = 1000;
  EXPECT_NE(errorOf(g).find("bufferViews[0]: byteOffset 0 and byteLength 1000 reach beyond the"), std::string::npos)
      << errorOf(g);

  g = triangleGltf();
  g["buffers"][0]["uri"] = "missing.bin";
  errorOf(g);

  g = triangleGltf();
  g["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
  EXPECT_NE(errorOf(g).find("meshes[0].primitives[0].attributes: POSITION is missing"), std::string::npos);

  g = triangleGltf();
  g["nodes"] = {{{"mesh", 0}, {"children", {0}}}};
  EXPECT_NE(errorOf(g).find("cycle"), std::string::npos);
}

// glTF meshes made of the same primitives are one mesh of the scene, instanced by every node that names one.
TEST(GltfLoader, MeshesOfTheSamePrimitivesAreOneMeshInstanced) {
  json g = triangleGltf();
  g["meshes"].push_back(g["meshes"][0]);
  g["nodes"] = {{{"mesh", 0}}, {{"mesh", 1}, {"translation", {2, 0, 0}}}};
  g["scenes"][0]["nodes"] = {0, 1};
  const Scene s = load(g);
  ASSERT_EQ(s.meshes.size(), 1u);
  ASSERT_EQ(s.instances.size(), 2u);
  EXPECT_EQ(s.instances[1].meshId, 0u);
  EXPECT_EQ(s.instances[1].objectToWorld.m[3], 2.0f);
}

// A primitive that repeats another's vertices, indices and mode adds nothing but memory: it is left out, and
// primitives that share vertex accessors share one copy of the vertices.
TEST(GltfLoader, RepeatedPrimitivesAreDrawnOnceAndSharedVerticesKeptOnce) {
  json g = triangleGltf();
  json primitive = g["meshes"][0]["primitives"][0];
  for (int i = 0; i < 3; ++i) g["meshes"][0]["primitives"].push_back(primitive);
  primitive["mode"] = 6;  // the same triangle as a fan
  g["meshes"][0]["primitives"].push_back(primitive);
  LoadWarnings warnings;
  const Scene s = load(g, warnings);
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].triangleCount(), 2u);
  EXPECT_EQ(s.meshes[0].positions.size(), 3u);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_EQ(warnings.messages[0],
            "test.gltf: meshes[0]: 3 primitives draw the triangles of an earlier primitive again and are left out");
}

TEST(GltfLoader, NegativeByteOffsetsAreRefused) {
  json g = triangleGltf();
  g["bufferViews"][1]["byteOffset"] = -4;
  EXPECT_EQ(errorOf(g), "test.gltf: bufferViews[1].byteOffset: -4 is not a whole number of bytes from 0");
  g = triangleGltf();
  g["accessors"][1]["byteOffset"] = -4;
  EXPECT_EQ(errorOf(g), "test.gltf: accessors[1].byteOffset: -4 is not a whole number of bytes from 0");
  g = triangleGltf();
  g["accessors"][1]["byteOffset"] = 4.5;
  EXPECT_EQ(errorOf(g), "test.gltf: accessors[1].byteOffset: 4.5 is not a whole number of bytes from 0");
}

// The camera --camera takes is held to the same limits as the first one.
TEST(GltfLoader, AChosenCameraIsCheckedLikeTheFirst) {
  TempFolder dir;
  json g = triangleGltf();
  g["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
  g["nodes"].push_back({{"camera", 0}, {"translation", {0, 0, 5}}});
  g["nodes"].push_back({{"camera", 0}, {"translation", {0, 0, 3e38}}});
  g["scenes"][0]["nodes"] = {0, 1, 2};
  const std::string file = dir.write("cameras.gltf", g.dump());
  SceneLoadOptions options;
  options.printWarnings = false;
  EXPECT_EQ(loadScene(file, options).camera.eye.z, 5.0f);
  options.camera = "1";
  try {
    loadScene(file, options);
    ADD_FAILURE() << "expected the far camera to be refused";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("camera.position: "), std::string::npos) << e.what();
  }
}

TEST(GltfLoader, MissingTextureIsAWarning) {
  TempFolder dir;
  json g = triangleGltf();
  g["images"] = {{{"uri", "nowhere.png"}}};
  g["textures"] = {{{"source", 0}}};
  g["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  g["meshes"][0]["primitives"][0]["material"] = 0;
  LoadWarnings warnings;
  Scene s = loadGltf(dir.write("a.gltf", g.dump()), warnings);
  EXPECT_TRUE(s.textures.empty());
  EXPECT_EQ(s.materials[0].baseColorTexture, kNoTexture);
  ASSERT_FALSE(warnings.messages.empty());
  EXPECT_NE(warnings.messages[0].find("nowhere.png"), std::string::npos);
}

TEST(GltfLoaderSharedScenes, DamagedHelmetGltfAndGlbAgree) {
  CANDELA_REQUIRE_SHARED_SCENES(scenes);
  LoadWarnings w1, w2;
  Scene glb = loadGltf((scenes / "damaged_helmet/glTF-Binary/DamagedHelmet.glb").string(), w1);
  Scene gltf = loadGltf((scenes / "damaged_helmet/glTF/DamagedHelmet.gltf").string(), w2);
  for (const Scene* s : {&glb, &gltf}) {
    validateScene(*s);
    EXPECT_EQ(s->triangleCount(), 15452u);
    EXPECT_EQ(s->materials.size(), 1u);
    EXPECT_EQ(s->textures.size(), 4u);  // albedo, metal-roughness, normal, emissive; occlusion is left out
    EXPECT_NE(s->materials[0].normalTexture, kNoTexture);
    EXPECT_NE(s->materials[0].emissionTexture, kNoTexture);
  }
  ASSERT_EQ(glb.meshes[0].positions.size(), gltf.meshes[0].positions.size());
  for (size_t i = 0; i < glb.meshes[0].positions.size(); i += 97)
    EXPECT_EQ(glb.meshes[0].positions[i].x, gltf.meshes[0].positions[i].x);
  for (size_t t = 0; t < glb.textures.size(); ++t) {
    EXPECT_EQ(glb.textures[t].width, gltf.textures[t].width);
    EXPECT_EQ(glb.textures[t].bytes, gltf.textures[t].bytes);
  }
}

TEST(GltfLoaderSharedScenes, MaterialTestModels) {
  CANDELA_REQUIRE_SHARED_SCENES(scenes);
  // Triangles drawn, as counted from the files' index accessors over the node graph (see SOURCES.md there).
  const std::map<std::string, size_t> triangles = {{"TextureCoordinateTest", 10},        {"TwoSidedPlane", 2},
                                                   {"EmissiveStrengthTest", 90},         {"NegativeScaleTest", 7724},
                                                   {"TextureSettingsTest", 72},          {"AlphaBlendModeTest", 61},
                                                   {"TransmissionTest", 128775},         {"SpecularTest", 44828},
                                                   {"TransmissionRoughnessTest", 77792}, {"NormalTangentTest", 7774},
                                                   {"NormalTangentMirrorTest", 5240}};
  size_t models = 0;
  for (const auto& entry : std::filesystem::directory_iterator(scenes / "gltf_material_tests")) {
    std::string name = entry.path().filename().string();
    LoadWarnings warnings;
    Scene s = loadGltf((entry.path() / "glTF" / (name + ".gltf")).string(), warnings);
    validateScene(s);
    ++models;
    auto expected = triangles.find(name);
    if (expected != triangles.end()) {
      EXPECT_EQ(s.triangleCount(), expected->second) << name;
    }
    std::set<MaterialType> types;
    for (const Material& m : s.materials) types.insert(m.type);
    if (name == "TransmissionTest" || name == "SpecularTest") {
      EXPECT_TRUE(types.count(MaterialType::Disney)) << name;
    }
    if (name == "EmissiveStrengthTest") {
      float brightest = 0;
      for (const Material& m : s.materials) brightest = std::max(brightest, maxComponent(m.emission));
      EXPECT_GT(brightest, 1.0f);
    }
    if (name == "AlphaBlendModeTest") {
      std::set<AlphaMode> modes;
      for (const Material& m : s.materials) modes.insert(m.alphaMode);
      EXPECT_EQ(modes.size(), 3u);
    }
    if (name == "MetalRoughSpheresNoTextures") {
      EXPECT_GT(s.instances.size(), 90u);
    }
  }
  EXPECT_EQ(models, 12u);
}

}  // namespace
}  // namespace candela
