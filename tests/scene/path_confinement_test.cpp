// Files that a model or scene file refers to must lie in its folder unless the user allows others: no mtllib,
// texture, buffer or model path, however written (../, absolute, percent-encoded, through a symbolic link),
// reads a file elsewhere.
#include <gtest/gtest.h>

#include <stb/stb_image_write.h>
#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/path_confinement.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/loaders/obj/obj_loader.h"
#include "scene/loaders/scene_file.h"
#include "scene/scene_test_files.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::TempFolder;

const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

std::string allOf(const LoadWarnings& warnings) {
  std::string all;
  for (const std::string& w : warnings.messages) all += w + "\n";
  return all;
}

void writePng(const std::string& path) {
  fs::create_directories(fs::path(path).parent_path());
  const uint8_t pixels[4] = {200, 200, 200, 200};
  ASSERT_TRUE(stbi_write_png(path.c_str(), 2, 2, 1, pixels, 2));
}

TEST(PathConfinement, ResolvesInsideAndRefusesOutside) {
  TempFolder dir;
  dir.write("model/a.png", "x");
  dir.write("secret.txt", "x");
  PathRule rule{dir.file("model"), OutsidePaths::Refused};
  EXPECT_TRUE(resolveModelPath(dir.file("model"), "a.png", rule).allowed());
  EXPECT_TRUE(resolveModelPath(dir.file("model/sub"), "../a.png", rule).allowed());
  EXPECT_TRUE(resolveModelPath(dir.file("model"), "textures\\new.png", rule).allowed());  // need not exist
  EXPECT_EQ(resolveModelPath(dir.file("model"), "textures\\new.png", rule).path, dir.file("model/textures/new.png"));
  ResolvedPath up = resolveModelPath(dir.file("model"), "../secret.txt", rule);
  EXPECT_FALSE(up.allowed());
  EXPECT_EQ(up.path, dir.file("secret.txt"));
  EXPECT_NE(up.refusal.find("leads to " + dir.file("secret.txt") + ", outside the folder " + dir.file("model")),
            std::string::npos)
      << up.refusal;
  EXPECT_NE(up.refusal.find("--allow-outside-paths"), std::string::npos);
  EXPECT_FALSE(resolveModelPath(dir.file("model"), "/etc/passwd", rule).allowed());
  EXPECT_FALSE(resolveModelPath(dir.file("model"), "..\\secret.txt", rule).allowed());
  EXPECT_FALSE(resolveModelPath(dir.file("model"), "", rule).allowed());
  EXPECT_FALSE(resolveModelPath(dir.file("model"), std::string("a.png\0/../../secret.txt", 22), rule).allowed());
  // A folder whose name starts like the model's is not inside it.
  dir.write("model2/b.png", "x");
  EXPECT_FALSE(resolveModelPath(dir.file("model"), "../model2/b.png", rule).allowed());
  // A symbolic link in the model's folder is followed to where it leads.
  fs::create_symlink(dir.file("secret.txt"), dir.file("model/link.png"));
  EXPECT_FALSE(resolveModelPath(dir.file("model"), "link.png", rule).allowed());
  fs::create_directory_symlink(dir.path(), dir.file("model/up"));
  EXPECT_FALSE(resolveModelPath(dir.file("model"), "up/secret.txt", rule).allowed());
  // The model's own folder may be reached through a link.
  fs::create_directory_symlink(dir.file("model"), dir.file("linked-model"));
  EXPECT_TRUE(
      resolveModelPath(dir.file("linked-model"), "a.png", {dir.file("linked-model"), OutsidePaths::Refused}).allowed());
  EXPECT_TRUE(resolveModelPath(dir.file("model"), "/etc/passwd", {dir.file("model"), OutsidePaths::Allowed}).allowed());
}

TEST(PathConfinement, UrisAreDecodedAsRfc3986Says) {
  EXPECT_EQ(uriToPath("textures/a%20b.png"), "textures/a b.png");
  EXPECT_EQ(uriToPath("a+b.png"), "a+b.png");  // '+' is a space only in query strings
  EXPECT_EQ(uriToPath("..%2f..%2Fsecret"), "../../secret");
  EXPECT_EQ(uriToPath("%C3%A9t%C3%A9.png"), "\xC3\xA9t\xC3\xA9.png");
  EXPECT_EQ(uriToPath("a%2"), std::nullopt);
  EXPECT_EQ(uriToPath("a%zz.png"), std::nullopt);
  EXPECT_EQ(uriToPath("a.png%00.txt"), std::nullopt);
  EXPECT_EQ(uriToPath("file:///etc/passwd"), std::nullopt);
  EXPECT_EQ(uriToPath("https://example.com/a.png"), std::nullopt);
  EXPECT_EQ(uriToPath("dir/a:b.png"), "dir/a:b.png");  // a colon after a slash is no scheme
}

