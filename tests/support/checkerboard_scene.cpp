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

Scene recedingTexturedPlane(const Texture& texture) {
  Scene scene;
  scene.name = "receding-textured-plane";
  Material m;
  m.baseColor = {0, 0, 0};
  m.emission = {1, 1, 1};
  m.emissionTexture = 0;
  scene.materials = {m};
  scene.textures = {texture};
  // 400 x 400 units in the plane y = 0, the texture repeated 100 times along each side (4 units a tile).
  constexpr float kHalf = 200.0f, kRepeats = 100.0f;
  Mesh plane;
  plane.positions = {{-kHalf, 0, -kHalf}, {kHalf, 0, -kHalf}, {kHalf, 0, kHalf}, {-kHalf, 0, kHalf}};
  plane.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  plane.uvs = {{0, 0}, {kRepeats, 0}, {kRepeats, kRepeats}, {0, kRepeats}};
  plane.indices = {0, 2, 1, 0, 3, 2};  // wound to face +y
  plane.triangleMaterials = {0, 0};
  scene.meshes = {plane};
  scene.instances = {{0, Affine3x4{}}};
  scene.environment.radiance = {0, 0, 0};
  scene.camera.eye = {0.3f, 1.0f, 0.0f};
  scene.camera.target = {0.0f, 0.75f, -10.0f};
  scene.camera.verticalFovDegrees = 40.0f;
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
