#include "light_transport_scenes.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/scene_loading.h"
#include "media/media_scenes.h"
#include "media/nanovdb_files.h"

namespace candela::test {
namespace {

std::string numbers(const std::vector<float>& values) {
  std::ostringstream text;
  text << '[';
  for (float v : values) text << ' ' << v;
  text << " ]";
  return text.str();
}

// `mesh`'s triangles as a pbrt trianglemesh.
std::string trianglemesh(const Mesh& mesh) {
  std::vector<float> points;
  for (Vec3 p : mesh.positions) points.insert(points.end(), {p.x, p.y, p.z});
  std::ostringstream text;
  text << "Shape \"trianglemesh\" \"point3 P\" " << numbers(points) << " \"integer indices\" [";
  for (uint32_t i : mesh.indices) text << ' ' << i;
  text << " ]\n";
  return text.str();
}

std::string quad(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  Mesh mesh;
  appendQuad(mesh, a, b, c, d, {0, 1, 0}, 0);
  return trianglemesh(mesh);
}

// The box [lo, hi], closed and wound outwards, so that a MediumInterface's inside is the box's inside.
std::string box(Vec3 lo, Vec3 hi) {
  Mesh mesh;
  appendBox(mesh, lo, hi, 0);
  return trianglemesh(mesh);
}

std::string sphere(Vec3 centre, float radius) {
  std::ostringstream text;
  text << "Translate " << centre.x << ' ' << centre.y << ' ' << centre.z << "\nShape \"sphere\" \"float radius\" "
       << radius << '\n';
  return text.str();
}

// One shape with its own material and media, in an attribute block of its own.
std::string object(const std::string& material, const std::string& mediumInterface, const std::string& shape) {
  std::string text = "AttributeBegin\nMaterial " + material + "\n";
  if (!mediumInterface.empty()) text += "MediumInterface " + mediumInterface + "\n";
  return text + shape + "AttributeEnd\n";
}

// The room x in [-1, 1], y in [0, 2], z in [-1, 1], open at z = -1 where the camera looks in from, its camera in
// the medium `cameraMedium` (none where empty), and `contents` in it.
std::string room(const std::string& contents, const std::string& cameraMedium = "") {
  std::string text;
  if (!cameraMedium.empty()) text += "MediumInterface \"\" \"" + cameraMedium + "\"\n";
  text +=
      "LookAt 0 1 -3.4  0 1 0  0 1 0\nCamera \"perspective\" \"float fov\" 38\n"
      "Film \"rgb\" \"integer xresolution\" 64 \"integer yresolution\" 64\nWorldBegin\n"
      // The room's own surfaces bound no medium: a ray that meets them stays in the medium it was in.
      "MediumInterface \"\" \"\"\n"
      "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [10 8 6] \"bool twosided\" true\n" +
      quad({-0.3f, 1.98f, -0.3f}, {0.3f, 1.98f, -0.3f}, {0.3f, 1.98f, 0.3f}, {-0.3f, 1.98f, 0.3f}) + "AttributeEnd\n";
  text += object("\"diffuse\" \"rgb reflectance\" [0.7 0.7 0.7]", "",
                 quad({-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}) +
                     quad({-1, 2, -1}, {1, 2, -1}, {1, 2, 1}, {-1, 2, 1}) +
                     quad({-1, 0, 1}, {1, 0, 1}, {1, 2, 1}, {-1, 2, 1}));
  text += object("\"diffuse\" \"rgb reflectance\" [0.63 0.065 0.05]", "",
                 quad({-1, 0, -1}, {-1, 0, 1}, {-1, 2, 1}, {-1, 2, -1}));
  text += object("\"diffuse\" \"rgb reflectance\" [0.14 0.45 0.091]", "",
                 quad({1, 0, -1}, {1, 0, 1}, {1, 2, 1}, {1, 2, -1}));
  return text + contents;
}

Scene load(const TempFolder& folder, const std::string& text) { return loadScene(folder.write("room.pbrt", text)); }

constexpr const char* kFog =
    "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.1 0.2 0.4] \"rgb sigma_s\" "
    "[2.5 1.5 0.8] \"float g\" 0.6\n";

// The fog sphere, clear of the fog room's smoke box, in `outside` (a medium's name, or "" for none).
std::string fogSphere(const std::string& outside) {
  return object("\"interface\"", "\"fog\" \"" + outside + "\"", sphere({-0.45f, 0.55f, 0.2f}, 0.45f));
}

}  // namespace

Scene makeFogRoom(const TempFolder& folder) {
  const std::string smoke =
      "MakeNamedMedium \"smoke\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.6 0.4 0.2] \"rgb sigma_s\" "
      "[1 2 3] \"float g\" -0.4\n";
  // The smoke box reaches below the floor, so that no face of it lies in the floor's plane.
  return load(folder,
              room(std::string(kFog) + smoke + fogSphere("") +
                   object("\"interface\"", "\"smoke\" \"\"", box({0.05f, -0.1f, -0.3f}, {0.75f, 1.3f, 0.5f})) +
                   object("\"diffuse\" \"rgb reflectance\" [0.8 0.8 0.8]", "", sphere({0.4f, 0.3f, 0.1f}, 0.2f))));
}

Scene makeHazyRoom(const TempFolder& folder) {
  const std::string haze =
      "MakeNamedMedium \"haze\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.05 0.05 0.05] \"rgb sigma_s\" "
      "[0.15 0.25 0.35] \"float g\" 0.3\n";
  return load(folder,
              room(std::string(kFog) + haze +
                       object("\"interface\"", "\"haze\" \"\"", box({-1.5f, -0.5f, -4.0f}, {1.5f, 2.5f, 1.5f})) +
                       fogSphere("haze"),
                   "haze"));
}

Scene makeUniformGridRoom(const TempFolder& folder) {
  constexpr int n = 8;
  std::vector<float> density, leScale;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const float x = (float(i) + 0.5f) / n * 2 - 1, y = (float(j) + 0.5f) / n * 2 - 1,
                    z = (float(k) + 0.5f) / n * 2 - 1;
        const float r = std::sqrt(x * x + y * y + z * z);
        // A blob, empty over the third of the box at low x and in a hole through its middle.
        const bool empty = i < 3 || (std::fabs(y) < 0.3f && std::fabs(z) < 0.3f);
        density.push_back(empty ? 0.0f : std::fmax(0.0f, 1.6f - r) * (1.0f + 0.5f * std::sin(5.0f * x + 3.0f * z)));
        leScale.push_back(j < n / 2 ? 1.0f + float(k % 3) : 0.0f);
      }
  const Vec3 p0{-0.9f, 0.05f, -0.7f}, p1{0.9f, 1.6f, 0.9f};
  std::ostringstream medium;
  medium << "MakeNamedMedium \"smoke\" \"string type\" \"uniformgrid\" \"integer nx\" " << n << " \"integer ny\" " << n
         << " \"integer nz\" " << n << " \"float density\" " << numbers(density) << " \"float Lescale\" "
         << numbers(leScale) << " \"point3 p0\" [" << p0.x << ' ' << p0.y << ' ' << p0.z << "] \"point3 p1\" [" << p1.x
         << ' ' << p1.y << ' ' << p1.z
         << "] \"rgb sigma_a\" [0.5 0.6 0.7] \"rgb sigma_s\" [4 3 2] \"rgb Le\" [2 1 0.4] \"float g\" 0.2\n";
  return load(folder, room(medium.str() + object("\"interface\"", "\"smoke\" \"\"", box(p0, p1))));
}

