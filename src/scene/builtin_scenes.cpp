#include "scene/builtin_scenes.h"

#include "scene/mesh_builders.h"

namespace candela {

namespace {

constexpr float kMillimetre = 0.001f;
Vec3 mm(float x, float y, float z) { return Vec3{x, y, z} * kMillimetre; }

Material diffuse(Vec3 albedo, Vec3 emission = {0, 0, 0}) {
  Material m;
  m.type = MaterialType::Diffuse;
  m.baseColor = albedo;
  m.emission = emission;
  return m;
}

// A block from its four floor corners and height, faces wound outwards.
void appendBlock(Mesh& mesh, const Vec3 (&floor)[4], float height, uint32_t material) {
  Vec3 centre = (floor[0] + floor[1] + floor[2] + floor[3]) * 0.25f + Vec3{0, height * 0.5f, 0};
  auto up = [&](Vec3 p) { return p + Vec3{0, height, 0}; };
  auto away = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return (a + b + c + d) * 0.5f - centre; };
  Vec3 t0 = up(floor[0]), t1 = up(floor[1]), t2 = up(floor[2]), t3 = up(floor[3]);
  appendQuad(mesh, t0, t1, t2, t3, away(t0, t1, t2, t3), material);
  for (int i = 0; i < 4; ++i) {
    Vec3 a = floor[i], b = floor[(i + 1) % 4];
    appendQuad(mesh, a, b, up(b), up(a), away(a, b, up(b), up(a)), material);
  }
}

// The Cornell box's walls, light and camera, without the two blocks.
Scene makeCornellRoom() {
  Scene scene;
  enum : uint32_t { kWhite, kRed, kGreen, kLight };
  scene.materials = {diffuse({0.725f, 0.71f, 0.68f}), diffuse({0.63f, 0.065f, 0.05f}),
                     diffuse({0.14f, 0.45f, 0.091f}), diffuse({0.78f, 0.78f, 0.78f}, {17.0f, 12.0f, 4.0f})};

  Mesh room;
  room.name = "room";
  Vec3 inside = mm(278.0f, 274.4f, 279.6f);
  appendQuad(room, mm(552.8f, 0, 0), mm(0, 0, 0), mm(0, 0, 559.2f), mm(549.6f, 0, 559.2f), inside, kWhite);
  appendQuad(room, mm(556.0f, 548.8f, 0), mm(556.0f, 548.8f, 559.2f), mm(0, 548.8f, 559.2f), mm(0, 548.8f, 0),
             inside, kWhite);
  appendQuad(room, mm(549.6f, 0, 559.2f), mm(0, 0, 559.2f), mm(0, 548.8f, 559.2f), mm(556.0f, 548.8f, 559.2f),
             inside, kWhite);
  appendQuad(room, mm(0, 0, 559.2f), mm(0, 0, 0), mm(0, 548.8f, 0), mm(0, 548.8f, 559.2f), inside, kGreen);
  appendQuad(room, mm(552.8f, 0, 0), mm(549.6f, 0, 559.2f), mm(556.0f, 548.8f, 559.2f), mm(556.0f, 548.8f, 0),
             inside, kRed);
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
  scene.materials = {diffuse({albedo, albedo, albedo}, {emission, emission, emission})};
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
  scene.materials = {diffuse({1, 1, 1})};
  scene.meshes.push_back(makeUvSphere(1.0f, 64, 32, 0, /*inward=*/false));
  scene.instances.push_back({0, Affine3x4{}});
  scene.environment.radiance = {1, 1, 1};
  scene.camera.eye = {0, 0, -4};
  scene.camera.target = {0, 0, 0};
  scene.camera.verticalFovDegrees = 40.0f;
  return scene;
}

std::vector<std::string> builtinSceneNames() {
  return {"cornell-box", "cornell-spheres", "white-furnace", "closed-sphere"};
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
  else
    return false;
  return true;
}

}  // namespace candela
