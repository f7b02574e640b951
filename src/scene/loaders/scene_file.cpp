#include "scene/loaders/scene_file.h"

#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <tuple>

#include "io/file_bytes.h"
#include "io/images/image_decoding.h"
#include "io/path_confinement.h"
#include "kernel/bsdf/material_type_names.h"
#include "scene/scene_repair.h"
#include "scene/transform.h"

namespace candela {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A JSON value with the path that leads to it, so that every complaint can say where it is.
class Node {
 public:
  Node(const json& value, std::string path, const std::string& file)
      : value_(value), path_(std::move(path)), file_(file) {}

  [[noreturn]] void fail(const std::string& what) const { failLoad(file_, path_.empty() ? what : path_ + ": " + what); }

  bool has(const char* key) const { return value_.is_object() && value_.contains(key); }
  Node operator[](const char* key) const {
    if (!has(key)) fail(std::string("'") + key + "' is missing");
    return {value_.at(key), path_.empty() ? key : path_ + "." + key, file_};
  }
  Node at(size_t i) const { return {value_.at(i), path_ + "[" + std::to_string(i) + "]", file_}; }
  bool isObject() const { return value_.is_object(); }
  size_t size() const {
    if (!value_.is_array()) fail("expected an array");
    return value_.size();
  }
  void expectObject(std::initializer_list<const char*> known, LoadWarnings& warnings) const {
    if (!value_.is_object()) fail("expected an object");
    for (const auto& item : value_.items()) {
      const std::string& key = item.key();
      if (std::find_if(known.begin(), known.end(), [&](const char* k) { return key == k; }) == known.end())
        warnings.add(file_, path_ + (path_.empty() ? "" : ".") + key + ": unknown key, ignored");
    }
  }

  float number() const {
    if (!value_.is_number()) fail("expected a number");
    double d = value_.get<double>();
    if (!std::isfinite(d) || std::fabs(d) > 3.0e38) fail("number out of range");
    return float(d);
  }
  float number(float min, float max) const {
    float x = number();
    if (x < min || x > max) fail("expected a number from " + std::to_string(min) + " to " + std::to_string(max));
    return x;
  }
  uint32_t count(uint32_t min, uint32_t max) const {
    if (!value_.is_number_integer() || value_.get<int64_t>() < min || value_.get<int64_t>() > max)
      fail("expected a whole number from " + std::to_string(min) + " to " + std::to_string(max));
    return uint32_t(value_.get<int64_t>());
  }
  bool boolean() const {
    if (!value_.is_boolean()) fail("expected true or false");
    return value_.get<bool>();
  }
  std::string string() const {
    if (!value_.is_string()) fail("expected a string");
    return value_.get<std::string>();
  }
  Vec3 vec3() const {
    if (!value_.is_array() || value_.size() != 3) fail("expected 3 numbers");
    return {at(0).number(), at(1).number(), at(2).number()};
  }
  bool isNumber() const { return value_.is_number(); }

 private:
  const json& value_;
  std::string path_;
  const std::string& file_;
};

glm::mat4 transformOf(const Node& t, LoadWarnings& warnings) {
  t.expectObject({"matrix", "translate", "rotate_degrees", "scale"}, warnings);
  if (t.has("matrix")) {
    Node m = t["matrix"];
    if (m.size() != 16) m.fail("expected 16 numbers (a row-major 4x4 matrix)");
    glm::mat4 out;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) out[c][r] = m.at(size_t(4 * r + c)).number();
    return out;
  }
  glm::mat4 out(1.0f);
  if (t.has("translate")) {
    Vec3 v = t["translate"].vec3();
    out = glm::translate(out, {v.x, v.y, v.z});
  }
  if (t.has("rotate_degrees")) {  // about X, then Y, then Z
    Vec3 r = t["rotate_degrees"].vec3() * (kPi / 180.0f);
    out = glm::rotate(out, r.z, {0, 0, 1});
    out = glm::rotate(out, r.y, {0, 1, 0});
    out = glm::rotate(out, r.x, {1, 0, 0});
  }
  if (t.has("scale")) {
    Node s = t["scale"];
    Vec3 v = s.isNumber() ? Vec3{1, 1, 1} * s.number() : s.vec3();
    if (v.x == 0 || v.y == 0 || v.z == 0) s.fail("a scale of 0 collapses the model");
    out = glm::scale(out, {v.x, v.y, v.z});
  }
  return out;
}