TEST(PathConfinement, ObjMaterialLibrariesAndTexturesStayInTheModelsFolder) {
  TempFolder dir;
  dir.write("outside.mtl", "newmtl red\nKd 1 0 0\n");
  writePng(dir.file("outside.png"));
  writePng(dir.file("model/inside.png"));
  dir.write("model/m.mtl", "newmtl blue\nKd 0 0 1\nmap_Kd ../outside.png\nnewmtl green\nmap_Kd inside.png\n");
  // Faces use every material: only the materials faces use are made, and only their textures read.
  const std::string obj =
      dir.write("model/m.obj", "mtllib ../outside.mtl " + dir.file("outside.mtl") + " m.mtl\nusemtl red\n" +
                                   kTriangleObj + "usemtl blue\nf 1 2 3\nusemtl green\nf 1 2 3\n");

  LoadWarnings warnings;
  Scene s = loadObj(obj, warnings);
  std::string all = allOf(warnings);
  EXPECT_NE(all.find(obj + ":1: material library '../outside.mtl' leads to " + dir.file("outside.mtl") +
                     ", outside the folder " + dir.file("model")),
            std::string::npos)
      << all;
  EXPECT_NE(all.find(obj + ":1: material library '" + dir.file("outside.mtl") + "' leads to"), std::string::npos)
      << all;
  EXPECT_NE(all.find(dir.file("outside.png") + ": leads to " + dir.file("outside.png") + ", outside the folder"),
            std::string::npos)
      << all;
  EXPECT_EQ(s.textures.size(), 1u);  // inside.png only
  for (const std::string& f : s.inputFiles) EXPECT_EQ(f.find("outside"), std::string::npos) << f;

  LoadWarnings allowedWarnings;
  Scene allowed = loadObj(obj, allowedWarnings, OutsidePaths::Allowed);
  EXPECT_EQ(allowed.textures.size(), 2u) << allOf(allowedWarnings);
  EXPECT_FLOAT_EQ(allowed.materials[0].baseColor.x, 1.0f);  // red, from ../outside.mtl
}

json gltfWithBuffer(const std::string& uri) {
  return {{"asset", {{"version", "2.0"}}}, {"buffers", {{{"uri", uri}, {"byteLength", 12}}}}};
}

TEST(PathConfinement, GltfBuffersOutsideTheFolderAreAnError) {
  TempFolder dir;
  dir.write("secret.bin", std::string(12, '\0'));
  for (const std::string& uri :
       {std::string("../secret.bin"), std::string("..%2fsecret.bin"), std::string("..%2Fsecret.bin"),
        std::string("..%5csecret.bin"), dir.file("secret.bin")}) {
    std::string gltf = dir.write("model/m.gltf", gltfWithBuffer(uri).dump());
    LoadWarnings warnings;
    try {
      loadGltf(gltf, warnings);
      ADD_FAILURE() << uri << " was read";
    } catch (const LoadError& e) {
      EXPECT_NE(std::string(e.what()).find(gltf + ": buffer '"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("leads to " + dir.file("secret.bin") + ", outside the folder"),
                std::string::npos)
          << e.what();
    }
  }
  // The working directory, where tinygltf looks next, is not searched either.
  const fs::path before = fs::current_path();
  fs::current_path(dir.path());
  std::string gltf = dir.write("model/m.gltf", gltfWithBuffer("secret.bin").dump());
  LoadWarnings warnings;
  EXPECT_THROW(loadGltf(gltf, warnings), LoadError);
  fs::current_path(before);
}

// A triangle in an external buffer: 36 bytes of positions, 6 of indices.
void writeTriangleBuffer(const std::string& path) {
  std::vector<uint8_t> buffer(36 + 6);
  float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  uint16_t indices[3] = {0, 1, 2};
  std::memcpy(buffer.data(), positions, 36);
  std::memcpy(buffer.data() + 36, indices, 6);
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(buffer.data()), 42);
}