Scene makeRgbGridAndCloudRoom(const TempFolder& folder) {
  constexpr int n = 4;
  std::vector<float> sigmaA, sigmaS;
  for (int s = 0; s < n * n * n; ++s) {
    // Every fifth sample is empty; the others absorb and scatter in proportions of their own per channel.
    const float on = s % 5 == 0 ? 0.0f : 1.0f;
    sigmaA.insert(sigmaA.end(), {on * 0.2f * float(s % 3), on * 0.3f, on * 0.1f * float(s % 4)});
    sigmaS.insert(sigmaS.end(), {on * (1.0f + float(s % 7)), on * 2.0f, on * (4.0f - float(s % 4))});
  }
  const std::string rgb =
      "MakeNamedMedium \"tint\" \"string type\" \"rgbgrid\" \"integer nx\" 4 \"integer ny\" 4 "
      "\"integer nz\" 4 \"point3 p0\" [-0.95 0.05 -0.5] \"point3 p1\" [-0.05 1.2 0.6] "
      "\"rgb sigma_a\" " +
      numbers(sigmaA) + " \"rgb sigma_s\" " + numbers(sigmaS) + " \"float scale\" 1.5\n";
  const std::string cloud =
      "MakeNamedMedium \"cloud\" \"string type\" \"cloud\" \"point3 p0\" [0.05 0.3 -0.5] \"point3 p1\" "
      "[0.95 1.5 0.6] \"rgb sigma_a\" [0.2 0.3 0.4] \"rgb sigma_s\" [6 5 4] \"float density\" 2 "
      "\"float wispiness\" 0.8 \"float frequency\" 4 \"float g\" 0.5\n";
  return load(folder, room(rgb + cloud +
                           object("\"interface\"", "\"tint\" \"\"", box({-0.95f, 0.05f, -0.5f}, {-0.05f, 1.2f, 0.6f})) +
                           object("\"interface\"", "\"cloud\" \"\"", box({0.05f, 0.3f, -0.5f}, {0.95f, 1.5f, 0.6f}))));
}

