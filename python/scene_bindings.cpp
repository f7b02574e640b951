#include "scene_bindings.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "candela/candela.h"

namespace py = pybind11;

namespace candela::python {

namespace {

template <class T>
using Array = py::array_t<T, py::array::c_style | py::array::forcecast>;

std::string shapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) text += (i ? ", " : "") + std::to_string(array.shape(i));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

// The number of rows of `array`, which must be rows x columns, or flat with a multiple of `columns` entries;
// Error naming `what` otherwise.
size_t rowsOf(const py::array& array, py::ssize_t columns, const char* what) {
  if (array.ndim() == 2 && array.shape(1) == columns) return size_t(array.shape(0));
  if (array.ndim() == 1 && array.shape(0) % columns == 0) return size_t(array.shape(0) / columns);
  throw api::Error(std::string(what) + ": an array of shape (n, " + std::to_string(columns) + "), not " +
                   shapeText(array));
}

// A 3x4 or 4x4 object-to-world matrix (the last row of a 4x4 must be 0 0 0 1).
std::array<float, 12> transformOf(const Array<float>& matrix) {
  const bool square = matrix.ndim() == 2 && matrix.shape(0) == 4 && matrix.shape(1) == 4;
  if (!(matrix.ndim() == 2 && matrix.shape(1) == 4 && (matrix.shape(0) == 3 || square)))
    throw api::Error("transform: a 3x4 or 4x4 matrix, not " + shapeText(matrix));
  const float* m = matrix.data();
  if (square && !(m[12] == 0.0f && m[13] == 0.0f && m[14] == 0.0f && m[15] == 1.0f))
    throw api::Error("transform: the last row of a 4x4 matrix must be 0 0 0 1 (no projection)");
  std::array<float, 12> transform;
  std::copy(m, m + 12, transform.begin());
  return transform;
}

uint32_t addMesh(api::SceneBuilder& builder, const Array<float>& positions, const Array<uint32_t>& indices,
                 uint32_t material, const std::optional<Array<float>>& normals, const std::optional<Array<float>>& uvs,
                 const std::optional<Array<uint32_t>>& triangleMaterials,
                 const std::optional<Array<float>>& transform) {
  api::MeshArrays mesh;
  mesh.positions = positions.data();
  mesh.vertexCount = rowsOf(positions, 3, "positions");
  mesh.indices = indices.data();
  mesh.triangleCount = rowsOf(indices, 3, "indices");
  mesh.material = material;
  if (normals) {
    if (rowsOf(*normals, 3, "normals") != mesh.vertexCount) throw api::Error("normals: one per vertex");
    mesh.normals = normals->data();
  }
  if (uvs) {
    if (rowsOf(*uvs, 2, "uvs") != mesh.vertexCount) throw api::Error("uvs: one per vertex");
    mesh.uvs = uvs->data();
  }
  if (triangleMaterials) {
    if (triangleMaterials->ndim() != 1 || size_t(triangleMaterials->shape(0)) != mesh.triangleCount)
      throw api::Error("triangle_materials: one per triangle, not " + shapeText(*triangleMaterials));
    mesh.triangleMaterials = triangleMaterials->data();
  }
  if (transform) mesh.transform = transformOf(*transform);
  return builder.addMesh(mesh);
}

}  // namespace

void bindScenes(py::module_& m) {
  py::class_<api::Scene>(m, "LoadedScene",
                         "A scene ready to render: from candela.load(), or Scene.build(). Renders share it.")
      .def_property_readonly("name", &api::Scene::name)
      .def_property_readonly("triangle_count", &api::Scene::triangleCount)
      .def("__repr__", [](const api::Scene& s) {
        return "<candela.LoadedScene '" + s.name() + "', " + std::to_string(s.triangleCount()) + " triangles>";
      });

  using Vec3 = api::Vec3;
  py::class_<api::SceneBuilder>(m, "Scene", "A scene built from NumPy arrays: materials, meshes, lights, a camera.")
      .def(py::init<const std::string&>(), py::arg("name") = "arrays")
      .def(
          "add_material",
          [](api::SceneBuilder& b, const std::string& type, const Vec3& baseColor, const Vec3& emission,
             float roughness, float metallic, float ior) {
            return b.addMaterial({type, baseColor, emission, roughness, metallic, ior});
          },
          py::kw_only(), py::arg("type") = "pbr", py::arg("base_color") = Vec3{0.8f, 0.8f, 0.8f},
          py::arg("emission") = Vec3{0.0f, 0.0f, 0.0f}, py::arg("roughness") = 0.5f, py::arg("metallic") = 0.0f,
          py::arg("ior") = 1.5f,
          "Adds a material (type: diffuse, blinn-phong, pbr, disney, mirror or glass; colours linear RGB; emission "
          "in W/(m^2 sr) makes its triangles lights) and returns its index.")
      .def("add_mesh", &addMesh, py::arg("positions"), py::arg("indices"), py::kw_only(), py::arg("material") = 0,
           py::arg("normals") = py::none(), py::arg("uvs") = py::none(), py::arg("triangle_materials") = py::none(),
           py::arg("transform") = py::none(),
           "Adds a triangle mesh: positions (n, 3), indices (t, 3); optional normals (n, 3), uvs (n, 2), one "
           "material index per triangle, and a 3x4 or 4x4 object-to-world transform. Returns its index.")
      .def("add_point_light", &api::SceneBuilder::addPointLight, py::arg("position"), py::arg("intensity"),
           "A point light; intensity in W/sr per channel.")
      .def("add_spot_light", &api::SceneBuilder::addSpotLight, py::arg("position"), py::arg("direction"),
           py::arg("intensity"), py::arg("inner_degrees"), py::arg("outer_degrees"))
      .def("add_directional_light", &api::SceneBuilder::addDirectionalLight, py::arg("direction"),
           py::arg("irradiance"), "Light travelling along `direction` from infinitely far away.")
      .def("set_environment", &api::SceneBuilder::setEnvironment, py::arg("radiance"), "A constant sky.")
      .def("set_environment_map", &api::SceneBuilder::setEnvironmentMap, py::arg("path"), py::arg("intensity") = 1.0f,
           py::arg("rotation_degrees") = 0.0f, "An equirectangular .hdr or .exr sky.")
      .def(
          "set_camera",
          [](api::SceneBuilder& b, const Vec3& eye, const Vec3& target, const Vec3& up, float fov) {
            b.setCamera({eye, target, up, fov});
          },
          py::arg("eye"), py::arg("target"), py::kw_only(), py::arg("up") = Vec3{0.0f, 1.0f, 0.0f},
          py::arg("fov") = 40.0f, "Without one, the scene's bounds are framed. fov: vertical, in degrees.")
      .def("build", &api::SceneBuilder::build,
           "The scene as a LoadedScene, repaired as a loaded file is; the Scene can go on growing.");
}

}  // namespace candela::python