json triangleInBuffer(const std::string& uri) {
  return {
      {"asset", {{"version", "2.0"}}},
      {"buffers", {{{"uri", uri}, {"byteLength", 42}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}, {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
      {"nodes", {{{"mesh", 0}}}},
  };
}

TEST(PathConfinement, GltfBufferUrisAreDecodedAsRfc3986Says) {
  TempFolder dir;
  writeTriangleBuffer(dir.file("model/a+b.bin"));  // no "a b.bin": '+' is no space in a path
  writeTriangleBuffer(dir.file("model/c d.bin"));
  writeTriangleBuffer(dir.file("model/sub/e.bin"));
  LoadWarnings warnings;
  for (const char* uri : {"a+b.bin", "c%20d.bin", "sub%2Fe.bin", "sub/../a%2Bb.bin"}) {
    Scene s = loadGltf(dir.write("model/m.gltf", triangleInBuffer(uri).dump()), warnings);
    EXPECT_EQ(s.triangleCount(), 1u) << uri;
  }
  std::string gltf = dir.write("model/m.gltf", triangleInBuffer("a%zz.bin").dump());
  try {
    loadGltf(gltf, warnings);
    ADD_FAILURE() << "a malformed URI was read";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("names no file (a relative path with valid %-escapes)"), std::string::npos)
        << e.what();
  }
}

TEST(PathConfinement, GltfImagesOutsideTheFolderAreAWarning) {
  TempFolder dir;
  writePng(dir.file("outside.png"));
  writePng(dir.file("model/a+b.png"));
  writeTriangleBuffer(dir.file("model/m.bin"));
  json g = triangleInBuffer("m.bin");
  g.update({
      {"images",
       {{{"uri", "..%2Foutside.png"}}, {{"uri", "a+b.png"}}, {{"uri", "a%00.png"}}, {{"uri", "file:///etc/passwd"}}}},
      {"textures", {{{"source", 0}}, {{"source", 1}}, {{"source", 2}}, {{"source", 3}}}},
      {"materials",
       {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}},
        {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}},
        {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 2}}}}}},
        {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 3}}}}}}}},
      {"meshes",
       {{{"primitives",
          {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 0}},
           {{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 1}},
           {{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 2}},
           {{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 3}}}}}}},
  });
  std::string gltf = dir.write("model/m.gltf", g.dump());
  LoadWarnings warnings;
  Scene s = loadGltf(gltf, warnings);
  std::string all = allOf(warnings);
  EXPECT_NE(all.find(dir.file("outside.png") + ": leads to " + dir.file("outside.png") + ", outside the folder"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("images[2].uri 'a%00.png' names no file"), std::string::npos) << all;
  EXPECT_NE(all.find("images[3].uri 'file:///etc/passwd' names no file"), std::string::npos) << all;
  ASSERT_EQ(s.textures.size(), 1u) << all;  // a+b.png, by its own name
  EXPECT_EQ(s.materials[1].baseColorTexture, 0);
  EXPECT_EQ(s.materials[0].baseColorTexture, kNoTexture);

  LoadWarnings allowedWarnings;
  EXPECT_EQ(loadGltf(gltf, allowedWarnings, OutsidePaths::Allowed).textures.size(), 2u) << allOf(allowedWarnings);
}

Scene loadModel(const std::string& path, LoadWarnings& warnings, SharedModelAssets&) { return loadObj(path, warnings); }

TEST(PathConfinement, SceneFilesNameModelsInTheirFolder) {
  TempFolder dir;
  dir.write("models/t.obj", kTriangleObj);
  std::string scene = dir.write("scenes/s.json", R"({"models": [{"file": "../models/t.obj"}]})");
  LoadWarnings warnings;
  try {
    loadSceneFile(scene, &loadModel, warnings);
    ADD_FAILURE() << "a model outside the scene file's folder was read";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find(scene + ": models[0].file: '../models/t.obj' leads to " +
                                         dir.file("models/t.obj") + ", outside the folder " + dir.file("scenes")),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(loadSceneFile(scene, &loadModel, warnings, OutsidePaths::Allowed).triangleCount(), 1u);

  // Through a symbolic link too.
  fs::create_directory_symlink(dir.file("models"), dir.file("scenes/linked"));
  std::string linked = dir.write("scenes/linked.json", R"({"models": [{"file": "linked/t.obj"}]})");
  EXPECT_THROW(loadSceneFile(linked, &loadModel, warnings), LoadError);

  std::string withMap =
      dir.write("scenes/e.json", R"({"models": [{"file": "t.obj"}], "environment": {"map": "../sky.hdr"}})");
  dir.write("scenes/t.obj", kTriangleObj);
  try {
    loadSceneFile(withMap, &loadModel, warnings);
    ADD_FAILURE() << "an environment map outside the scene file's folder was read";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find(withMap + ": environment.map: '../sky.hdr' leads to " + dir.file("sky.hdr")),
              std::string::npos)
        << e.what();
  }
}

// An absolute path is the scene file's author's choice, as in the views the viewer saves.
TEST(PathConfinement, SceneFilesMayNameModelsByAbsolutePath) {
  TempFolder dir;
  dir.write("models/t.obj", kTriangleObj);
  json scene = {{"models", {{{"file", dir.file("models/t.obj")}}}}};
  LoadWarnings warnings;
  EXPECT_EQ(loadSceneFile(dir.write("views/v.json", scene.dump()), &loadModel, warnings).triangleCount(), 1u);
}

}  // namespace
}  // namespace candela