MaterialType materialType(const Node& n) {
  std::string t = n.string();
  if (std::optional<MaterialType> type = materialTypeNamed(t)) return *type;
  n.fail("unknown material type '" + t + "' (" + materialTypeNameList() + ")");
}

void overrideMaterial(Material& m, const Node& o, LoadWarnings& warnings) {
  o.expectObject({"type", "base_color", "emission", "roughness", "metallic", "ior", "specular_transmission",
                  "transmittance", "opacity", "double_sided"},
                 warnings);
  if (o.has("type")) m.type = materialType(o["type"]);
  if (o.has("base_color")) m.baseColor = o["base_color"].vec3();
  if (o.has("emission")) m.emission = o["emission"].vec3();
  if (o.has("roughness")) m.roughness = o["roughness"].number(0, 1);
  if (o.has("metallic")) m.metallic = o["metallic"].number(0, 1);
  if (o.has("ior")) m.ior = o["ior"].number(1, 10);
  if (o.has("specular_transmission")) m.specTrans = o["specular_transmission"].number(0, 1);
  if (o.has("transmittance")) m.transmittance = o["transmittance"].vec3();
  if (o.has("opacity")) m.opacity = o["opacity"].number(0, 1);
  if (o.has("double_sided")) m.doubleSided = o["double_sided"].boolean() ? 1u : 0u;
  if (m.baseColor.x < 0 || m.baseColor.y < 0 || m.baseColor.z < 0 || m.emission.x < 0 || m.emission.y < 0 ||
      m.emission.z < 0 || m.transmittance.x < 0 || m.transmittance.y < 0 || m.transmittance.z < 0)
    o.fail("colours must not be negative");
}

// The file a scene file names. A relative path follows the rule of a model's references (path_confinement.h),
// since a scene file may come in one bundle with its models from an untrusted place. An absolute path is its
// author's deliberate choice (the viewer saves views naming their models so) and is taken as it is.
std::string resolve(const Node& name, const PathRule& rule) {
  const bool absolute = fs::path(name.string()).is_absolute();
  const PathRule asWritten{rule.folder, OutsidePaths::Allowed};
  ResolvedPath path = resolveModelPath(rule.folder, name.string(), absolute ? asWritten : rule);
  if (!path.allowed()) name.fail("'" + name.string() + "' " + path.refusal);
  return path.path;
}

// Where byte `offset` of `text` is: "12:5" (line and column, from 1).
std::string placeOfOffset(const std::string& text, size_t offset) {
  offset = std::min(offset, text.size());
  size_t lineStart = text.rfind('\n', offset == 0 ? std::string::npos : offset - 1);
  lineStart = lineStart == std::string::npos ? 0 : lineStart + 1;
  size_t line = size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(lineStart), '\n')) + 1;
  return std::to_string(line) + ":" + std::to_string(offset - lineStart + 1);
}

// nlohmann's DOM builder that keeps where parsing failed instead of throwing: not every error says (a number
// too large for a double, out_of_range.406, carries no position).
class PlacedDomParser : public nlohmann::detail::json_sax_dom_parser<json> {
 public:
  explicit PlacedDomParser(json& result) : json_sax_dom_parser(result, /*allow_exceptions=*/false) {}

  bool parse_error(std::size_t position, const std::string& token, const json::exception& e) {
    // `position` counts the characters read: for a number out of range, those of the number too (the start
    // of which is the place to show); for a syntax error, up to the offending character.
    const size_t back = dynamic_cast<const json::out_of_range*>(&e) ? token.size() : 1;
    errorOffset = position >= back ? position - back : 0;
    error = e.what();
    size_t tag = error.find("] ");  // "[json.exception.parse_error.101] parse error at line 1, column 2: ..."
    if (tag != std::string::npos) error = error.substr(tag + 2);
    size_t located = error.find(": ");
    if (error.rfind("parse error at line", 0) == 0 && located != std::string::npos) error = error.substr(located + 2);
    return false;
  }

  std::string error;
  size_t errorOffset = 0;
};

