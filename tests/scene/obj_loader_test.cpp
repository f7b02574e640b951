#include <gtest/gtest.h>

#include <stb/stb_image_write.h>

#include <cmath>
#include <set>

#include "scene/loaders/obj/obj_loader.h"
#include "scene/scene_test_files.h"

namespace candela {
namespace {

using test::TempFolder;

Scene loadText(const std::string& text, LoadWarnings& warnings) { return loadObjText("test.obj", text, warnings); }

Scene loadText(const std::string& text) {
  LoadWarnings warnings;
  return loadText(text, warnings);
}

// The message of the LoadError that loading `text` throws.
std::string errorOf(const std::string& text) {
  LoadWarnings warnings;
  try {
    loadText(text, warnings);
  } catch (const LoadError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a LoadError for:\n" << text;
  return {};
}

const char* kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";

TEST(ObjLoader, TriangulatesPolygonsAndKeepsWinding) {
  Scene s =
      loadText(std::string(kQuad) + "f 1 2 3 4 4\n" + "v 2 0 0\nv 3 0 0\nv 3 1 0\nv 2.5 1.5 0\nv 2 1 0\nf 5 6 7 8 9\n");
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  EXPECT_EQ(m.triangleCount(), 2u + 3u + 3u);
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    Vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
         c = m.positions[m.indices[3 * t + 2]];
    EXPECT_GE(cross(b - a, c - a).z, 0.0f) << "triangle " << t << " flipped";
  }
  EXPECT_TRUE(s.cameraMissing);
}

TEST(ObjLoader, RelativeIndicesAndCrlf) {
  Scene s = loadText("v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nf -4 -3 -2 -1\r\n");
  ASSERT_EQ(s.meshes[0].triangleCount(), 2u);
  EXPECT_EQ(s.meshes[0].positions.size(), 4u);
}

TEST(ObjLoader, SharesVerticesByPositionUvAndNormal) {
  Scene s = loadText(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\nvn 0 0 1\n"
      "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\nf 1/5/1 2/2/1 3/3/1\n");
  const Mesh& m = s.meshes[0];
  EXPECT_EQ(m.positions.size(), 5u);  // corner 1 appears with two different uvs
  ASSERT_EQ(m.uvs.size(), m.positions.size());
  ASSERT_EQ(m.normals.size(), m.positions.size());
  // OBJ's v runs up the image, the mesh convention down: vt (1, 0) is the bottom right.
  EXPECT_FLOAT_EQ(m.uvs[m.indices[1]].x, 1.0f);
  EXPECT_FLOAT_EQ(m.uvs[m.indices[1]].y, 1.0f);
}

TEST(ObjLoader, GeneratesSmoothNormalsWithinSmoothingGroups) {
  // Two triangles folded by 90 degrees along the shared edge x = 1.
  const std::string fold = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 1 0 -1\nv 1 1 -1\n";
  Scene smooth = loadText(fold + "s 1\nf 1 2 3 4\nf 2 5 6 3\n");
  Scene flat = loadText(fold + "s off\nf 1 2 3 4\nf 2 5 6 3\n");
  // Smoothed: the vertices on the fold are shared, their normal halfway between the faces.
  EXPECT_EQ(smooth.meshes[0].positions.size(), 6u);
  bool foundHalfway = false;
  for (Vec3 n : smooth.meshes[0].normals) foundHalfway |= std::fabs(n.x - n.z) < 1e-5f && n.x > 0.5f;
  EXPECT_TRUE(foundHalfway);
  // Group 0 smooths only within the crease angle (45 degrees): the fold stays sharp.
  EXPECT_EQ(flat.meshes[0].positions.size(), 8u);
  for (Vec3 n : flat.meshes[0].normals) EXPECT_TRUE(std::fabs(n.z - 1.0f) < 1e-6f || std::fabs(n.x - 1.0f) < 1e-6f);
}

TEST(ObjLoader, CreaseAngleSmoothsGentleBends) {
  // Two faces 20 degrees apart with no smoothing group share their normals along the bend.
  float s = std::sin(20.0f * kPi / 180.0f), c = std::cos(20.0f * kPi / 180.0f);
  std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv " + std::to_string(1 + c) + " 0 " + std::to_string(-s) +
                     "\nv " + std::to_string(1 + c) + " 1 " + std::to_string(-s) + "\nf 1 2 3 4\nf 2 5 6 3\n";
  EXPECT_EQ(loadText(text).meshes[0].positions.size(), 6u);
}

TEST(ObjLoader, ErrorsNameFileAndLine) {
  std::string e = errorOf("v 0 0 0\nv 1 0 0\nv 1 1 0\n# comment\nf 1 2 7\n");
  EXPECT_EQ(e, "test.obj:5: vertex reference 7 but 3 vertices are defined before it") << e;
  EXPECT_NE(errorOf("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 0 1 2\n").find("test.obj:4: vertex reference 0"), std::string::npos);
  EXPECT_NE(errorOf("v 0 0 0\nv 1 0 0\nv 1 1 0\nf -4 -3 -2\n").find("test.obj:4:"), std::string::npos);
  EXPECT_EQ(errorOf("v 0 0 0\nv nan 0 0\nv 1 1 0\nf 1 2 3\n"), "test.obj:2: a coordinate is not a number");
  EXPECT_EQ(errorOf("v 0 0 0 # fine\nv 1 0 0\nv 1 1 0\nvn 0 0 1\nvn 0 0 1.#IND\nf 1 2 3\n"),
            "test.obj:5: a coordinate is not a number");
  EXPECT_EQ(errorOf("v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 1e39\nf 1//1 2//1 3//1\n"), "test.obj:4: non-finite normal");
  EXPECT_NE(errorOf("v 0 0 0\nv 1 0 0\nl 1 2\n").find("test.obj: has only line and point elements"), std::string::npos);
  EXPECT_NE(errorOf("# nothing\n").find("test.obj: has no faces"), std::string::npos);
  EXPECT_NE(errorOf("").find("test.obj: has no faces"), std::string::npos);
}

TEST(ObjLoader, SkinWeightsAreIgnoredWithAWarning) {
  LoadWarnings warnings;
  Scene s = loadText("v 0 0 0\nv 1 0 0\nvw 0 3e10 0.5\n  vw 1 2 0.5\nv 1 1 0\nf 1 2 3\n", warnings);
  EXPECT_EQ(s.meshes[0].positions.size(), 3u);
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_EQ(warnings.messages[0], "test.obj:3: 'vw' (skin weight) statements are ignored");
}

TEST(ObjLoader, MissingNormalReferencesAreAWarning) {
  LoadWarnings warnings;
  Scene s = loadText("v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n", warnings);
  EXPECT_EQ(s.meshes[0].normals.size(), 3u);
  ASSERT_EQ(warnings.messages.size(), 1u) << warnings.messages[0] << "\n" << warnings.messages[1];
  EXPECT_EQ(warnings.messages[0].rfind("test.obj:5: normal reference 2", 0), 0u) << warnings.messages[0];
}

TEST(ObjLoader, TruncatedFileIsRejectedOrLoadsWhatIsThere) {
  std::string full = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1 4/1/1\n";
  for (size_t n = 0; n < full.size(); ++n) {
    LoadWarnings warnings;
    try {
      Scene s = loadText(full.substr(0, n), warnings);
      validateScene(s);
    } catch (const LoadError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("test.obj", 0), 0u) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
  }
}

void writePng(const std::string& path, int w, int h, int channels) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::vector<uint8_t> pixels(size_t(w) * h * channels, 200);
  ASSERT_TRUE(stbi_write_png(path.c_str(), w, h, channels, pixels.data(), w * channels));
}

TEST(ObjLoader, MapsMtlMaterials) {
  TempFolder dir;
  writePng(dir.file("textures/albedo.png"), 4, 2, 3);
  writePng(dir.file("rough.png"), 2, 2, 1);
  dir.write("m.mtl",
            "newmtl matte\nKd 0.5 0.25 0.125\n"
            "newmtl shiny\nKd 0.1 0.1 0.1\nKs 0.5 0.5 0.5\nNs 200\n"
            "newmtl mirror\nKs 0.9 0.9 0.9\nillum 5\n"
            "newmtl glass\nNi 1.33\nTf 0.9 1 0.9\nillum 7\n"
            "newmtl pbr\nKd 1 1 1\nPr 0.3\nPm 1\nPc 0.5\nPcr 0.2\nmap_Pr rough.png\n"
            "newmtl lamp\nKd 0 0 0\nKe 5 4 3\n"
            "newmtl veil\nd 0.25\nmap_Kd textures\\albedo.png\n"
            "newmtl leaf\nmap_d rough.png\nmap_Kd missing.png\n");
  std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\n";
  for (const char* name : {"matte", "shiny", "mirror", "glass", "pbr", "lamp", "veil", "leaf"})
    obj += std::string("usemtl ") + name + "\nf 1 2 3\n";
  obj += "usemtl nonexistent\nf 1 2 3\n";
  LoadWarnings warnings;
  Scene s = loadObj(dir.write("m.obj", obj), warnings);
  ASSERT_EQ(s.materials.size(), 9u);  // eight from the library and the default for the unknown name
  const auto& m = s.materials;
  EXPECT_EQ(m[0].type, MaterialType::Diffuse);
  EXPECT_FLOAT_EQ(m[0].baseColor.y, 0.25f);
  EXPECT_EQ(m[1].type, MaterialType::BlinnPhong);
  EXPECT_FLOAT_EQ(m[1].shininess, 200.0f);
  EXPECT_EQ(m[2].type, MaterialType::Mirror);
  EXPECT_FLOAT_EQ(m[2].specularColor.x, 0.9f);
  EXPECT_EQ(m[3].type, MaterialType::Glass);
  EXPECT_FLOAT_EQ(m[3].ior, 1.33f);
  EXPECT_FLOAT_EQ(m[3].baseColor.x, 0.9f);
  EXPECT_EQ(m[4].type, MaterialType::Disney);
  EXPECT_FLOAT_EQ(m[4].roughness, 0.3f);
  EXPECT_FLOAT_EQ(m[4].metallic, 1.0f);
  EXPECT_FLOAT_EQ(m[4].clearcoat, 0.5f);
  EXPECT_FLOAT_EQ(m[4].clearcoatGloss, 0.8f);
  EXPECT_FLOAT_EQ(m[5].emission.x, 5.0f);
  EXPECT_EQ(m[6].alphaMode, AlphaMode::Blend);
  EXPECT_FLOAT_EQ(m[6].opacity, 0.25f);
  EXPECT_EQ(m[7].alphaMode, AlphaMode::Mask);

  // Two textures: albedo (sRGB RGBA) and rough.png (linear grey, used by map_Pr and map_d); the missing one
  // is a warning and leaves the material untextured.
  ASSERT_EQ(s.textures.size(), 2u);
  const Texture& albedo = s.textures[size_t(m[6].baseColorTexture)];
  EXPECT_EQ(albedo.width, 4u);
  EXPECT_EQ(albedo.height, 2u);
  EXPECT_EQ(albedo.channels, 4u);
  EXPECT_TRUE(albedo.srgb);
  EXPECT_EQ(m[4].roughnessTexture, m[7].opacityTexture);
  EXPECT_EQ(s.textures[size_t(m[4].roughnessTexture)].channels, 1u);
  EXPECT_EQ(m[7].baseColorTexture, kNoTexture);
  std::string all;
  for (const auto& w : warnings.messages) all += w + "\n";
  EXPECT_NE(all.find("missing.png"), std::string::npos) << all;
  EXPECT_NE(all.find("nonexistent"), std::string::npos) << all;
  validateScene(s);
}

TEST(ObjLoader, MissingMaterialLibraryIsAWarning) {
  TempFolder dir;
  LoadWarnings warnings;
  Scene s = loadObj(dir.write("a.obj", std::string("mtllib nowhere.mtl\nusemtl red\n") + kQuad), warnings);
  EXPECT_EQ(s.materials.size(), 1u);
  ASSERT_FALSE(warnings.messages.empty());
  EXPECT_NE(warnings.messages[0].find("nowhere.mtl"), std::string::npos);
  EXPECT_EQ(warnings.messages[0].rfind(dir.file("a.obj"), 0), 0u);
}

TEST(ObjLoader, MissingFileIsAnError) {
  LoadWarnings warnings;
  EXPECT_THROW(loadObj("/nonexistent/x.obj", warnings), LoadError);
}

// ../shared/scenes/obj_edge_cases: tinyobjloader's own test files.
TEST(ObjLoaderSharedScenes, EdgeCases) {
  CANDELA_REQUIRE_SHARED_SCENES(scenes);
  // The deliberately invalid ones, and what a user should get: an error, or a warning and a render.
  const std::map<std::string, bool> invalidRejected = {
      {"invalid-face-definition.obj", true},
      {"invalid-relative-texture-index.obj", true},
      {"invalid-relative-vertex-index.obj", true},
      {"issue-140-zero-face-idx.obj", true},
      {"test-nan.obj", true},
      {"line-prim.obj", true},
      {"points-prim.obj", true},
      {"issue-356-leading-spaces-newmtl.obj", true},
      {"missing_material_file.obj", false},
      {"mtllib-multiple-files-issue-112.obj", false},
      {"issue-244-mtl-searchpaths.obj", false},
  };
  size_t valid = 0;
  for (const auto& entry : std::filesystem::directory_iterator(scenes / "obj_edge_cases/models")) {
    if (entry.path().extension() != ".obj") continue;
    std::string file = entry.path().filename().string();
    LoadWarnings warnings;
    auto invalid = invalidRejected.find(file);
    try {
      Scene s = loadObj(entry.path().string(), warnings);
      validateScene(s);
      EXPECT_FALSE(invalid != invalidRejected.end() && invalid->second) << file << " should have been rejected";
      if (invalid != invalidRejected.end()) {
        EXPECT_FALSE(warnings.messages.empty()) << file << " loaded silently";
      }
      if (invalid == invalidRejected.end()) ++valid;
      EXPECT_GT(s.triangleCount(), 0u) << file;
    } catch (const LoadError& e) {
      std::string what = e.what();
      EXPECT_TRUE(invalid != invalidRejected.end() && invalid->second) << file << ": " << what;
      EXPECT_EQ(what.rfind(entry.path().string(), 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  EXPECT_GE(valid, 30u);
}

TEST(ObjLoaderSharedScenes, EdgeCaseDetails) {
  CANDELA_REQUIRE_SHARED_SCENES(scenes);
  const auto models = scenes / "obj_edge_cases/models";
  LoadWarnings w;
  // Error messages name the line.
  try {
    loadObj((models / "issue-140-zero-face-idx.obj").string(), w);
    ADD_FAILURE();
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("issue-140-zero-face-idx.obj:16:"), std::string::npos) << e.what();
  }
  // A file name with spaces, and its material library with spaces.
  Scene spaces = loadObj((models / "mtl filename with whitespace issue46.obj").string(), w);
  EXPECT_GT(spaces.triangleCount(), 0u);
  // The PBR extension becomes Disney.
  Scene pbr = loadObj((models / "pbr-mat-ext.obj").string(), w);
  ASSERT_FALSE(pbr.materials.empty());
  EXPECT_EQ(pbr.materials[0].type, MaterialType::Disney);
  EXPECT_FLOAT_EQ(pbr.materials[0].roughness, 0.2f);
  EXPECT_FLOAT_EQ(pbr.materials[0].metallic, 0.3f);
  EXPECT_FLOAT_EQ(pbr.materials[0].anisotropic, 0.7f);
}

TEST(ObjLoaderSharedScenes, CornellBoxes) {
  CANDELA_REQUIRE_SHARED_SCENES(scenes);
  struct Expected {
    const char* file;
    size_t triangles;
    size_t materials;
  };
  for (Expected e : {Expected{"CornellBox-Original.obj", 36, 8}, Expected{"CornellBox-Mirror.obj", 36, 8},
                     Expected{"CornellBox-Sphere.obj", 2188, 8}, Expected{"CornellBox-Glossy.obj", 1112, 0},
                     Expected{"CornellBox-Water.obj", 7088, 0}, Expected{"CornellBox-Empty-RG.obj", 12, 0}}) {
    LoadWarnings w;
    Scene s = loadObj((scenes / "cornell_box" / e.file).string(), w);
    validateScene(s);
    EXPECT_EQ(s.triangleCount(), e.triangles) << e.file;
    if (e.materials) {
      EXPECT_EQ(s.materials.size(), e.materials) << e.file;
    }
    size_t emissive = 0;
    for (const Material& m : s.materials) emissive += !isBlack(m.emission);
    EXPECT_EQ(emissive, 1u) << e.file;
  }
  LoadWarnings w;
  Scene sphere = loadObj((scenes / "cornell_box/CornellBox-Sphere.obj").string(), w);
  std::set<MaterialType> types;
  for (const Material& m : sphere.materials) types.insert(m.type);
  EXPECT_TRUE(types.count(MaterialType::Mirror));
  EXPECT_TRUE(types.count(MaterialType::Glass));
}

}  // namespace
}  // namespace candela
