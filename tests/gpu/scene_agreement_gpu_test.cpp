// CPU and GPU renders of the scenes that exercise the other material models, textures, normal maps and
// environment maps must agree (see expectRendersAgree): the GPU runs the same kernel on its own traversal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "app/scene_loading.h"
#include "backend_agreement.h"
#include "kernel/bsdf/hair.h"
#include "many_lights_scene.h"
#include "support/cutout_screen.h"

namespace candela {
namespace {

// `scene` with every instance's mesh cut into meshes of at most `triangles` triangles, each keeping only the
// vertices it uses and having that instance alone. Each instance's pieces are moved in object space by an
// offset of their own, which the instance's transform takes back, so that no two pieces are equal meshes.
Scene splitIntoMeshes(const Scene& scene, size_t triangles) {
  Scene split = scene;
  split.meshes.clear();
  split.instances.clear();
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    Instance instance = scene.instances[i];
    const Vec3 offset{0.5f * float(i + 1), 0.25f, 0.0f};
    const Vec3 shift = instance.objectToWorld.vector(offset);
    instance.objectToWorld.m[3] -= shift.x;
    instance.objectToWorld.m[7] -= shift.y;
    instance.objectToWorld.m[11] -= shift.z;
    const Mesh& mesh = scene.meshes[instance.meshId];
    for (size_t first = 0; first < mesh.triangleCount(); first += triangles) {
      Mesh piece;
      piece.name = mesh.name + " piece " + std::to_string(first / triangles);
      std::vector<uint32_t> remap(mesh.positions.size(), UINT32_MAX);
      for (size_t t = first; t < std::min(first + triangles, mesh.triangleCount()); ++t) {
        piece.triangleMaterials.push_back(mesh.triangleMaterials[t]);
        for (size_t k = 0; k < 3; ++k) {
          const uint32_t v = mesh.indices[3 * t + k];
          if (remap[v] == UINT32_MAX) {
            remap[v] = uint32_t(piece.positions.size());
            piece.positions.push_back(mesh.positions[v] + offset);
            if (!mesh.normals.empty()) piece.normals.push_back(mesh.normals[v]);
            if (!mesh.uvs.empty()) piece.uvs.push_back(mesh.uvs[v]);
            if (!mesh.tangents.empty()) piece.tangents.push_back(mesh.tangents[v]);
            if (!mesh.colors.empty()) piece.colors.push_back(mesh.colors[v]);
          }
          piece.indices.push_back(remap[v]);
        }
      }
      split.instances.push_back({uint32_t(split.meshes.size()), instance.objectToWorld});
      split.meshes.push_back(std::move(piece));
    }
  }
  return split;
}

void expectBackendsAgree(const Scene& scene, uint32_t seed, LightSamplerKind lightSampler = LightSamplerKind::Bvh) {
  test::AgreementRun run;
  run.lightSampler = lightSampler;
  test::expectBackendsAgree(scene, seed, run);
}

// Disney BSDF rows (metallic, sheen, clearcoat, subsurface, transmission) and a diffuse floor and wall.
TEST(GpuMaterialGallery, AgreesWithTheCpuBackend) { expectBackendsAgree(makeMaterialGallery(), 41); }

// Mirrors: delta lobes, paths that reach the light only by reflection.
TEST(GpuMirrorCorridor, AgreesWithTheCpuBackend) { expectBackendsAgree(makeMirrorCorridor(), 51); }

// Cut-outs (support/cutout_screen.h): an alpha-tested checker or alpha blending, and culled back faces, in
// one mesh with an opaque floor; shadow and bounce rays cross them.
TEST(GpuCutoutScreen, AgreesWithTheCpuBackend) {
  expectBackendsAgree(test::makeCutoutScreen(test::ScreenCoverage::CheckerMask), 71);
  expectBackendsAgree(test::makeCutoutScreen(test::ScreenCoverage::HalfBlend), 81);
}

// Mix materials, chosen per shading point by the same hash on both backends: the material gallery with each
// material mixed with the next (amount 0.4, the mix keeping the first's emission), and the floor's mix mixed
// again with the next mix through a texture (nested, and a textured amount).
TEST(GpuMixedMaterials, AgreeWithTheCpuBackend) {
  Scene scene = makeMaterialGallery();
  const uint32_t n = uint32_t(scene.materials.size());
  for (uint32_t i = 0; i < n; ++i) {
    Material mix;
    mix.type = MaterialType::Mix;
    mix.mixedMaterials[0] = i;
    mix.mixedMaterials[1] = (i + 1) % n;
    mix.mixAmount = 0.4f;
    mix.emission = scene.materials[i].emission;
    scene.materials.push_back(mix);
  }
  Texture amount;
  amount.width = amount.height = 2;
  amount.channels = 1;
  amount.bytes = {40, 220, 220, 40};
  scene.textures.push_back(amount);
  Material nested = scene.materials[n];
  nested.mixedMaterials[0] = n;
  nested.mixedMaterials[1] = n + 1;
  nested.mixAmount = 0.9f;
  nested.mixAmountTexture = int32_t(scene.textures.size() - 1);
  scene.materials.push_back(nested);
  if (!scene.materialNames.empty()) scene.materialNames.resize(scene.materials.size(), "mix");
  for (Mesh& mesh : scene.meshes)
    for (uint32_t& m : mesh.triangleMaterials) m = m == 0 ? 2 * n : n + m;
  expectBackendsAgree(scene, 131);
}

// Scenes of many meshes have them built many to a GAS, in world space (acceleration.cpp): the Cornell spheres
// cut into about 5,000 meshes of one instance each (several batches, and both spheres' transforms) must render
// as the CPU backend renders them.
TEST(GpuManyMeshes, AgreesWithTheCpuBackend) {
  const Scene split = splitIntoMeshes(makeCornellSpheres(), 64);
  ASSERT_GT(split.meshes.size(), 4000u);
  auto backend = test::makeBackend<OptixBackend>(split, test::squareImage(test::AgreementRun{}.size, 1));
  EXPECT_GT(backend->accelerationStatistics().batchedMeshes, 4000u);
  expectBackendsAgree(split, 91);
}

// Hundreds of small lights (bench/many_lights_scene.h: 288 windows and 49 street lamps among buildings), picked
// through the light BVH and by power, some sampled by solid angle and some by area.
TEST(GpuNightTown, AgreesWithTheCpuBackendWithEitherLightSampler) {
  const Scene town = makeNightTown(6, 1);
  expectBackendsAgree(town, 111, LightSamplerKind::Bvh);
  expectBackendsAgree(town, 121, LightSamplerKind::Power);
}

// Point lights in the light BVH and in the power table (bench/many_lights_scene.h: 200 of them over a field of
// pillars), with a directional light and a spot light picked beside and among them.
TEST(GpuPointField, AgreesWithTheCpuBackendWithEitherLightSampler) {
  Scene field = makePointLitField(200, 1);
  PunctualLight sun;
  sun.type = PunctualLightType::Directional;
  sun.direction = normalize(Vec3{0.3f, -1.0f, 0.2f});
  sun.intensity = {0.5f, 0.5f, 0.5f};
  field.punctualLights.push_back(sun);
  PunctualLight spot;
  spot.type = PunctualLightType::Spot;
  spot.position = {0.0f, 8.0f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.intensity = {40.0f, 40.0f, 40.0f};
  spot.cosInner = 0.9f;
  spot.cosOuter = 0.7f;
  field.punctualLights.push_back(spot);
  expectBackendsAgree(field, 131, LightSamplerKind::Bvh);
  expectBackendsAgree(field, 141, LightSamplerKind::Power);
}

// Textured glTF materials with a normal map, lit by an importance-sampled environment map.
TEST(GpuDamagedHelmet, AgreesWithTheCpuBackendUnderAnEnvironmentMap) {
  std::filesystem::path shared = CANDELA_SHARED_SCENES;
  std::filesystem::path model = shared / "damaged_helmet/glTF-Binary/DamagedHelmet.glb";
  std::filesystem::path environment = shared / "envmaps/royal_esplanade_1k.hdr";
  if (!std::filesystem::exists(model) || !std::filesystem::exists(environment))
    GTEST_SKIP() << "shared scenes not found at " << shared;
  expectBackendsAgree(loadScene(model.string(), {environment.string()}), 61);
}

// Vertex colours (glTF COLOR_0) multiply the base colour: the material gallery with a colour per vertex made
// from its position, on every mesh but the first (which keeps none).
TEST(GpuVertexColours, AgreeWithTheCpuBackend) {
  Scene scene = makeMaterialGallery();
  for (size_t m = 1; m < scene.meshes.size(); ++m) {
    Mesh& mesh = scene.meshes[m];
    mesh.colors.clear();
    for (Vec3 p : mesh.positions)
      mesh.colors.push_back({0.5f + 0.5f * std::sin(3.0f * p.x), 0.5f + 0.5f * std::sin(3.0f * p.y), 0.75f});
  }
  expectBackendsAgree(scene, 101);
}

// Absorbing volumes (glTF's KHR_materials_volume): the gallery's transmissive spheres absorb inside, red least.
TEST(GpuAbsorbingVolumes, AgreeWithTheCpuBackend) {
  Scene scene = makeMaterialGallery();
  size_t absorbing = 0;
  for (Material& m : scene.materials)
    if (m.specTrans > 0.0f || m.type == MaterialType::Glass) {
      m.absorption = {0.3f, 1.0f, 2.5f};
      ++absorbing;
    }
  ASSERT_GT(absorbing, 0u);
  expectBackendsAgree(scene, 121);
}

// Iridescent films (glTF's KHR_materials_iridescence, kernel/bsdf/thin_film.h): every sphere of the gallery but
// the transmissive ones gets a film, half of them as the metallic-roughness model, the others kept Disney; the
// first sphere's film takes its strength (R) and thickness (G) from a texture.
TEST(GpuIridescentFilms, AgreeWithTheCpuBackend) {
  Scene scene = makeMaterialGallery();
  Texture film;
  film.width = film.height = 2;
  film.channels = 3;
  film.bytes = {255, 0, 0, 128, 255, 0, 200, 100, 0, 60, 200, 0};
  scene.textures.push_back(film);
  size_t iridescent = 0;
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    Material& m = scene.materials[i];
    if (m.type != MaterialType::Disney || m.specTrans > 0.0f) continue;
    if (i % 2 == 1) m.type = MaterialType::Pbr;
    m.iridescence = 1.0f;
    m.iridescenceIor = i % 3 == 0 ? 1.3f : 1.8f;
    m.iridescenceThickness = 250.0f + 50.0f * float(i % 5);
    ++iridescent;
  }
  ASSERT_GT(iridescent, 2u);
  Material& textured = scene.materials[0];
  textured.iridescenceTexture = textured.iridescenceThicknessTexture = int32_t(scene.textures.size() - 1);
  textured.iridescenceThicknessMinimum = 100.0f;
  expectBackendsAgree(scene, 141);
}

// Hair (pbrt-v4's HairBxDF, kernel/bsdf/hair.h): the gallery's Disney spheres become fibres wound round them, of
// absorptions from none to dark brown and roughnesses of their own. The spheres get texture coordinates (u round
// the vertical axis, v from pole to pole), from which the scene generates the tangents the fibres run along and
// the kernel takes each point's offset across its fibre.
TEST(GpuHair, AgreesWithTheCpuBackend) {
  Scene scene = makeMaterialGallery();
  size_t hair = 0;
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    Material& m = scene.materials[i];
    if (m.type != MaterialType::Disney) continue;
    m.type = MaterialType::Hair;
    m.fibreAbsorption = HairBsdf::absorptionOfMelanin(0.4f * float(i % 5), 0.3f * float(i % 3));
    m.roughness = 0.2f + 0.15f * float(i % 4);
    m.azimuthalRoughness = 0.25f + 0.2f * float(i % 3);
    m.scaleTilt = i % 2 == 0 ? 2.0f : 0.0f;
    m.ior = 1.55f;
    ++hair;
  }
  ASSERT_GT(hair, 2u);
  for (Mesh& mesh : scene.meshes) {
    if (scene.materials[mesh.triangleMaterials[0]].type != MaterialType::Hair) continue;
    mesh.uvs.clear();
    for (Vec3 n : mesh.normals)
      mesh.uvs.push_back({0.5f + std::atan2(n.z, n.x) / (2.0f * kPi), std::acos(std::clamp(n.y, -1.0f, 1.0f)) / kPi});
  }
  expectBackendsAgree(scene, 161);
}

// Khronos sample models for what the kernel does beyond the core model: normal maps steep enough that
// reflections are kept above the surface (NormalTangentMirrorTest), transmission of every roughness including
// the index-matched ior 1 row (TransmissionRoughnessTest), and sampler wrap modes per axis
// (TextureSettingsTest).
TEST(GpuGltfMaterialTests, AgreeWithTheCpuBackend) {
  std::filesystem::path shared = CANDELA_SHARED_SCENES;
  std::filesystem::path environment = shared / "envmaps/royal_esplanade_1k.hdr";
  uint32_t seed = 111;
  for (const char* name : {"NormalTangentMirrorTest", "TransmissionRoughnessTest", "TextureSettingsTest"}) {
    std::filesystem::path model = shared / "gltf_material_tests" / name / "glTF" / (std::string(name) + ".gltf");
    if (!std::filesystem::exists(model) || !std::filesystem::exists(environment))
      GTEST_SKIP() << "shared scenes not found at " << shared;
    SCOPED_TRACE(name);
    expectBackendsAgree(loadScene(model.string(), {environment.string()}), seed += 10);
  }
}

}  // namespace
}  // namespace candela
