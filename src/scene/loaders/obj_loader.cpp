#include "scene/loaders/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "scene/loaders/mtl_materials.h"
#include "scene/loaders/normal_generation.h"
#include "scene/loaders/obj_line_locator.h"
#include "scene/loaders/obj_text_buffer.h"
#include "scene/loaders/texture_table.h"

namespace candela {

namespace {

namespace fs = std::filesystem;

// Finds the MTL libraries next to the OBJ file and remembers which file each material came from.
class MtlLibraryReader : public tinyobj::MaterialReader {
 public:
  MtlLibraryReader(fs::path directory, std::string objFile, LoadWarnings& warnings)
      : directory_(std::move(directory)), objFile_(std::move(objFile)), warnings_(warnings) {}

  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* names, std::string* /*warn*/, std::string* /*err*/) override {
    std::string file = name;
    std::replace(file.begin(), file.end(), '\\', '/');
    fs::path path = (directory_ / file).lexically_normal();
    std::ifstream in(path, std::ios::binary);
    if (!in || fs::is_directory(path)) {
      warnings_.add(objFile_, "material library '" + name + "' not found; its materials are replaced by grey");
      return false;
    }
    std::string mtlWarnings, mtlErrors;
    tinyobj::LoadMtl(names, materials, &in, &mtlWarnings, &mtlErrors);
    forwardMessages(path.string(), mtlWarnings + mtlErrors);
    sources.resize(materials->size(), path.string());
    return true;
  }

  void forwardMessages(const std::string& file, const std::string& text) {
    std::map<std::string, size_t> counts;
    std::vector<std::string> order;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
      while (!line.empty() && (line.back() == '.' || line.back() == ' ' || line.back() == '\r')) line.pop_back();
      // Missing material files and out-of-range references are reported by the loader itself, with more detail.
      if (line.empty() || line.rfind("Failed to load material file", 0) == 0 ||
          line.find("indices out of bounds") != std::string::npos)
        continue;
      if (counts[line]++ == 0) order.push_back(line);
    }
    for (const std::string& l : order)
      warnings_.add(file, counts[l] > 1 ? l + " (" + std::to_string(counts[l]) + " times)" : l);
  }

  std::vector<std::string> sources;  // the .mtl file of each material

 private:
  fs::path directory_;
  std::string objFile_;
  LoadWarnings& warnings_;
};

struct ParsedObj {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
};

// Where the OBJ text comes from; reopened from the start to locate the line of a problem found after parsing.
class ObjSource {
 public:
  virtual ~ObjSource() = default;
  virtual std::unique_ptr<ObjTextBuffer> open() const = 0;
};

class FileSource : public ObjSource {
 public:
  explicit FileSource(std::string path) : path_(std::move(path)) {}
  std::unique_ptr<ObjTextBuffer> open() const override {
    auto buffer = ObjTextBuffer::openFile(path_);
    if (!buffer) failLoad(path_, "cannot open");
    return buffer;
  }

 private:
  std::string path_;
};

class TextSource : public ObjSource {
 public:
  explicit TextSource(std::string_view text) : text_(text) {}
  std::unique_ptr<ObjTextBuffer> open() const override { return std::make_unique<ObjTextBuffer>(text_); }

 private:
  std::string_view text_;
};

[[noreturn]] void failAtLine(const std::string& name, const ObjSource& source, const char* keyword, size_t ordinal,
                             const std::string& what) {
  auto buffer = source.open();
  std::istream in(buffer.get());
  if (auto line = lineOfStatement(in, keyword, ordinal)) failLoad(name, *line, what);
  failLoad(name, what);
}

std::optional<ObjProblem> locateBadReference(const ObjSource& source) {
  auto buffer = source.open();
  std::istream in(buffer.get());
  return findBadReference(in);
}

[[noreturn]] void failBadReference(const std::string& name, const ObjSource& source, const std::string& fallback) {
  if (auto problem = locateBadReference(source)) failLoad(name, problem->line, problem->what);
  failLoad(name, fallback);
}

void checkFinite(const std::string& name, const ObjSource& text, const std::vector<tinyobj::real_t>& values,
                 size_t stride, const char* keyword, const char* what) {
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i])) failAtLine(name, text, keyword, i / stride, std::string("non-finite ") + what);
}

