#include "scene/builtin_scenes.h"

#include "scene/mesh_builders.h"
#include "scene/transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace candela {

namespace {

constexpr float kMillimetre = 0.001f;
Vec3 mm(float x, float y, float z) { return Vec3{x, y, z} * kMillimetre; }

// The Cornell box's walls, light and camera, without the two blocks.
Scene makeCornellRoom() {
  Scene scene;
  enum : uint32_t { kWhite, kRed, kGreen, kLight };
  scene.materials = {diffuseMaterial({0.725f, 0.71f, 0.68f}), diffuseMaterial({0.63f, 0.065f, 0.05f}),
                     diffuseMaterial({0.14f, 0.45f, 0.091f}),
                     diffuseMaterial({0.78f, 0.78f, 0.78f}, {17.0f, 12.0f, 4.0f})};

  Mesh room;
  room.name = "room";
  Vec3 inside = mm(278.0f, 274.4f, 279.6f);
  appendQuad(room, mm(552.8f, 0, 0), mm(0, 0, 0), mm(0, 0, 559.2f), mm(549.6f, 0, 559.2f), inside, kWhite);
  appendQuad(room, mm(556.0f, 548.8f, 0), mm(556.0f, 548.8f, 559.2f), mm(0, 548.8f, 559.2f), mm(0, 548.8f, 0), inside,
             kWhite);
  appendQuad(room, mm(549.6f, 0, 559.2f), mm(0, 0, 559.2f), mm(0, 548.8f, 559.2f), mm(556.0f, 548.8f, 559.2f), inside,
             kWhite);
  appendQuad(room, mm(0, 0, 559.2f), mm(0, 0, 0), mm(0, 548.8f, 0), mm(0, 548.8f, 559.2f), inside, kGreen);
  appendQuad(room, mm(552.8f, 0, 0), mm(549.6f, 0, 559.2f), mm(556.0f, 548.8f, 559.2f), mm(556.0f, 548.8f, 0), inside,
             kRed);
  // The light hangs a fraction of a millimetre below the ceiling so that the two never coincide.
  appendQuad(room, mm(343.0f, 548.7f, 227.0f), mm(343.0f, 548.7f, 332.0f), mm(213.0f, 548.7f, 332.0f),
             mm(213.0f, 548.7f, 227.0f), inside, kLight);
  scene.meshes.push_back(std::move(room));
  scene.instances.push_back({0, Affine3x4{}});
  scene.camera.eye = mm(278.0f, 273.0f, -800.0f);
  scene.camera.target = mm(278.0f, 273.0f, 0.0f);
  scene.camera.up = {0, 1, 0};
  scene.camera.verticalFovDegrees = 2.0f * atanf(12.5f / 35.0f) * 180.0f / kPi;
  return scene;
}

constexpr uint32_t kCornellWhite = 0;

}  // namespace

Scene makeCornellBox() {
  Scene scene = makeCornellRoom();
  scene.name = "cornell-box";
  Mesh& room = scene.meshes[0];
  const Vec3 shortBlock[4] = {mm(130, 0, 65), mm(82, 0, 225), mm(240, 0, 272), mm(290, 0, 114)};
  const Vec3 tallBlock[4] = {mm(423, 0, 247), mm(265, 0, 296), mm(314, 0, 456), mm(472, 0, 406)};
  appendBlock(room, shortBlock, 165.0f * kMillimetre, kCornellWhite);
  appendBlock(room, tallBlock, 330.0f * kMillimetre, kCornellWhite);
  return scene;
}

Scene makeCornellSpheres() {
  Scene scene = makeCornellRoom();
  scene.name = "cornell-spheres";
  scene.meshes.push_back(makeUvSphere(1.0f, 400, 200, kCornellWhite, /*inward=*/false));
  auto placeSphere = [&](Vec3 centre, float radius) {
    Affine3x4 t;
    t.m[0] = t.m[5] = t.m[10] = radius;
    t.m[3] = centre.x;
    t.m[7] = centre.y;
    t.m[11] = centre.z;
    scene.instances.push_back({1, t});
  };
  placeSphere(mm(186, 100, 169), 0.1f);
  placeSphere(mm(368, 140, 351), 0.14f);
  return scene;
}