json parseJson(const std::string& path, const std::string& text) {
  json doc;
  PlacedDomParser parser(doc);
  if (!json::sax_parse(text, &parser))
    failLoad(path + ":" + placeOfOffset(text, parser.errorOffset), "invalid JSON: " + parser.error);
  return doc;
}

}  // namespace

void appendScene(Scene& scene, Scene&& part, const Affine3x4& transform, const std::string& cameraPrefix) {
  uint32_t meshBase = uint32_t(scene.meshes.size()), materialBase = uint32_t(scene.materials.size());
  for (Mesh& m : part.meshes) {
    for (uint32_t& id : m.triangleMaterials) id += materialBase;
    scene.meshes.push_back(std::move(m));
  }
  using TextureKey = std::tuple<std::string, bool, TextureWrap, TextureWrap>;
  auto keyOf = [](const Texture& t) { return TextureKey{t.name, t.srgb, t.wrapU, t.wrapV}; };
  std::map<TextureKey, int32_t> known;
  for (size_t t = 0; t < scene.textures.size(); ++t) known.try_emplace(keyOf(scene.textures[t]), int32_t(t));
  std::vector<int32_t> textureId(part.textures.size());
  for (size_t t = 0; t < part.textures.size(); ++t) {
    auto [it, added] = known.try_emplace(keyOf(part.textures[t]), int32_t(scene.textures.size()));
    if (added) scene.textures.push_back(std::move(part.textures[t]));
    textureId[t] = it->second;
  }
  part.materialNames.resize(part.materials.size());
  for (size_t i = 0; i < part.materials.size(); ++i) {
    Material m = part.materials[i];
    for (int32_t* t :
         {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.roughnessTexture, &m.metallicTexture, &m.emissionTexture,
          &m.normalTexture, &m.opacityTexture, &m.iridescenceTexture, &m.iridescenceThicknessTexture})
      // A part loaded with SharedModelAssets has no textures of its own: its ids point into the shared table.
      if (*t != kNoTexture && !part.textures.empty()) *t = textureId[size_t(*t)];
    scene.materials.push_back(m);
    scene.materialNames.push_back(part.materialNames[i]);
  }
  scene.inputFiles.insert(scene.inputFiles.end(), part.inputFiles.begin(), part.inputFiles.end());
  appendAnimation(scene.animation, part.animation, transform,
                  {uint32_t(scene.instances.size()), uint32_t(scene.cameras.size()),
                   uint32_t(scene.punctualLights.size()), meshBase});
  for (NamedCamera c : part.cameras) {
    c.description.eye = transform.point(c.description.eye);
    c.description.target = transform.point(c.description.target);
    c.description.up = normalize(transform.vector(c.description.up));
    scene.cameras.push_back({cameraPrefix + c.name, c.description});
  }
  glm::mat4 outer = toMat4(transform);
  for (const Instance& inst : part.instances)
    scene.instances.push_back({inst.meshId + meshBase, toAffine(outer * toMat4(inst.objectToWorld))});
  for (PunctualLight light : part.punctualLights) {
    light.position = transform.point(light.position);
    light.direction = normalize(transform.vector(light.direction));
    scene.punctualLights.push_back(light);
  }
}

namespace {

// One entry of the scene file's `lights`: a point, spot or directional light (kernel/scene_view.h).
PunctualLight punctualLightOf(const Node& l, LoadWarnings& warnings) {
  l.expectObject({"type", "position", "direction", "target", "color", "intensity", "inner_angle_degrees",
                  "outer_angle_degrees"},
                 warnings);
  PunctualLight light;
  const std::string type = l["type"].string();
  if (type == "point")
    light.type = PunctualLightType::Point;
  else if (type == "spot")
    light.type = PunctualLightType::Spot;
  else if (type == "directional")
    light.type = PunctualLightType::Directional;
  else
    l["type"].fail("unknown light type '" + type + "' (use point, spot or directional)");
  Vec3 color{1, 1, 1};
  if (l.has("color")) color = l["color"].vec3();
  if (color.x < 0 || color.y < 0 || color.z < 0) l["color"].fail("must not be negative");
  float intensity = l.has("intensity") ? l["intensity"].number(0.0f, 1e30f) : 1.0f;
  light.intensity = color * intensity;
  if (light.type != PunctualLightType::Directional) light.position = l["position"].vec3();
  if (light.type != PunctualLightType::Point) {
    if (l.has("direction") == l.has("target")) l.fail("give either 'direction' or 'target'");
    Vec3 direction = l.has("direction") ? l["direction"].vec3() : l["target"].vec3() - light.position;
    if (!(length(direction) > 0.0f)) l.fail("the light's direction has no length");
    light.direction = normalize(direction);
  }
  if (light.type == PunctualLightType::Spot) {
    float outer = l.has("outer_angle_degrees") ? l["outer_angle_degrees"].number(0.0f, 180.0f) : 45.0f;
    float inner = l.has("inner_angle_degrees") ? l["inner_angle_degrees"].number(0.0f, outer) : 0.0f;
    light.cosOuter = std::cos(outer * kPi / 180.0f);
    light.cosInner = std::cos(inner * kPi / 180.0f);
  }
  return light;
}

}  // namespace

