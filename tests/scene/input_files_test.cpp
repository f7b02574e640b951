// Loaders read only regular files of a bounded size: links to devices, FIFOs and oversized files are refused
// with one line naming the file, before anything is read (and without waiting for a FIFO's writer).
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>

#include "io/file_bytes.h"
#include "io/images/image_decoding.h"
#include "scene/cache/scene_cache.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/loaders/obj/obj_loader.h"
#include "scene/loaders/obj/obj_text_source.h"
#include "scene/loaders/scene_file.h"
#include "scene/scene_test_files.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using test::TempFolder;

const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

std::string fifo(const TempFolder& dir, const std::string& name) {
  std::string path = dir.file(name);
  EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0);
  return path;
}

std::string linkTo(const TempFolder& dir, const std::string& name, const std::string& target) {
  std::string path = dir.file(name);
  fs::create_symlink(target, path);
  return path;
}

// The message of the LoadError that `load` throws, checked to be one line that starts with `file`.
template <class Load>
std::string errorOf(const std::string& file, Load load) {
  try {
    load();
  } catch (const LoadError& e) {
    std::string what = e.what();
    EXPECT_EQ(what.rfind(file + ": ", 0), 0u) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    return what;
  }
  ADD_FAILURE() << "expected a LoadError for " << file;
  return {};
}

Scene loadModel(const std::string& path, LoadWarnings& warnings, SharedModelAssets&) {
  return path.ends_with(".obj") ? loadObj(path, warnings) : loadGltf(path, warnings);
}

TEST(InputFiles, DevicesAreRefusedBeforeTheyAreRead) {
  TempFolder dir;
  LoadWarnings warnings;
  for (const char* device : {"/dev/zero", "/dev/urandom"}) {
    std::string glb = linkTo(dir, fs::path(device).filename().string() + ".glb", device);
    EXPECT_NE(errorOf(glb, [&] { loadGltf(glb, warnings); }).find("is a device"), std::string::npos);
    std::string obj = linkTo(dir, fs::path(device).filename().string() + ".obj", device);
    EXPECT_NE(errorOf(obj, [&] { loadObj(obj, warnings); }).find("is a device"), std::string::npos);
    std::string json = linkTo(dir, fs::path(device).filename().string() + ".json", device);
    EXPECT_NE(errorOf(json, [&] { loadSceneFile(json, &loadModel, warnings); }).find("is a device"), std::string::npos);
    std::string hdr = linkTo(dir, fs::path(device).filename().string() + ".hdr", device);
    EXPECT_NE(errorOf(hdr, [&] { loadEnvironmentImage(hdr); }).find("is a device"), std::string::npos);
    std::string exr = linkTo(dir, fs::path(device).filename().string() + ".exr", device);
    EXPECT_NE(errorOf(exr, [&] { loadEnvironmentImage(exr); }).find("is a device"), std::string::npos);
  }
}

TEST(InputFiles, FifosAreRefusedWithoutWaitingForAWriter) {
  TempFolder dir;
  LoadWarnings warnings;
  for (const char* name : {"m.obj", "m.gltf", "s.json", "e.hdr", "e.exr"}) {
    std::string path = fifo(dir, name);
    std::string what = errorOf(path, [&] {
      std::string ext = fs::path(path).extension().string();
      if (ext == ".obj")
        loadObj(path, warnings);
      else if (ext == ".gltf")
        loadGltf(path, warnings);
      else if (ext == ".json")
        loadSceneFile(path, &loadModel, warnings);
      else
        loadEnvironmentImage(path);
    });
    EXPECT_NE(what.find("is a FIFO"), std::string::npos) << what;
  }
  EXPECT_NE(errorOf(dir.path().string(), [&] { readFileBytes(dir.path().string()); }).find("is a directory"),
            std::string::npos);
}