Scene makeClosedEmissiveSphere(float albedo, float emission) {
  Scene scene;
  scene.name = "closed-sphere";
  scene.materials = {diffuseMaterial({albedo, albedo, albedo}, {emission, emission, emission})};
  scene.meshes.push_back(makeUvSphere(1.0f, 48, 24, 0, /*inward=*/true));
  // Interpolated normals would break the energy balance the analytic answer rests on: keep the facets.
  scene.meshes.back().normals.clear();
  scene.instances.push_back({0, Affine3x4{}});
  scene.camera.eye = {0, 0, 0};
  scene.camera.target = {0, 0, 1};
  scene.camera.verticalFovDegrees = 90.0f;
  return scene;
}

Scene makeWhiteFurnace() {
  Scene scene;
  scene.name = "white-furnace";
  scene.materials = {diffuseMaterial({1, 1, 1})};
  scene.meshes.push_back(makeUvSphere(1.0f, 64, 32, 0, /*inward=*/false));
  scene.instances.push_back({0, Affine3x4{}});
  scene.environment.radiance = {1, 1, 1};
  scene.camera.eye = {0, 0, -4};
  scene.camera.target = {0, 0, 0};
  scene.camera.verticalFovDegrees = 40.0f;
  return scene;
}

namespace {

// Adds a sphere with its own material, placed by an instance.
void addSphere(Scene& scene, Vec3 centre, float radius, const Material& material) {
  uint32_t materialId = uint32_t(scene.materials.size());
  scene.materials.push_back(material);
  scene.meshes.push_back(makeUvSphere(radius, 48, 24, materialId, /*inward=*/false));
  glm::mat4 placement = glm::translate(glm::mat4(1.0f), glm::vec3(centre.x, centre.y, centre.z));
  scene.instances.push_back({uint32_t(scene.meshes.size() - 1), toAffine(placement)});
}

// Adds one mesh holding a quad with its own material.
void addQuad(Scene& scene, Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 towards, const Material& material) {
  uint32_t materialId = uint32_t(scene.materials.size());
  scene.materials.push_back(material);
  Mesh mesh;
  mesh.name = "quad";
  appendQuad(mesh, a, b, c, d, towards, materialId);
  scene.meshes.push_back(std::move(mesh));
  scene.instances.push_back({uint32_t(scene.meshes.size() - 1), Affine3x4{}});
}

Material disney(Vec3 baseColor, float roughness) {
  Material m;
  m.type = MaterialType::Disney;
  m.baseColor = baseColor;
  m.roughness = roughness;
  return m;
}

}  // namespace

Scene makeMaterialGallery() {
  Scene scene;
  scene.name = "material-gallery";
  constexpr int kColumns = 7;
  constexpr float kSpacing = 1.0f, kRadius = 0.42f;
  struct Row {
    Material base;
    float Material::*parameter;
  };
  Material gold = disney({1.0f, 0.71f, 0.29f}, 0.0f);
  gold.metallic = 1.0f;
  Material clearcoated = disney({0.55f, 0.05f, 0.05f}, 0.6f);
  clearcoated.clearcoatGloss = 0.9f;
  Material glass = disney({0.95f, 0.95f, 0.95f}, 0.1f);
  glass.ior = 1.5f;
  const Row rows[] = {
      {gold, &Material::roughness},
      {disney({0.9f, 0.3f, 0.2f}, 0.3f), &Material::metallic},
      {disney({0.1f, 0.12f, 0.45f}, 0.8f), &Material::sheen},
      {clearcoated, &Material::clearcoat},
      {disney({0.9f, 0.65f, 0.5f}, 0.5f), &Material::subsurface},
      {glass, &Material::specTrans},
  };
  constexpr int kRows = int(sizeof rows / sizeof rows[0]);
  for (int r = 0; r < kRows; ++r)
    for (int c = 0; c < kColumns; ++c) {
      Material m = rows[r].base;
      m.*rows[r].parameter = float(c) / float(kColumns - 1);
      // The camera looks along +z, so +x is on the left of the image.
      Vec3 centre{(0.5f * float(kColumns - 1) - float(c)) * kSpacing, (float(kRows - 1 - r) + 0.5f) * kSpacing, 0.0f};
      addSphere(scene, centre, kRadius, m);
    }
  float halfWidth = 0.5f * kColumns * kSpacing + 2.0f;
  addQuad(scene, {-halfWidth, 0, -4}, {halfWidth, 0, -4}, {halfWidth, 0, 4}, {-halfWidth, 0, 4}, {0, 1, 0},
          diffuseMaterial({0.5f, 0.5f, 0.5f}));
  addQuad(scene, {-halfWidth, 0, 1}, {halfWidth, 0, 1}, {halfWidth, 8, 1}, {-halfWidth, 8, 1}, {0, 0, 0},
          diffuseMaterial({0.35f, 0.35f, 0.35f}));
  addQuad(scene, {-2.5f, 9, -6}, {2.5f, 9, -6}, {2.5f, 9, -2}, {-2.5f, 9, -2}, {0, 0, 0},
          diffuseMaterial({0, 0, 0}, {6.0f, 6.0f, 6.0f}));
  scene.environment.radiance = {0.25f, 0.27f, 0.3f};
  scene.camera.eye = {0.0f, 3.0f, -14.0f};
  scene.camera.target = {0.0f, 3.0f, 0.0f};
  scene.camera.verticalFovDegrees = 28.0f;
  return scene;
}