Scene makeNanoVdbRoom(const TempFolder& folder) {
  TestNanoVdbGrid density;
  density.size = {12, 10, 12};
  density.voxelSize = {0.12, 0.12, 0.12};
  density.translation = {-0.66, 0.21, -0.54};  // the voxels' cells fill [-0.72, 0.72] x [0.15, 1.35] x [-0.6, 0.84]
  TestNanoVdbGrid temperature = density;
  temperature.name = "temperature";
  for (uint32_t k = 0; k < 12; ++k)
    for (uint32_t j = 0; j < 10; ++j)
      for (uint32_t i = 0; i < 12; ++i) {
        const float x = (float(i) - 5.5f) / 6, y = (float(j) - 4.5f) / 5, z = (float(k) - 5.5f) / 6;
        const float r = std::sqrt(x * x + y * y + z * z);
        density.values.push_back(r > 1.0f || (i + j + k) % 7 == 0 ? 0.0f : 1.2f - r);
        // Hot at the bottom (up to 2,500 K), colder than the emission's cutoff at the top.
        temperature.values.push_back(j < 6 ? 1000.0f + 250.0f * float(6 - j) + 50.0f * float(i % 3) : 80.0f);
      }
  folder.write("fire.nvdb", nanoVdbFile({density, temperature}));
  const std::string medium =
      "MakeNamedMedium \"fire\" \"string type\" \"nanovdb\" \"string filename\" \"fire.nvdb\" \"rgb sigma_a\" "
      "[0.8 1 1.2] \"rgb sigma_s\" [3 2.5 2] \"float scale\" 1.5 \"float g\" 0.3 \"float Lescale\" 1.5\n";
  return load(folder, room(medium + object("\"interface\"", "\"fire\" \"\"",
                                           box({-0.75f, 0.12f, -0.63f}, {0.75f, 1.38f, 0.87f}))));
}

Scene makeSubsurfaceRoom(const TempFolder& folder) {
  return load(folder, room(object("\"subsurface\" \"rgb reflectance\" [0.9 0.6 0.4] \"rgb mfp\" [0.3 0.15 0.08] "
                                  "\"float eta\" 1.33",
                                  "", sphere({-0.45f, 0.4f, 0.1f}, 0.4f)) +
                           // Floating just above the floor, so that no face of it lies in the floor's plane.
                           object("\"subsurface\" \"rgb sigma_a\" [0.2 0.5 1] \"rgb sigma_s\" [8 6 4] \"float g\" 0.3 "
                                  "\"float roughness\" 0.2",
                                  "", box({0.1f, 0.02f, -0.2f}, {0.8f, 0.72f, 0.5f})) +
                           object("\"diffusetransmission\" \"rgb reflectance\" [0.3 0.4 0.5] \"rgb transmittance\" "
                                  "[0.6 0.5 0.3]",
                                  "", sphere({0.45f, 1.25f, 0.3f}, 0.3f))));
}

Scene withDenserHomogeneousMedia(Scene scene, float factor) {
  for (Medium& m : scene.media) {
    // A grid medium's majorants bound its coefficients as loaded; scaled, they would no longer.
    if (m.grid != kHomogeneous) throw std::invalid_argument("withDenserHomogeneousMedia: the scene has a grid medium");
    m.sigmaA = m.sigmaA * factor;
    m.sigmaS = m.sigmaS * factor;
  }
  return scene;
}

}  // namespace candela::test