// A face that refers to a missing vertex is an error. One that refers to a missing normal or texture coordinate
// (some exporters write "# 6 normals" and then none) loses that reference, with a warning.
void checkReferences(const std::string& name, const ObjSource& text, ParsedObj& obj, LoadWarnings& warnings) {
  const long long nv = (long long)obj.attrib.vertices.size() / 3, nn = (long long)obj.attrib.normals.size() / 3,
                  nt = (long long)obj.attrib.texcoords.size() / 2;
  size_t dropped = 0;
  for (tinyobj::shape_t& shape : obj.shapes) {
    for (tinyobj::index_t& i : shape.mesh.indices) {
      if (i.vertex_index < 0 || i.vertex_index >= nv)
        failBadReference(name, text, "a face refers to a missing vertex");
      if (i.normal_index < -1 || i.normal_index >= nn) {
        i.normal_index = -1;
        ++dropped;
      }
      if (i.texcoord_index < -1 || i.texcoord_index >= nt) {
        i.texcoord_index = -1;
        ++dropped;
      }
    }
    for (unsigned char n : shape.mesh.num_face_vertices)
      if (n != 3) failLoad(name, "a polygon could not be triangulated");
  }
  if (dropped > 0) {
    auto problem = locateBadReference(text);
    std::string where = problem ? name + ":" + std::to_string(problem->line) : name;
    warnings.messages.push_back(where + ": " + (problem ? problem->what + "; " : std::string()) +
                                std::to_string(dropped) +
                                " references to missing normals or texture coordinates are ignored");
  }
}

Vec3 attribute3(const std::vector<tinyobj::real_t>& v, int i) {
  return {float(v[3 * size_t(i)]), float(v[3 * size_t(i) + 1]), float(v[3 * size_t(i) + 2])};
}

// Flattens the shapes into one mesh, sharing a vertex among corners with the same position, texture coordinate
// and normal.
Mesh buildMesh(const std::string& meshName, ParsedObj& obj, const std::vector<uint32_t>& materialOf,
               uint32_t defaultMaterial) {
  size_t triangles = 0;
  for (const auto& s : obj.shapes) triangles += s.mesh.indices.size() / 3;
  std::vector<uint32_t> cornerPositions(3 * triangles), smoothing(triangles);
  std::vector<uint8_t> needsNormals(triangles);
  std::vector<int32_t> cornerUv(3 * triangles), cornerNormal(3 * triangles);
  Mesh mesh;
  mesh.name = meshName;
  mesh.triangleMaterials.resize(triangles);
  bool anyUv = false, anyMissingNormal = false;
  size_t t = 0;
  for (tinyobj::shape_t& shape : obj.shapes) {
    const auto& idx = shape.mesh.indices;
    for (size_t f = 0; f < idx.size() / 3; ++f, ++t) {
      bool missing = false;
      for (int k = 0; k < 3; ++k) {
        const tinyobj::index_t& i = idx[3 * f + k];
        cornerPositions[3 * t + k] = uint32_t(i.vertex_index);
        cornerUv[3 * t + k] = i.texcoord_index;
        cornerNormal[3 * t + k] = i.normal_index;
        anyUv |= i.texcoord_index >= 0;
        missing |= i.normal_index < 0;
      }
      // A triangle takes normals from the file only when all three corners have one.
      if (missing)
        for (int k = 0; k < 3; ++k) cornerNormal[3 * t + k] = -1;
      needsNormals[t] = missing;
      anyMissingNormal |= missing;
      smoothing[t] = shape.mesh.smoothing_group_ids.empty() ? 0 : shape.mesh.smoothing_group_ids[f];
      int m = shape.mesh.material_ids.empty() ? -1 : shape.mesh.material_ids[f];
      mesh.triangleMaterials[t] = m >= 0 && size_t(m) < materialOf.size() ? materialOf[size_t(m)] : defaultMaterial;
    }
    shape.mesh = {};
  }

  std::vector<Vec3> positions(obj.attrib.vertices.size() / 3);
  for (size_t i = 0; i < positions.size(); ++i) positions[i] = attribute3(obj.attrib.vertices, int(i));
  obj.attrib.vertices = {};
  std::vector<Vec3> generated;
  if (anyMissingNormal) {
    NormalGenerationInput in;
    in.positions = &positions;
    in.cornerPositions = cornerPositions.data();
    in.triangleCount = triangles;
    in.smoothingGroups = smoothing.data();
    in.needsNormals = needsNormals.data();
    generated = generateCornerNormals(in);
  }

  // Vertices already made for each position, as linked lists through `next`.
  constexpr uint32_t kEnd = ~0u;
  std::vector<uint32_t> head(positions.size(), kEnd), next;
  std::vector<int32_t> vertexUv, vertexNormal;
  mesh.indices.resize(3 * triangles);
  for (size_t c = 0; c < 3 * triangles; ++c) {
    uint32_t p = cornerPositions[c];
    int32_t uv = cornerUv[c], n = cornerNormal[c];
    Vec3 normal = n >= 0 ? attribute3(obj.attrib.normals, n) : generated[c];
    uint32_t found = kEnd;
    for (uint32_t v = head[p]; v != kEnd; v = next[v])
      if (vertexUv[v] == uv && vertexNormal[v] == n &&
          (n >= 0 || (mesh.normals[v].x == normal.x && mesh.normals[v].y == normal.y && mesh.normals[v].z == normal.z))) {
        found = v;
        break;
      }
    if (found == kEnd) {
      found = uint32_t(mesh.positions.size());
      mesh.positions.push_back(positions[p]);
      mesh.normals.push_back(normal);
      if (anyUv) {
        const auto& tc = obj.attrib.texcoords;
        mesh.uvs.push_back(uv >= 0 ? Vec2{float(tc[2 * size_t(uv)]), 1.0f - float(tc[2 * size_t(uv) + 1])} : Vec2{});
      }
      vertexUv.push_back(uv);
      vertexNormal.push_back(n);
      next.push_back(head[p]);
      head[p] = found;
    }
    mesh.indices[c] = found;
  }
  // Normals that are not unit length (or zero) in the file are normalised; zero ones are left for the kernel,
  // which then shades with the geometric normal.
  for (Vec3& n : mesh.normals) {
    float len = length(n);
    if (len > 0.0f) n = n / len;
  }
  return mesh;
}