Scene makeMirrorCorridor() {
  Scene scene;
  scene.name = "mirror-corridor";
  constexpr float kHalfWidth = 1.0f, kHeight = 2.5f, kHalfLength = 3.0f;
  Material mirror;
  mirror.type = MaterialType::Mirror;
  mirror.specularColor = {0.95f, 0.95f, 0.95f};
  addQuad(scene, {-kHalfWidth, 0, -kHalfLength}, {-kHalfWidth, 0, kHalfLength}, {-kHalfWidth, kHeight, kHalfLength},
          {-kHalfWidth, kHeight, -kHalfLength}, {0, 1, 0}, mirror);
  addQuad(scene, {kHalfWidth, 0, -kHalfLength}, {kHalfWidth, 0, kHalfLength}, {kHalfWidth, kHeight, kHalfLength},
          {kHalfWidth, kHeight, -kHalfLength}, {0, 1, 0}, mirror);
  addQuad(scene, {-kHalfWidth, 0, -kHalfLength}, {kHalfWidth, 0, -kHalfLength}, {kHalfWidth, 0, kHalfLength},
          {-kHalfWidth, 0, kHalfLength}, {0, 1, 0}, diffuseMaterial({0.6f, 0.6f, 0.6f}));
  // A light strip along the whole ceiling: paths that reach it only through the mirrors (which light sampling
  // cannot follow) find it often enough to converge quickly.
  addQuad(scene, {-0.5f, kHeight, -kHalfLength}, {0.5f, kHeight, -kHalfLength}, {0.5f, kHeight, kHalfLength},
          {-0.5f, kHeight, kHalfLength}, {0, 0, 0}, diffuseMaterial({0, 0, 0}, {3.0f, 2.8f, 2.4f}));
  addSphere(scene, {0.0f, 0.35f, 0.8f}, 0.35f, diffuseMaterial({0.7f, 0.15f, 0.1f}));
  addSphere(scene, {-0.35f, 0.25f, -0.3f}, 0.25f, diffuseMaterial({0.15f, 0.35f, 0.7f}));
  Material gold = disney({1.0f, 0.71f, 0.29f}, 0.25f);
  gold.metallic = 1.0f;
  addSphere(scene, {0.4f, 0.3f, 0.0f}, 0.3f, gold);
  // Standing close to one mirror and looking across at the other, the camera sees both walls' reflections
  // of each other recede; the mirrors' planes are exactly parallel, so the images line up.
  scene.camera.eye = {0.75f, 1.1f, -2.8f};
  scene.camera.target = {-1.0f, 0.8f, 0.6f};
  scene.camera.verticalFovDegrees = 55.0f;
  return scene;
}

std::vector<std::string> builtinSceneNames() {
  return {"cornell-box", "cornell-spheres", "white-furnace", "closed-sphere", "material-gallery", "mirror-corridor"};
}

bool makeBuiltinScene(const std::string& name, Scene& scene) {
  if (name == "cornell-box")
    scene = makeCornellBox();
  else if (name == "cornell-spheres")
    scene = makeCornellSpheres();
  else if (name == "white-furnace")
    scene = makeWhiteFurnace();
  else if (name == "closed-sphere")
    scene = makeClosedEmissiveSphere(0.5f, 0.5f);
  else if (name == "material-gallery")
    scene = makeMaterialGallery();
  else if (name == "mirror-corridor")
    scene = makeMirrorCorridor();
  else
    return false;
  return true;
}

}  // namespace candela