TEST(InputFiles, ReferencedFilesThatAreFifosOrDevicesAreRefused) {
  TempFolder dir;
  fifo(dir, "lib.mtl");
  dir.write("t.mtl", "newmtl red\nmap_Kd zero.png\n");
  linkTo(dir, "zero.png", "/dev/zero");
  // A link to a device leads outside the model's folder; where that is allowed, the device is still refused.
  LoadWarnings warnings;
  loadObj(dir.write("m.obj", std::string("mtllib lib.mtl t.mtl\nusemtl red\n") + kTriangleObj), warnings,
          OutsidePaths::Allowed);
  std::string all;
  for (const std::string& w : warnings.messages) all += w + "\n";
  EXPECT_NE(all.find("material library 'lib.mtl' cannot be read (" + dir.file("lib.mtl") + ": is a FIFO"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find(dir.file("zero.png") + ": is a device"), std::string::npos) << all;

  linkTo(dir, "zero.bin", "/dev/zero");
  std::string gltf =
      dir.write("b.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "zero.bin", "byteLength": 12}]})");
  EXPECT_NE(errorOf(gltf, [&] { loadGltf(gltf, warnings, OutsidePaths::Allowed); }).find("is a device"),
            std::string::npos);
  EXPECT_NE(errorOf(gltf, [&] { loadGltf(gltf, warnings); }).find("buffer 'zero.bin' leads to /dev/zero"),
            std::string::npos);
}

TEST(InputFiles, FilesLargerThanTheLimitAreRefused) {
  TempFolder dir;
  std::string obj = dir.write("m.obj", kTriangleObj);
  const uint64_t limit = maxInputFileBytes();
  setMaxInputFileBytes(8);
  LoadWarnings warnings;
  std::string what = errorOf(obj, [&] { loadObj(obj, warnings); });
  std::string bytes = errorOf(obj, [&] { readFileBytes(obj); });
  setMaxInputFileBytes(limit);
  EXPECT_NE(what.find("is 32 bytes, larger than the 7.45e-09 GiB a file may be (--max-file-gib raises the limit)"),
            std::string::npos)
      << what;
  EXPECT_EQ(what, bytes);
  EXPECT_EQ(loadObj(obj, warnings).triangleCount(), 1u);
  EXPECT_EQ(kDefaultMaxInputFileBytes, uint64_t(8) << 30);
}

TEST(InputFiles, AFifoInPlaceOfTheSceneCacheIsDamagedNotWaitedFor) {
  TempFolder dir;
  std::string model = dir.write("m.obj", kTriangleObj);
  fs::create_directories(dir.file("cache"));
  std::string cacheFile = fifo(dir, "cache/" + fs::path(sceneCacheFile(dir.file("cache"), model)).filename().string());
  CachedScene cached;
  EXPECT_EQ(readSceneCache(cacheFile, model, cached), SceneCacheRead::Damaged);
}

// A UTF-8 byte order mark, which some editors write, is not part of the first statement.
TEST(InputFiles, ByteOrderMarksAreSkipped) {
  TempFolder dir;
  const std::string bom = "\xEF\xBB\xBF";
  dir.write("m.mtl", bom + "newmtl red\nKd 1 0 0\n");
  std::string obj = dir.write("m.obj", bom + "v 0 0 0\nv 1 0 0\nv 0 1 0\nmtllib m.mtl\nusemtl red\nf 1 2 3\n");
  LoadWarnings warnings;
  Scene s = loadObj(obj, warnings);
  EXPECT_TRUE(warnings.messages.empty()) << warnings.messages[0];
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].triangleCount(), 1u);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_FLOAT_EQ(s.materials[0].baseColor.x, 1.0f);
  EXPECT_FLOAT_EQ(s.materials[0].baseColor.y, 0.0f);

  std::string text = bom + "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (size_t window : {size_t(1), size_t(5), size_t(1) << 20}) {
    ObjReadOptions options;
    options.windowBytes = window;
    EXPECT_EQ(loadObjText("t.obj", text, warnings, options).triangleCount(), 1u) << window;
  }

  for (size_t window : {size_t(1), size_t(64)}) {
    std::unique_ptr<ObjTextSource> source = openObjTextFile(obj, window);
    ObjTextSource::Window first = source->next();
    EXPECT_EQ(first.offset, 3u);
    EXPECT_EQ(first.text.substr(0, 2), "v ");
  }

  std::string json = dir.write("s.json", bom + R"({"models": [{"file": "m.obj"}]})");
  EXPECT_EQ(loadSceneFile(json, &loadModel, warnings).triangleCount(), 1u);
}

}  // namespace
}  // namespace candela
