#include "support/cutout_screen.h"

#include "scene/mesh_builders.h"

namespace candela::test {

namespace {

constexpr float kScreenHalfSize = 200.0f;
constexpr float kCheckerPeriod = 0.25f;  // the camera sees a square of side 1

// A quad facing `towards`, with texture coordinates that repeat every kCheckerPeriod in x and z.
void appendTexturedQuad(Mesh& mesh, float y, float halfSize, Vec3 towards, uint32_t material) {
  appendQuad(mesh, {-halfSize, y, -halfSize}, {halfSize, y, -halfSize}, {halfSize, y, halfSize},
             {-halfSize, y, halfSize}, towards, material);
  for (size_t i = mesh.positions.size() - 4; i < mesh.positions.size(); ++i)
    mesh.uvs.push_back({mesh.positions[i].x / kCheckerPeriod, mesh.positions[i].z / kCheckerPeriod});
}

}  // namespace

Scene makeCutoutScreen(ScreenCoverage coverage) {
  Scene scene;
  scene.name = "cutout-screen";
  Material floor;
  floor.baseColor = {kScreenFloorAlbedo, kScreenFloorAlbedo, kScreenFloorAlbedo};
  Material screen;
  screen.baseColor = {0, 0, 0};
  Material culled = screen;
  culled.doubleSided = 0;
  switch (coverage) {
    case ScreenCoverage::CheckerMask:
      screen.alphaMode = AlphaMode::Mask;
      screen.opacityTexture = 0;
      break;
    case ScreenCoverage::HalfBlend:
      screen.alphaMode = AlphaMode::Blend;
      screen.opacity = 0.5f;
      break;
    case ScreenCoverage::Opaque:
    case ScreenCoverage::Absent: break;
  }
  scene.materials = {floor, screen, culled};

  Texture checker;
  checker.name = "a 2x2 checker";
  checker.width = checker.height = 2;
  checker.channels = 1;
  checker.bytes = {255, 0, 0, 255};
  scene.textures.push_back(checker);

  Mesh mesh;
  appendTexturedQuad(mesh, 0.0f, 1.0f, {0, 1, 0}, 0);
  if (coverage != ScreenCoverage::Absent) appendTexturedQuad(mesh, 1.0f, kScreenHalfSize, {0, 0, 0}, 1);
  appendTexturedQuad(mesh, 0.75f, 1.0f, {0, 2, 0}, 2);
  scene.meshes.push_back(mesh);
  scene.instances.push_back({0, Affine3x4{}});
  scene.environment.radiance = {1, 1, 1};
  scene.camera.eye = {0, 0.5f, 0};
  scene.camera.target = {0, 0, 0};
  scene.camera.up = {0, 0, 1};
  scene.camera.verticalFovDegrees = 90.0f;
  return scene;
}

}  // namespace candela::test
