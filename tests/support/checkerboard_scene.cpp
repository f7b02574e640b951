#include "support/checkerboard_scene.h"

namespace candela::test {

Texture checkerboardTexture(uint32_t size, uint32_t square) {
  Texture t;
  t.name = "checkerboard";
  t.width = t.height = size;
  t.channels = 1;
  t.bytes.resize(size_t(size) * size);
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) t.bytes[size_t(y) * size + x] = ((x / square + y / square) % 2) ? 255 : 0;
  return t;
}

namespace {

// 400 x 400 units in the plane y = height, facing up or down, the texture repeated 100 times along each side
// (4 units a tile).
Mesh texturedPlane(float height, bool facingUp, uint32_t materialId) {
  constexpr float kHalf = 200.0f, kRepeats = 100.0f;
  const float n = facingUp ? 1.0f : -1.0f;
  Mesh plane;
  plane.positions = {
      {-kHalf, height, -kHalf}, {kHalf, height, -kHalf}, {kHalf, height, kHalf}, {-kHalf, height, kHalf}};
  plane.normals = {{0, n, 0}, {0, n, 0}, {0, n, 0}, {0, n, 0}};
  plane.uvs = {{0, 0}, {kRepeats, 0}, {kRepeats, kRepeats}, {0, kRepeats}};
  plane.indices = facingUp ? std::vector<uint32_t>{0, 2, 1, 0, 3, 2} : std::vector<uint32_t>{0, 1, 2, 0, 2, 3};
  plane.triangleMaterials = {materialId, materialId};
  return plane;
}

Material emitting(uint32_t texture) {
  Material m;
  m.baseColor = {0, 0, 0};
  m.emission = {1, 1, 1};
  m.emissionTexture = int32_t(texture);
  return m;
}

void lookTowardsTheHorizon(Scene& scene) {
  scene.environment.radiance = {0, 0, 0};
  scene.camera.eye = {0.3f, 1.0f, 0.0f};
  scene.camera.target = {0.0f, 0.75f, -10.0f};
  scene.camera.verticalFovDegrees = 40.0f;
}

}  // namespace

Scene recedingTexturedPlane(const Texture& texture) {
  Scene scene;
  scene.name = "receding-textured-plane";
  scene.materials = {emitting(0)};
  scene.textures = {texture};
  scene.meshes = {texturedPlane(0.0f, true, 0)};
  scene.instances = {{0, Affine3x4{}}};
  lookTowardsTheHorizon(scene);
  return scene;
}

Scene mirroredTexturedCeiling(const Texture& texture) {
  Scene scene;
  scene.name = "mirrored-textured-ceiling";
  Material mirror;
  mirror.type = MaterialType::Mirror;
  mirror.specularColor = {1, 1, 1};
  scene.materials = {emitting(0), mirror};
  scene.textures = {texture};
  scene.meshes = {texturedPlane(2.0f, false, 0), texturedPlane(0.0f, true, 1)};
  scene.meshes[1].uvs.clear();
  scene.instances = {{0, Affine3x4{}}, {1, Affine3x4{}}};
  lookTowardsTheHorizon(scene);
  return scene;
}

double meanSquaredDifference(const Image& a, const Image& b) { return meanSquaredDifference(a, b, 0, a.height); }

double meanSquaredDifference(const Image& a, const Image& b, uint32_t firstRow, uint32_t rows) {
  double sum = 0.0;
  size_t count = 0;
  for (uint32_t y = firstRow; y < firstRow + rows && y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x, ++count) {
      const double d = double(luminance(a.at(x, y))) - double(luminance(b.at(x, y)));
      sum += d * d;
    }
  return count == 0 ? 0.0 : sum / double(count);
}

double meanLuminance(const Image& image) {
  double sum = 0.0;
  for (const Vec3& p : image.pixels) sum += luminance(p);
  return image.pixels.empty() ? 0.0 : sum / double(image.pixels.size());
}

}  // namespace candela::test
