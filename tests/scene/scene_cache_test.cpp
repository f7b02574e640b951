// The scene cache: a round trip gives the same scene, a changed input makes the cache stale (also a same-size
// replacement that keeps the modification time), and no truncated, corrupted or hand-built cache file is read as
// a scene or crashes the reader.
#include <gtest/gtest.h>

#include <stb/stb_image_write.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <thread>

#include "kernel/scene_arrays.h"
#include "scene/cache/binary_stream.h"
#include "scene/cache/cache_key.h"
#include "scene/cache/scene_cache.h"
#include "scene/loaders/obj/obj_loader.h"
#include "scene/scene_test_files.h"
#include "support/scoped_variable.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using test::TempFolder;

template <class T>
void expectSameBytes(const std::vector<T>& a, const std::vector<T>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  if (!a.empty()) {
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(T)), 0) << what;
  }
}

void expectSameTexture(const Texture& a, const Texture& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.channels, b.channels);
  EXPECT_EQ(a.srgb, b.srgb);
  EXPECT_EQ(a.wrapU, b.wrapU);
  EXPECT_EQ(a.wrapV, b.wrapV);
  expectSameBytes(a.bytes, b.bytes, "texture bytes");
  expectSameBytes(a.floats, b.floats, "texture floats");
}

void expectSameScene(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (size_t i = 0; i < a.meshes.size(); ++i) {
    const Mesh &m = a.meshes[i], &n = b.meshes[i];
    EXPECT_EQ(m.name, n.name);
#define CANDELA_EXPECT_SAME_MESH_ARRAY(Type, member, upload, count, description) \
  expectSameBytes(m.member, n.member, #member);
    CANDELA_MESH_ARRAYS(CANDELA_EXPECT_SAME_MESH_ARRAY)
#undef CANDELA_EXPECT_SAME_MESH_ARRAY
  }
  expectSameBytes(a.instances, b.instances, "instances");
  expectSameBytes(a.materials, b.materials, "materials");
  EXPECT_EQ(a.materialNames, b.materialNames);
  ASSERT_EQ(a.textures.size(), b.textures.size());
  for (size_t i = 0; i < a.textures.size(); ++i) expectSameTexture(a.textures[i], b.textures[i]);
  EXPECT_EQ(std::memcmp(&a.environment.radiance, &b.environment.radiance, sizeof(Vec3)), 0);
  expectSameTexture(a.environment.map, b.environment.map);
  EXPECT_EQ(a.environment.intensity, b.environment.intensity);
  EXPECT_EQ(a.environment.rotationDegrees, b.environment.rotationDegrees);
  EXPECT_EQ(a.environment.visibleToCamera, b.environment.visibleToCamera);
  EXPECT_EQ(std::memcmp(&a.camera, &b.camera, sizeof(CameraDescription)), 0);
  EXPECT_EQ(a.renderHints.width, b.renderHints.width);
  EXPECT_EQ(a.renderHints.height, b.renderHints.height);
  EXPECT_EQ(a.renderHints.samplesPerPixel, b.renderHints.samplesPerPixel);
  EXPECT_EQ(a.renderHints.maxDepth, b.renderHints.maxDepth);
  EXPECT_EQ(a.cameraMissing, b.cameraMissing);
  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  for (size_t i = 0; i < a.cameras.size(); ++i) {
    EXPECT_EQ(a.cameras[i].name, b.cameras[i].name);
    EXPECT_EQ(std::memcmp(&a.cameras[i].description, &b.cameras[i].description, sizeof(CameraDescription)), 0);
  }
  EXPECT_EQ(a.inputFiles, b.inputFiles);
}

// Every field set to something other than its default.
Scene richScene() {
  Scene s;
  s.name = "rich";
  for (int k = 0; k < 2; ++k) {
    Mesh m;
    m.name = "mesh" + std::to_string(k);
    m.positions = {{0, 0, 0}, {1, 0, float(k)}, {0, 1, 0}, {1, 1, 1}};
    m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
    if (k == 0) m.uvs = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    if (k == 0) m.tangents = {{1, 0, 0, 1}, {1, 0, 0, -1}, {1, 0, 0, 1}, {1, 0, 0, 1}};
    if (k == 1) m.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    m.indices = {0, 1, 2, 1, 3, 2};
    m.triangleMaterials = {uint32_t(k), 1};
    s.meshes.push_back(m);
  }
  Instance moved{1, Affine3x4{}};
  moved.objectToWorld.m[3] = 5.0f;
  s.instances = {{0, Affine3x4{}}, moved};
  Material glass;
  glass.type = MaterialType::Glass;
  glass.ior = 1.33f;
  glass.baseColorTexture = 0;
  Material emitter;
  emitter.emission = {4, 3, 2};
  emitter.normalTexture = 1;
  s.materials = {glass, emitter};
  s.materialNames = {"glass", "lamp"};
  Texture bytes{"albedo.png", 2, 1, 4, true, TextureWrap::Clamp, TextureWrap::Mirror, {1, 2, 3, 4, 5, 6, 7, 8}, {}};
  Texture floats{"normal.exr", 1, 1, 3, false, TextureWrap::Mirror, TextureWrap::Repeat, {}, {0.5f, 0.25f, 1.0f}};
  s.textures = {bytes, floats};
  s.environment.radiance = {0.1f, 0.2f, 0.3f};
  s.environment.map = {"sky.hdr", 2, 1, 3, false, TextureWrap::Repeat, TextureWrap::Repeat, {}, {1, 2, 3, 4, 5, 6}};
  s.environment.intensity = 2.5f;
  s.environment.rotationDegrees = 90;
  s.environment.visibleToCamera = false;
  s.camera.eye = {1, 2, 3};
  s.camera.apertureRadius = 0.1f;
  s.renderHints.width = 320;
  s.renderHints.maxDepth = 4;
  s.cameraMissing = true;
  s.cameras = {{"front", s.camera}, {"side", CameraDescription{}}};
  s.inputFiles = {"model.obj", "model.mtl"};
  return s;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A new file rather than a truncated one: ext4 flushes a file rewritten through truncation when it is closed,
// which makes a loop of rewrites take seconds.
void writeFile(const std::string& path, const std::string& bytes) {
  fs::remove(path);
  std::ofstream(path, std::ios::binary) << bytes;
}

TEST(SceneCache, RoundTripGivesTheSameScene) {
  TempFolder dir;
  const std::string model = dir.write("model.obj", "unused: the key only needs the file to exist");
  const std::string cache = sceneCacheFile(dir.file("cache"), model);
  const Scene scene = richScene();
  writeSceneCache(cache, model, scene, {"model.obj:3: a warning"});
  CachedScene read;
  ASSERT_EQ(readSceneCache(cache, model, read), SceneCacheRead::Hit);
  expectSameScene(scene, read.scene);
  EXPECT_EQ(read.warnings, std::vector<std::string>{"model.obj:3: a warning"});
  // No temporary file is left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.file("cache")), fs::directory_iterator()), 1);
}

// An OBJ with a material library and a texture, loaded through the cache.
struct CachedObj {
  TempFolder dir;
  std::string model, library, texture, cacheDirectory;
  CachedObj() {
    std::vector<uint8_t> pixels(4 * 4 * 3, 128);
    texture = dir.file("wood.png");
    stbi_write_png(texture.c_str(), 4, 4, 3, pixels.data(), 12);
    library = dir.write("m.mtl", "newmtl wood\nKd 1 1 1\nmap_Kd wood.png\n");
    model =
        dir.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl wood\nf 1 2 3\nusemtl nowhere\nf 1 3 2\n");
    cacheDirectory = dir.file("cache");
  }
  Scene load(LoadWarnings& warnings, int* freshLoads = nullptr) const {
    return loadThroughSceneCache(model, {true, cacheDirectory}, warnings, [&](LoadWarnings& w) {
      if (freshLoads) ++*freshLoads;
      return loadObj(model, w);
    });
  }
  SceneCacheRead status() const {
    CachedScene ignored;
    return readSceneCache(sceneCacheFile(cacheDirectory, model), model, ignored);
  }
};

TEST(SceneCache, SecondLoadComesFromTheCacheWithItsWarnings) {
  CachedObj obj;
  int fresh = 0;
  LoadWarnings first, second;
  Scene a = obj.load(first, &fresh);
  Scene b = obj.load(second, &fresh);
  EXPECT_EQ(fresh, 1);
  expectSameScene(a, b);
  ASSERT_FALSE(first.messages.empty());
  EXPECT_EQ(first.messages, second.messages);
  EXPECT_EQ(a.inputFiles, (std::vector<std::string>{obj.model, obj.library, obj.texture}));
}

TEST(SceneCache, ChangedInputsMakeTheCacheStale) {
  CachedObj obj;
  LoadWarnings w;
  auto reload = [&] {
    obj.load(w);
    ASSERT_EQ(obj.status(), SceneCacheRead::Hit);
  };
  reload();
  // The model's modification time alone.
  fs::last_write_time(obj.model, fs::last_write_time(obj.model) + std::chrono::seconds(1));
  EXPECT_EQ(obj.status(), SceneCacheRead::Stale);
  reload();
  // The model's size, with the modification time put back.
  auto time = fs::last_write_time(obj.model);
  writeFile(obj.model, readFile(obj.model) + "# more\n");
  fs::last_write_time(obj.model, time);
  EXPECT_EQ(obj.status(), SceneCacheRead::Stale);
  reload();
  // The material library, and the texture.
  fs::last_write_time(obj.library, fs::last_write_time(obj.library) - std::chrono::seconds(5));
  EXPECT_EQ(obj.status(), SceneCacheRead::Stale);
  reload();
  fs::remove(obj.texture);
  EXPECT_EQ(obj.status(), SceneCacheRead::Stale);
}

// One triangle whose first vertex's x is `x`, padded with a comment to `bytes` bytes, so that two versions of
// the model have the same size.
std::string triangleObj(char x, size_t bytes) {
  std::string obj = std::string("v ") + x + " 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# ";
  obj.resize(bytes - 1, 'p');
  return obj + "\n";
}

// Loads `model` through the cache in `cacheDirectory`; `fresh` counts the loads that read the model itself.
Scene loadCachedObj(const std::string& model, const std::string& cacheDirectory, int& fresh,
                    LoadWarnings* warnings = nullptr) {
  LoadWarnings ignored;
  return loadThroughSceneCache(model, {true, cacheDirectory}, warnings ? *warnings : ignored, [&](LoadWarnings& w) {
    ++fresh;
    return loadObj(model, w);
  });
}

// `cp -p new model`: the model's file is rewritten in place with contents of the same size, and its
// modification time is put back. Size and modification time alone would serve the old model.
void copyPreservingTime(const std::string& from, const std::string& to) {
  const auto time = fs::last_write_time(to);
  std::ofstream(to, std::ios::binary | std::ios::trunc) << readFile(from);
  fs::last_write_time(to, time);
}

// `rsync -t new model`: a new file with the old modification time is renamed over the model.
void renamePreservingTime(const std::string& from, const std::string& to) {
  const auto time = fs::last_write_time(to);
  const std::string temporary = to + ".partial";
  fs::copy_file(from, temporary, fs::copy_options::overwrite_existing);
  fs::last_write_time(temporary, time);
  fs::rename(temporary, to);
}

TEST(SceneCache, SameSizeReplacementKeepingTheTimeIsLoadedAfresh) {
  for (size_t bytes : {size_t(200), size_t(kHashedFileBytes + 1000)}) {  // hashed, and too large to hash
    for (auto replace : {copyPreservingTime, renamePreservingTime}) {
      TempFolder dir;
      const std::string model = dir.write("m.obj", triangleObj('0', bytes));
      const std::string cacheDirectory = dir.file("cache");
      int fresh = 0;
      EXPECT_EQ(loadCachedObj(model, cacheDirectory, fresh).meshes[0].positions[0].x, 0.0f);
      EXPECT_EQ(loadCachedObj(model, cacheDirectory, fresh).meshes[0].positions[0].x, 0.0f);
      ASSERT_EQ(fresh, 1);
      // Beyond the file system's clock tick, which large files (not hashed) rely on to change the inode's
      // change time.
      if (bytes > kHashedFileBytes) std::this_thread::sleep_for(std::chrono::milliseconds(50));
      const std::string update = dir.write("update.obj", triangleObj('5', bytes));
      replace(update, model);
      ASSERT_EQ(fs::file_size(model), bytes);
      EXPECT_EQ(loadCachedObj(model, cacheDirectory, fresh).meshes[0].positions[0].x, 5.0f) << bytes << " bytes";
      EXPECT_EQ(fresh, 2);
    }
  }
}

TEST(SceneCache, SmallFilesAreKeyedByTheirContents) {
  TempFolder dir;
  const std::string a = dir.write("a.mtl", "newmtl red\nKd 1 0 0\n");
  const FileState before = fileState(a);
  EXPECT_NE(before.contentHash, 0u);
  EXPECT_NE(before.inode, 0u);
  // A same-size edit within one tick of the file system's clock leaves size and times alike: the hash differs.
  std::ofstream(a, std::ios::binary | std::ios::trunc) << "newmtl red\nKd 0 1 0\n";
  EXPECT_NE(fileState(a).contentHash, before.contentHash);
  // Large files are not read for the key.
  const std::string big = dir.write("big.obj", std::string(kHashedFileBytes, '#'));
  EXPECT_EQ(fileState(big).contentHash, 0u);
  EXPECT_TRUE(fileState(big).exists);
}

TEST(SceneCache, AddingAMissingLibraryMakesTheCacheStale) {
  TempFolder dir;
  const std::string model = dir.write("m.obj", "mtllib later.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const SceneCacheSettings settings{true, dir.file("cache")};
  LoadWarnings w;
  auto load = [&](LoadWarnings& lw) { return loadObj(model, lw); };
  loadThroughSceneCache(model, settings, w, load);
  CachedScene cached;
  ASSERT_EQ(readSceneCache(sceneCacheFile(settings.directory, model), model, cached), SceneCacheRead::Hit);
  dir.write("later.mtl", "newmtl red\nKd 1 0 0\n");
  EXPECT_EQ(readSceneCache(sceneCacheFile(settings.directory, model), model, cached), SceneCacheRead::Stale);
}

TEST(SceneCache, TruncatedCachesAreDamaged) {
  TempFolder dir;
  const std::string model = dir.write("model.obj", "x");
  const std::string cache = dir.file("model.scene");
  writeSceneCache(cache, model, richScene(), {"w"});
  const std::string whole = readFile(cache);
  for (size_t n = 0; n < whole.size(); ++n) {
    writeFile(cache, whole.substr(0, n));
    CachedScene read;
    EXPECT_EQ(readSceneCache(cache, model, read), SceneCacheRead::Damaged) << "truncated to " << n;
  }
  writeFile(cache, whole + "x");
  CachedScene read;
  EXPECT_EQ(readSceneCache(cache, model, read), SceneCacheRead::Damaged) << "a byte too many";
}

// Random corruptions of a small cache file: flipped bits, overwritten bytes, huge counts, cut or inserted
// pieces. None may be read as a scene, crash the reader or make it allocate beyond the file's size.
TEST(SceneCache, CorruptedCachesAreNeverReadAsScenes) {
  TempFolder dir;
  const std::string model = dir.write("model.obj", "x");
  const std::string cache = dir.file("model.scene");
  writeSceneCache(cache, model, richScene(), {"w"});
  const std::string whole = readFile(cache);
  std::mt19937 rng(12345);
  auto position = [&](size_t size) { return std::uniform_int_distribution<size_t>(0, size - 1)(rng); };
  for (int trial = 0; trial < 3000; ++trial) {
    std::string bytes = whole;
    const int edits = 1 + trial % 3;
    for (int e = 0; e < edits; ++e) {
      switch (rng() % 5) {
        case 0: bytes[position(bytes.size())] ^= char(1 << (rng() % 8)); break;
        case 1: bytes[position(bytes.size())] = char(rng()); break;
        case 2: {  // a count or size made huge
          uint64_t huge = uint64_t(rng()) << (32 + rng() % 31);
          size_t at = position(bytes.size() - 8);
          std::memcpy(&bytes[at], &huge, sizeof huge);
          break;
        }
        case 3: bytes.erase(position(bytes.size()), 1 + rng() % 16); break;
        default: bytes.insert(position(bytes.size()), std::string(1 + rng() % 16, char(rng())));
      }
      if (bytes.size() < 16) bytes = whole.substr(0, 16);
    }
    writeFile(cache, bytes);
    CachedScene read;
    SceneCacheRead status = readSceneCache(cache, model, read);
    if (bytes != whole) {
      EXPECT_NE(status, SceneCacheRead::Hit) << "trial " << trial;
    }
  }
}

TEST(SceneCache, DamagedCacheIsAWarningAndIsReplaced) {
  CachedObj obj;
  LoadWarnings first;
  Scene fresh = obj.load(first);
  const std::string cache = sceneCacheFile(obj.cacheDirectory, obj.model);
  std::string bytes = readFile(cache);
  bytes[bytes.size() - 9] ^= 0x40;  // the last byte of the scene, before the checksum
  writeFile(cache, bytes);
  int loads = 0;
  LoadWarnings second;
  Scene again = obj.load(second, &loads);
  EXPECT_EQ(loads, 1);
  expectSameScene(fresh, again);
  ASSERT_FALSE(second.messages.empty());
  EXPECT_EQ(second.messages[0], cache + ": damaged scene cache ignored; the model is loaded afresh and cached again");
  EXPECT_EQ(obj.status(), SceneCacheRead::Hit);
}

// Cache files written with a correct checksum around a scene no loader gives: each must be refused as Invalid.
TEST(SceneCache, HandBuiltCachesWithInvalidScenesAreRefused) {
  TempFolder dir;
  const std::string model = dir.write("model.obj", "x");
  const std::string cache = dir.file("model.scene");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<std::pair<const char*, std::function<void(Scene&)>>> edits = {
      {"unknown material type", [](Scene& s) { s.materials[0].type = MaterialType(77); }},
      {"unknown alpha mode", [](Scene& s) { s.materials[1].alphaMode = AlphaMode(3); }},
      {"NaN material parameter", [&](Scene& s) { s.materials[0].ior = nan; }},
      {"NaN camera", [&](Scene& s) { s.camera.eye.y = nan; }},
      {"camera on its target", [](Scene& s) { s.camera.target = s.camera.eye; }},
      {"field of view of 0", [](Scene& s) { s.camera.verticalFovDegrees = 0.0f; }},
      {"negative aperture", [](Scene& s) { s.camera.apertureRadius = -1.0f; }},
      {"render width of 0", [](Scene& s) { s.renderHints.width = 0u; }},
      {"huge render height", [](Scene& s) { s.renderHints.height = 1u << 30; }},
      {"spp of 0", [](Scene& s) { s.renderHints.samplesPerPixel = 0u; }},
      {"unknown texture wrap", [](Scene& s) { s.textures[0].wrapV = TextureWrap(9); }},
      {"unknown punctual light type",
       [](Scene& s) {
         PunctualLight light;
         light.type = PunctualLightType(7);
         s.punctualLights.push_back(light);
       }},
      {"non-finite second camera",
       [&](Scene& s) {
         NamedCamera second{"b", s.camera};
         second.description.eye.x = nan;
         s.cameras.push_back(second);
       }},
      {"texture size overflowing 64 bits",
       [](Scene& s) {
         s.textures[0].width = s.textures[0].height = 1u << 31;
         s.textures[0].bytes.clear();
       }},
      {"texture with bytes and floats",
       [](Scene& s) {
         s.textures[1].bytes = {1, 2, 3};
       }},
      {"NaN texel", [&](Scene& s) { s.textures[1].floats[0] = nan; }},
      {"environment map larger than its floats", [](Scene& s) { s.environment.map.height = 1000; }},
      {"environment map without channels", [](Scene& s) { s.environment.map.channels = 0; }},
      {"environment map of bytes",
       [](Scene& s) {
         s.environment.map.bytes = {1, 2, 3, 4, 5, 6};
         s.environment.map.floats.clear();
       }},
      {"negative environment radiance", [](Scene& s) { s.environment.radiance.x = -1.0f; }},
      {"NaN environment intensity", [&](Scene& s) { s.environment.intensity = nan; }},
      {"infinite environment rotation", [](Scene& s) { s.environment.rotationDegrees = INFINITY; }},
      {"NaN normal", [&](Scene& s) { s.meshes[1].normals[2].z = nan; }},
      {"NaN texture coordinate", [&](Scene& s) { s.meshes[0].uvs[3].x = nan; }},
      {"NaN colour", [&](Scene& s) { s.meshes[1].colors[0].y = nan; }},
      {"NaN instance transform", [&](Scene& s) { s.instances[1].objectToWorld.m[7] = nan; }},
      {"material id past the materials", [](Scene& s) { s.meshes[0].triangleMaterials[1] = 2; }},
      {"index past the vertices", [](Scene& s) { s.meshes[1].indices[4] = 4; }},
      {"one material name for two materials", [](Scene& s) { s.materialNames.pop_back(); }},
  };
  for (const auto& [what, edit] : edits) {
    Scene scene = richScene();
    edit(scene);
    writeSceneCache(cache, model, scene, {});
    CachedScene read;
    std::string problem;
    EXPECT_EQ(readSceneCache(cache, model, read, &problem), SceneCacheRead::Invalid) << what;
    EXPECT_FALSE(problem.empty()) << what;
  }
  writeSceneCache(cache, model, richScene(), {});
  CachedScene read;
  EXPECT_EQ(readSceneCache(cache, model, read), SceneCacheRead::Hit);
}

// A file with a correct checksum whose counts claim more than the file holds: refused before allocating.
TEST(SceneCache, HandBuiltCacheWithAHugeCountIsDamaged) {
  TempFolder dir;
  const std::string model = dir.write("model.obj", "x");
  const std::string cache = dir.file("model.scene");
  for (int field = 0; field < 3; ++field) {
    std::FILE* file = std::fopen(cache.c_str(), "wb");
    ASSERT_TRUE(file);
    {
      BinaryWriter out(file);
      out.bytes("candelaS", 8);
      writeCacheKey(out, currentCacheKey(model, {}));
      const uint64_t huge = uint64_t(1) << 60;
      out.value(uint64_t(field == 0 ? huge : 0));  // warnings
      out.string("scene");
      out.value(uint64_t(field == 1 ? huge : 1));  // meshes
      if (field == 2) {
        out.string("mesh");
        out.value(huge);  // positions
      }
      out.finish();
      ASSERT_TRUE(out.ok());
    }
    std::fclose(file);
    CachedScene read;
    EXPECT_EQ(readSceneCache(cache, model, read), SceneCacheRead::Damaged) << "field " << field;
  }
}

TEST(SceneCache, InvalidCacheIsAWarningAndIsReplaced) {
  CachedObj obj;
  LoadWarnings first;
  Scene fresh = obj.load(first);
  const std::string cache = sceneCacheFile(obj.cacheDirectory, obj.model);
  Scene bad = fresh;
  bad.camera.eye.x = std::numeric_limits<float>::quiet_NaN();
  writeSceneCache(cache, obj.model, bad, {});
  ASSERT_EQ(obj.status(), SceneCacheRead::Invalid);
  int loads = 0;
  LoadWarnings second;
  Scene again = obj.load(second, &loads);
  EXPECT_EQ(loads, 1);
  expectSameScene(fresh, again);
  ASSERT_FALSE(second.messages.empty());
  EXPECT_EQ(second.messages[0].rfind(cache + ": invalid scene cache ignored (", 0), 0u) << second.messages[0];
  EXPECT_NE(second.messages[0].find("the model is loaded afresh and cached again"), std::string::npos);
  EXPECT_EQ(obj.status(), SceneCacheRead::Hit);
}

// A loaded scene that the cache would refuse to read back is not written (else every load would warn again).
TEST(SceneCache, SceneTheCacheWouldRefuseIsNotWritten) {
  CachedObj obj;
  LoadWarnings warnings;
  loadThroughSceneCache(obj.model, {true, obj.cacheDirectory}, warnings, [&](LoadWarnings& w) {
    Scene s = loadObj(obj.model, w);
    s.camera.verticalFovDegrees = 0.0f;
    return s;
  });
  EXPECT_EQ(obj.status(), SceneCacheRead::Missing);
  bool warned = false;
  for (const std::string& m : warnings.messages) warned |= m.find("scene cache not written") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(SceneCache, UnwritableCacheIsAWarning) {
  CachedObj obj;
  obj.cacheDirectory = obj.dir.write("not-a-folder", "a file where the cache folder should be");
  LoadWarnings warnings;
  Scene s = obj.load(warnings);
  EXPECT_EQ(s.triangleCount(), 2u);
  bool warned = false;
  for (const std::string& m : warnings.messages) warned |= m.find("scene cache not written") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(SceneCache, DisabledCacheWritesNothing) {
  CachedObj obj;
  LoadWarnings warnings;
  loadThroughSceneCache(obj.model, {false, obj.cacheDirectory}, warnings,
                        [&](LoadWarnings& w) { return loadObj(obj.model, w); });
  EXPECT_FALSE(fs::exists(obj.cacheDirectory));
}

TEST(SceneCache, DefaultFolder) {
  ScopedVariable home("HOME", "/home/someone"), xdg("XDG_CACHE_HOME", nullptr), own("CANDELA_CACHE_DIR", nullptr);
  EXPECT_EQ(defaultSceneCacheDirectory(), "/home/someone/.cache/candela");
  {
    ScopedVariable relative("XDG_CACHE_HOME", "relative/ignored");
    EXPECT_EQ(defaultSceneCacheDirectory(), "/home/someone/.cache/candela");
  }
  ScopedVariable xdgSet("XDG_CACHE_HOME", "/var/cache/me");
  EXPECT_EQ(defaultSceneCacheDirectory(), "/var/cache/me/candela");
  ScopedVariable ownSet("CANDELA_CACHE_DIR", "/scratch/scenes");
  EXPECT_EQ(defaultSceneCacheDirectory(), "/scratch/scenes");
}

}  // namespace
}  // namespace candela