Scene loadSceneFile(const std::string& path, const ModelLoader& loadModel, LoadWarnings& warnings,
                    OutsidePaths outside) {
  std::vector<uint8_t> bytes = readFileBytes(path);
  const json doc = parseJson(path, std::string(bytes.begin(), bytes.end()));
  const PathRule files = PathRule::forFile(path, outside);
  Node root(doc, "", path);
  root.expectObject({"models", "camera", "environment", "lights", "render"}, warnings);

  Scene scene;
  scene.name = fs::path(path).stem().string();
  std::optional<CameraDescription> modelCamera;
  int32_t modelCameraIndex = -1;  // modelCamera's entry in scene.cameras, or -1
  SharedModelAssets shared;
  // A model file loaded before with the same material overrides: its instances, relative to its transform, and
  // its animation.
  struct LoadedModel {
    std::vector<Instance> instances;
    SceneAnimation animation;
  };
  std::map<std::pair<std::string, std::string>, LoadedModel> loaded;
  Node models = root["models"];
  if (models.size() == 0) models.fail("a scene needs at least one model");
  for (size_t i = 0; i < models.size(); ++i) {
    Node model = models.at(i);
    model.expectObject({"file", "transform", "materials"}, warnings);
    std::string file = resolve(model["file"], files);
    std::string ext = fs::path(file).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".obj" && ext != ".gltf" && ext != ".glb")
      model["file"].fail("models must be .obj, .gltf or .glb files");
    glm::mat4 transform = model.has("transform") ? transformOf(model["transform"], warnings) : glm::mat4(1.0f);
    std::pair<std::string, std::string> key{file, model.has("materials") ? doc["models"][i]["materials"].dump() : ""};
    // A model with skinned or morphed meshes is loaded again: each placement deforms meshes of its own.
    if (auto it = loaded.find(key); it != loaded.end() && it->second.animation.deformations.empty()) {
      // Only the instances are placed again (a model's cameras and lights come with its first placement).
      appendAnimation(scene.animation, it->second.animation, toAffine(transform),
                      {uint32_t(scene.instances.size()), 0, 0});
      for (const Instance& inst : it->second.instances)
        scene.instances.push_back({inst.meshId, toAffine(transform * toMat4(inst.objectToWorld))});
      if (scene.instances.size() > kMaxInstances)
        model.fail("the models hold more than " + std::to_string(kMaxInstances) + " mesh instances in all");
      continue;
    }
    Scene part = loadModel(file, warnings, shared);
    LoadedModel& first = loaded[key];
    for (const Instance& inst : part.instances)
      first.instances.push_back({inst.meshId + uint32_t(scene.meshes.size()), inst.objectToWorld});
    first.animation = part.animation;
    first.animation.cameras.clear();
    first.animation.lights.clear();
    if (model.has("materials")) {
      if (!model["materials"].isObject()) model["materials"].fail("expected an object of material names");
      const json& overrides = doc["models"][i]["materials"];
      for (const auto& [name, value] : overrides.items()) {
        Node o(value, "models[" + std::to_string(i) + "].materials." + name, path);
        bool found = false;
        for (size_t m = 0; m < part.materials.size(); ++m)
          if (m < part.materialNames.size() && part.materialNames[m] == name) {
            overrideMaterial(part.materials[m], o, warnings);
            found = true;
          }
        if (!found)
          warnings.add(path,
                       "models[" + std::to_string(i) + "].materials." + name + ": no material of that name in " + file);
      }
    }
    if (!part.cameraMissing && !modelCamera) {
      modelCamera = part.camera;
      modelCamera->eye = toAffine(transform).point(part.camera.eye);
      modelCamera->target = toAffine(transform).point(part.camera.target);
      modelCamera->up = normalize(toAffine(transform).vector(part.camera.up));
      if (part.cameraIndex >= 0) modelCameraIndex = int32_t(scene.cameras.size()) + part.cameraIndex;
    }
    appendScene(scene, std::move(part), toAffine(transform), "models[" + std::to_string(i) + "]: ");
    if (scene.instances.size() > kMaxInstances)
      model.fail("the models hold more than " + std::to_string(kMaxInstances) + " mesh instances in all");
  }
  shared.textures.finish(scene, 0, warnings);

  scene.cameraMissing = true;
  if (modelCamera) {
    scene.camera = *modelCamera;
    scene.cameraIndex = modelCameraIndex;
    scene.cameraMissing = false;
  }
  if (root.has("camera")) {
    Node c = root["camera"];
    c.expectObject({"position", "target", "up", "fov_degrees", "aperture_radius", "focus_distance"}, warnings);
    CameraDescription& cam = scene.camera;
    cam = CameraDescription{};
    cam.eye = c["position"].vec3();
    cam.target = c["target"].vec3();
    if (c.has("up")) cam.up = c["up"].vec3();
    if (c.has("fov_degrees")) cam.verticalFovDegrees = c["fov_degrees"].number(0.01f, 179.0f);
    if (c.has("aperture_radius")) cam.apertureRadius = c["aperture_radius"].number(0.0f, 1e30f);
    if (c.has("focus_distance")) cam.focusDistance = c["focus_distance"].number(0.0f, 1e30f);
    Vec3 forward = cam.target - cam.eye;
    if (length(forward) == 0.0f) c.fail("position and target coincide");
    if (length(cross(forward, cam.up)) == 0.0f) c["up"].fail("up is parallel to the viewing direction");
    scene.cameraMissing = false;
    scene.cameras.insert(scene.cameras.begin(), {"camera", cam});
    scene.cameraIndex = 0;
    for (AnimatedCamera& a : scene.animation.cameras) ++a.camera;
  }
  if (root.has("environment")) {
    Node e = root["environment"];
    e.expectObject({"map", "radiance", "intensity", "rotation_degrees", "visible"}, warnings);
    Environment env;
    if (e.has("map")) {
      std::string map = resolve(e["map"], files);
      env.map = loadEnvironmentImage(map);
      scene.inputFiles.push_back(map);
    }
    if (e.has("radiance")) env.radiance = e["radiance"].vec3();
    if (env.radiance.x < 0 || env.radiance.y < 0 || env.radiance.z < 0) e["radiance"].fail("must not be negative");
    if (e.has("intensity")) env.intensity = e["intensity"].number(0.0f, 1e30f);
    // Reduced exactly to one turn, so that any finite angle keeps its meaning (and the viewer can turn it further).
    if (e.has("rotation_degrees")) env.rotationDegrees = std::fmod(e["rotation_degrees"].number(), 360.0f);
    if (e.has("visible")) env.visibleToCamera = e["visible"].boolean();
    scene.environment = std::move(env);
  }
  if (root.has("lights")) {
    Node lights = root["lights"];
    for (size_t i = 0; i < lights.size(); ++i) scene.punctualLights.push_back(punctualLightOf(lights.at(i), warnings));
  }
  if (root.has("render")) {
    Node r = root["render"];
    r.expectObject({"width", "height", "spp", "max_depth"}, warnings);
    if (r.has("width")) scene.renderHints.width = r["width"].count(1, 16384);
    if (r.has("height")) scene.renderHints.height = r["height"].count(1, 16384);
    if (r.has("spp")) scene.renderHints.samplesPerPixel = r["spp"].count(1, 1u << 24);
    if (r.has("max_depth")) scene.renderHints.maxDepth = r["max_depth"].count(1, 1024);
  }
  return scene;
}

}  // namespace candela