Scene loadParsed(const std::string& name, const ObjSource& text, MtlLibraryReader* mtlReader, LoadWarnings& warnings) {
  ParsedObj obj;
  std::string warn, err;
  std::unique_ptr<ObjTextBuffer> buffer = text.open();
  std::istream in(buffer.get());
  bool ok = tinyobj::LoadObj(&obj.attrib, &obj.shapes, &obj.materials, &warn, &err, &in, mtlReader,
                             /*triangulate=*/true, /*default_vcols_fallback=*/false);
  if (buffer->readFailed()) failLoad(name, "read error");
  if (auto line = buffer->firstLineWithBadNumber()) failLoad(name, *line, "a coordinate is not a number");
  if (auto line = buffer->firstSkippedLine())
    warnings.add(name + ":" + std::to_string(*line), "'vw' (skin weight) statements are ignored");
  buffer.reset();
  if (!ok) {
    std::string first = err.substr(0, err.find('\n'));
    failBadReference(name, text, first.empty() ? "cannot be parsed" : first);
  }
  if (mtlReader) {
    mtlReader->forwardMessages(name, warn);
  } else {
    MtlLibraryReader forwarder({}, name, warnings);
    forwarder.forwardMessages(name, warn);
  }
  checkFinite(name, text, obj.attrib.vertices, 3, "v", "vertex position");
  checkFinite(name, text, obj.attrib.normals, 3, "vn", "normal");
  checkFinite(name, text, obj.attrib.texcoords, 2, "vt", "texture coordinate");
  checkReferences(name, text, obj, warnings);

  size_t triangles = 0, otherElements = 0;
  for (const auto& s : obj.shapes) {
    triangles += s.mesh.indices.size() / 3;
    otherElements += s.lines.indices.size() + s.points.indices.size();
  }
  if (triangles == 0)
    failLoad(name, otherElements > 0 ? "has only line and point elements, no faces to render" : "has no faces");
  if (otherElements > 0) warnings.add(name, "line and point elements are not rendered");

  Scene scene;
  scene.name = fs::path(name).stem().string();
  TextureTable textures;
  std::vector<uint32_t> materialOf(obj.materials.size());
  for (size_t i = 0; i < obj.materials.size(); ++i) {
    const std::string& source = mtlReader && i < mtlReader->sources.size() ? mtlReader->sources[i] : name;
    materialOf[i] = uint32_t(scene.materials.size());
    scene.materialNames.push_back(obj.materials[i].name);
    scene.materials.push_back(materialFromMtl(obj.materials[i], source, fs::path(source).parent_path().string(),
                                              textures, warnings));
  }
  uint32_t defaultMaterial = uint32_t(scene.materials.size());
  scene.meshes.push_back(buildMesh(scene.name, obj, materialOf, defaultMaterial));
  const auto& ids = scene.meshes[0].triangleMaterials;
  if (std::find(ids.begin(), ids.end(), defaultMaterial) != ids.end()) {
    scene.materials.push_back(Material{});
    scene.materialNames.push_back("default");
  }
  scene.instances.push_back({0, Affine3x4{}});
  textures.finish(scene, 0, warnings);
  scene.cameraMissing = true;
  return scene;
}

}  // namespace

Scene loadObj(const std::string& path, LoadWarnings& warnings) {
  if (fs::is_directory(path)) failLoad(path, "is a directory");
  MtlLibraryReader reader(fs::path(path).parent_path(), path, warnings);
  return loadParsed(path, FileSource(path), &reader, warnings);
}

Scene loadObjText(const std::string& name, std::string_view text, LoadWarnings& warnings) {
  return loadParsed(name, TextSource(text), nullptr, warnings);
}

}  // namespace candela
