#include "scene/loaders/gltf/gltf_loader.h"

#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>
#define GLM_ENABLE_EXPERIMENTAL  // matrix_decompose is in glm/gtx
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>
#include <glm/mat4x4.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <new>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>

#include "io/file_bytes.h"
#include "io/images/image_decoding.h"
#include "io/path_confinement.h"
#include "scene/animation_player.h"
#include "scene/loaders/gltf/gltf_accessors.h"
#include "scene/loaders/gltf/gltf_animation.h"
#include "scene/loaders/gltf/gltf_buffer_charge.h"
#include "scene/loaders/gltf/gltf_buffer_list.h"
#include "scene/loaders/gltf/gltf_byte_ranges.h"
#include "scene/loaders/gltf/gltf_deformation.h"
#include "scene/loaders/gltf/gltf_draco.h"
#include "scene/loaders/gltf/gltf_extensions.h"
#include "scene/loaders/gltf/gltf_materials.h"
#include "scene/loaders/gltf/gltf_meshopt.h"
#include "scene/loaders/texture_table.h"
#include "scene/scene_repair.h"
#include "scene/transform.h"

namespace candela {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxJsonDepth = 128;   // deeper JSON is not a plausible glTF and would exhaust the stack
constexpr int kMaxNodeDepth = 1024;  // deeper node hierarchies would exhaust the stack
// Vertices of skinned and morphed meshes in all, each counted once and once more per morph target: each node
// that uses such a mesh deforms a copy of its own, and a target without accessors costs nothing in the file but
// a delta per vertex here, so a small file could otherwise ask for any amount of memory.
constexpr size_t kMaxDeformedVertices = size_t(1) << 24;

// The deepest nesting of arrays and objects in JSON text (strings skipped).
int jsonDepth(const char* p, size_t n) {
  int depth = 0, deepest = 0;
  bool inString = false;
  for (size_t i = 0; i < n; ++i) {
    char c = p[i];
    if (inString) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

bool isGlb(const uint8_t* data, size_t size) { return size >= 4 && std::memcmp(data, "glTF", 4) == 0; }

// The JSON chunk of a .glb, or nothing when the header is too short to say.
std::pair<const char*, size_t> glbJson(const uint8_t* data, size_t size) {
  if (size < 20) return {nullptr, 0};
  uint32_t length;
  std::memcpy(&length, data + 12, 4);
  return {reinterpret_cast<const char*>(data + 20), std::min<size_t>(length, size - 20)};
}

// A .glb's header and chunk lengths must agree with the bytes there are: tinygltf trusts them, and the passes
// that rewrite the JSON chunk before tinygltf reads it (gltf_glb.h) give the result the length of the bytes they
// copy, which would hide a header that claims more.
void checkGlbLengths(const std::string& name, const uint8_t* data, size_t size) {
  if (size < 20) failLoad(name, "the .glb header is cut short (" + std::to_string(size) + " bytes)");
  uint32_t total, jsonLength;
  std::memcpy(&total, data + 8, 4);
  std::memcpy(&jsonLength, data + 12, 4);
  if (total > size)
    failLoad(name,
             "the .glb header says the file has " + std::to_string(total) + " bytes, it has " + std::to_string(size));
  if (total < 20 || jsonLength > total - 20)
    failLoad(name, "the .glb's JSON chunk of " + std::to_string(jsonLength) + " bytes reaches beyond its end");
  const size_t binAt = 20 + size_t(jsonLength);
  if (binAt + 8 > total) return;
  uint32_t binLength;
  std::memcpy(&binLength, data + binAt, 4);
  if (binLength > total - binAt - 8)
    failLoad(name, "the .glb's second chunk of " + std::to_string(binLength) + " bytes reaches beyond its end");
}

std::string firstLine(const std::string& s) {
  std::string line = s.substr(0, s.find('\n'));
  while (!line.empty() && (line.back() == ' ' || line.back() == '.')) line.pop_back();
  return line;
}

// tinygltf's file callbacks, which read the external buffers of a .gltf. tinygltf decodes a buffer's URI its
// own way and looks for it in the glTF file's folder ("<baseDir>/<path>") and then in the working directory
// ("./<path>"): the second is never answered; the first is decoded again from the URI as written, and must stay
// inside the folder that `rule` allows.
struct FileAccess {
  std::string baseDir;  // empty: nothing outside the given bytes may be read
  PathRule rule;
  const GltfBufferList& buffers;       // the buffers as the glTF's JSON writes them
  std::vector<std::string> filesRead;  // buffers, for Scene::inputFiles
  std::string refusal;                 // why the last path asked about may not be read

  // The path tinygltf asks about, when it is one in the glTF file's folder and may be read.
  std::optional<std::string> allowed(const std::string& path) {
    const std::string prefix = baseDir.empty() || baseDir.back() == '/' ? baseDir : baseDir + "/";
    if (baseDir.empty() || path.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
    const std::string decoded = path.substr(prefix.size());
    if (decoded.empty()) {  // tinygltf asks for "" where a buffer has no uri
      refusal = "a buffer has no 'uri' (only the first buffer of a .glb may leave it out)";
      return std::nullopt;
    }
    std::optional<std::string> reference = buffers.pathFor(decoded);
    if (!reference) {
      refusal = "buffer '" + decoded + "' names no file (a relative path with valid %-escapes)";
      return std::nullopt;
    }
    ResolvedPath resolved = resolveModelPath(baseDir, *reference, rule);
    if (!resolved.allowed()) {
      refusal = "buffer '" + *reference + "' " + resolved.refusal;
      return std::nullopt;
    }
    return resolved.path;
  }
};

bool fileExists(const std::string& path, void* user) {
  std::optional<std::string> file = static_cast<FileAccess*>(user)->allowed(path);
  std::error_code ec;
  return file && fs::exists(*file, ec);
}
std::string expandFilePath(const std::string& path, void*) { return path; }
bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  auto* access = static_cast<FileAccess*>(user);
  std::optional<std::string> file = access->allowed(path);
  if (!file) return false;
  access->filesRead.push_back(*file);
  try {
    *out = readFileBytes(*file);
    return true;
  } catch (const LoadError& e) {
    if (err) *err += e.what();
    return false;
  }
}
bool writeWholeFile(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

// Keeps the encoded image; TextureTable decodes it later, in parallel with the other textures.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

glm::mat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    float m[16];
    for (int i = 0; i < 16; ++i) m[i] = float(node.matrix[size_t(i)]);
    return glm::make_mat4(m);
  }
  glm::mat4 t(1.0f), r(1.0f), s(1.0f);
  if (node.translation.size() == 3)
    t = glm::translate(glm::mat4(1.0f), glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4)
    r = glm::mat4_cast(
        glm::quat(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]), float(node.rotation[2])));
  if (node.scale.size() == 3) s = glm::scale(glm::mat4(1.0f), glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
  return t * r * s;
}

class GltfSceneBuilder {
 public:
  // Textures go to `sharedTextures` when given (and are left for its owner to finish), else to the builder's own.
  GltfSceneBuilder(const tinygltf::Model& model, std::string file, const PathRule& files, LoadWarnings& warnings,
                   TextureTable* sharedTextures)
      : model_(model),
        file_(std::move(file)),
        files_(files),
        baseDir_(files.folder),
        warnings_(warnings),
        accessors_(model, file_),
        textures_(sharedTextures ? *sharedTextures : ownTextures_),
        sharesTextures_(sharedTextures != nullptr) {}

  Scene build() {
    scene_.name = fs::path(file_).stem().string();
    for (size_t i = 0; i < model_.materials.size(); ++i) {
      GltfMaterial m = materialFromGltf(
          model_, int(i), file_, [this](int t, bool srgb) { return texture(t, srgb); },
          [this](int t, bool srgb) { return textureMean(t, srgb); }, warnings_);
      scene_.materials.push_back(m.material);
      scene_.materialNames.push_back(model_.materials[i].name);
      uvTransforms_.push_back(m.uvTransform);
      texCoords_.push_back(m.texCoord);
    }
    std::vector<int> roots;
    int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : (model_.scenes.empty() ? -1 : 0);
    if (sceneIndex >= 0 && size_t(sceneIndex) < model_.scenes.size()) {
      roots = model_.scenes[size_t(sceneIndex)].nodes;
    } else {
      // No scene: every node that is nobody's child is a root.
      std::vector<bool> isChild(model_.nodes.size());
      for (const auto& n : model_.nodes)
        for (int c : n.children)
          if (c >= 0 && size_t(c) < isChild.size()) isChild[size_t(c)] = true;
      for (size_t i = 0; i < model_.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    }
    animated_ = animatedGltfNodes(model_);
    posed_ = posedNodes();
    animationNodes_.assign(model_.nodes.size(), -1);
    for (int r : roots) visitTree(r, "scenes[" + std::to_string(std::max(sceneIndex, 0)) + "].nodes");
    if (scene_.instances.empty()) failLoad(file_, "has no meshes to render");
    resolveSkins();
    readAnimations();
    if (lightRangesIgnored_ > 0)
      warnings_.add(file_, std::to_string(lightRangesIgnored_) +
                               " KHR_lights_punctual lights have a range, which is ignored: their light falls off "
                               "with the square of the distance everywhere");
    if (!sharesTextures_) textures_.finish(scene_, 0, warnings_);
    scene_.cameraMissing = !cameraFound_;
    return std::move(scene_);
  }

 private:
  // A node being visited, with the next of its children to visit.
  struct NodeVisit {
    int index;
    glm::mat4 world;
    int depth;
    int32_t animationNode;
    size_t nextChild = 0;
  };

  // Visits the root and its descendants, parents before children, each node's children in order. The walk keeps
  // its own stack: a hierarchy kMaxNodeDepth deep would exhaust the thread's stack in a recursive one.
  void visitTree(int root, const std::string& from) {
    std::vector<NodeVisit> path{enter(root, glm::mat4(1.0f), 0, from, -1)};
    while (!path.empty()) {
      NodeVisit& visit = path.back();
      const std::vector<int>& children = model_.nodes[size_t(visit.index)].children;
      if (visit.nextChild == children.size()) {
        nodeStates_[size_t(visit.index)] = NodeState::Done;
        path.pop_back();
        continue;
      }
      const int child = children[visit.nextChild++];
      NodeVisit next = enter(child, visit.world, visit.depth + 1, "nodes[" + std::to_string(visit.index) + "].children",
                             visit.animationNode);
      path.push_back(next);
    }
  }

  // Takes the node's mesh, camera and light into the scene. `parentNode`: the parent's entry in
  // scene_.animation.nodes, or -1 where the parent does not move.
  NodeVisit enter(int index, const glm::mat4& parent, int depth, const std::string& from, int32_t parentNode) {
    if (index < 0 || size_t(index) >= model_.nodes.size())
      failLoad(file_, from + ": node " + std::to_string(index) + " does not exist");
    std::string where = "nodes[" + std::to_string(index) + "]";
    if (depth > kMaxNodeDepth)
      failLoad(file_, where + ": the node hierarchy is deeper than " + std::to_string(kMaxNodeDepth));
    // Every node is entered once: a node listed twice, or with two parents, would be instanced again with all
    // its descendants (doubling at every level), and a cycle would never end. glTF allows neither.
    nodeStates_.resize(model_.nodes.size(), NodeState::Unvisited);
    if (nodeStates_[size_t(index)] == NodeState::OnPath)
      failLoad(file_, where + ": the node is its own ancestor (a cycle through " + from + ")");
    if (nodeStates_[size_t(index)] == NodeState::Done)
      failLoad(file_, where + ": listed again in " + from + "; a node may have only one parent and be listed once");
    nodeStates_[size_t(index)] = NodeState::OnPath;
    const tinygltf::Node& node = model_.nodes[size_t(index)];
    glm::mat4 world = parent * localTransform(node);
    for (int i = 0; i < 16; ++i)
      if (!std::isfinite(glm::value_ptr(world)[i])) failLoad(file_, where + ": transform is not finite");
    const int32_t animationNode =
        posed_[size_t(index)] || parentNode >= 0 ? addAnimationNode(index, parent, parentNode) : -1;
    if (node.mesh >= 0) {
      if (size_t(node.mesh) >= model_.meshes.size())
        failLoad(file_, where + ".mesh: mesh " + std::to_string(node.mesh) + " does not exist");
      const std::optional<uint32_t> mesh = deforms(node) ? deformedMeshFor(index, animationNode) : meshFor(node.mesh);
      if (mesh) addInstances(*mesh, node, world, where, animationNode);
    }
    if (node.camera >= 0) takeCamera(node.camera, world, where, animationNode);
    if (auto light = node.extensions.find("KHR_lights_punctual"); light != node.extensions.end())
      addLight(light->second, world, where, animationNode);
    return {index, world, depth, animationNode};
  }

  // `local`: what the instance's transform applies before the node's (`world`), for the animation to keep.
  void addInstance(uint32_t mesh, const glm::mat4& world, const std::string& where, int32_t animationNode,
                   const glm::mat4& local) {
    if (scene_.instances.size() == kMaxInstances)
      failLoad(file_, where + ": more than " + std::to_string(kMaxInstances) + " mesh instances");
    if (animationNode >= 0)
      scene_.animation.instances.push_back(
          {uint32_t(scene_.instances.size()), uint32_t(animationNode), toAffine(local)});
    scene_.instances.push_back({mesh, toAffine(world)});
  }

  // Makes the node an entry of the animation's nodes, under `parentNode` (-1: under the fixed `parent`).
  int32_t addAnimationNode(int index, const glm::mat4& parent, int32_t parentNode) {
    const tinygltf::Node& source = model_.nodes[size_t(index)];
    AnimationNode node;
    node.parent = parentNode;
    if (parentNode < 0) node.parentToWorld = toAffine(parent);
    node.sourceIndex = uint32_t(index);
    if (source.matrix.size() == 16 && !animated_[size_t(index)]) {
      node.hasMatrix = 1;
      node.matrix = toAffine(localTransform(source));
    } else if (source.matrix.size() == 16) {
      // glTF gives animated nodes no matrix; where a file does anyway, its channels replace parts of the
      // matrix's decomposition.
      glm::vec3 scale(1.0f), translation(0.0f), skew;
      glm::vec4 perspective;
      glm::quat rotation(1.0f, 0.0f, 0.0f, 0.0f);
      if (!glm::decompose(localTransform(source), scale, rotation, translation, skew, perspective))
        failLoad(file_, "nodes[" + std::to_string(index) + "].matrix: an animated node needs an invertible matrix");
      node.translation = {translation.x, translation.y, translation.z};
      node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
      node.scale = {scale.x, scale.y, scale.z};
    } else {
      const auto& t = source.translation;
      const auto& r = source.rotation;
      const auto& sc = source.scale;
      if (t.size() == 3) node.translation = {float(t[0]), float(t[1]), float(t[2])};
      if (r.size() == 4) node.rotation = {float(r[0]), float(r[1]), float(r[2]), float(r[3])};
      if (sc.size() == 3) node.scale = {float(sc[0]), float(sc[1]), float(sc[2])};
    }
    animationNodes_[size_t(index)] = int32_t(scene_.animation.nodes.size());
    scene_.animation.nodes.push_back(node);
    return animationNodes_[size_t(index)];
  }

  void readAnimations() {
    scene_.animation.clips = readGltfAnimations(model_, accessors_, animationNodes_, file_, warnings_);
    // The rest pose through the player, so that animated instances scaled to nothing at rest are hidden
    // rather than dropped by the scene's repair (they may grow later), and skinned and morphed meshes take the
    // shape their joints and weights give them at rest.
    if (!scene_.animation.empty() || !scene_.animation.deformations.empty())
      AnimationPlayer(scene_).pose(scene_, -1, 0.0f);
    if (scene_.animation.empty()) scene_.animation = {};
  }

  // One instance of `mesh` at the node's transform, or, with EXT_mesh_gpu_instancing, one per element of its
  // TRANSLATION, ROTATION and SCALE accessors, each applied before the node's transform.
  void addInstances(uint32_t mesh, const tinygltf::Node& node, const glm::mat4& world, const std::string& where,
                    int32_t animationNode) {
    auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
    if (ext == node.extensions.end() || !ext->second.Has("attributes")) {
      addInstance(mesh, world, where, animationNode, glm::mat4(1.0f));
      return;
    }
    const tinygltf::Value& attributes = ext->second.Get("attributes");
    std::string at = where + ".extensions.EXT_mesh_gpu_instancing.attributes.";
    auto accessorOf = [&](const char* name) {
      return attributes.Has(name) && attributes.Get(name).IsInt() ? attributes.Get(name).GetNumberAsInt() : -1;
    };
    std::vector<Vec3> translations, scales;
    std::vector<Vec4> rotations;
    if (int a = accessorOf("TRANSLATION"); a >= 0) translations = accessors_.readVec3(a, at + "TRANSLATION");
    if (int a = accessorOf("ROTATION"); a >= 0) rotations = accessors_.readVec4(a, at + "ROTATION");
    if (int a = accessorOf("SCALE"); a >= 0) scales = accessors_.readVec3(a, at + "SCALE");
    size_t count = std::max({translations.size(), rotations.size(), scales.size()});
    for (size_t n : {translations.size(), rotations.size(), scales.size()})
      if (n != 0 && n != count)
        failLoad(file_, at + "*: the attributes have different counts (" + std::to_string(n) + " and " +
                            std::to_string(count) + ")");
    for (size_t i = 0; i < count; ++i) {
      glm::mat4 local(1.0f);
      if (!translations.empty())
        local = glm::translate(local, glm::vec3(translations[i].x, translations[i].y, translations[i].z));
      if (!rotations.empty())
        local *=
            glm::mat4_cast(glm::normalize(glm::quat(rotations[i].w, rotations[i].x, rotations[i].y, rotations[i].z)));
      if (!scales.empty()) local = glm::scale(local, glm::vec3(scales[i].x, scales[i].y, scales[i].z));
      glm::mat4 instance = world * local;
      bool finite = true;
      for (int k = 0; k < 16; ++k) finite &= std::isfinite(glm::value_ptr(instance)[k]);
      if (!finite) {
        warnings_.add(file_, at + "*: instance " + std::to_string(i) + " has a non-finite transform and is left out");
        continue;
      }
      addInstance(mesh, instance, where, animationNode, local);
    }
  }

  // A node's KHR_lights_punctual light, at the node's origin and shining along its -Z. The intensity is taken as
  // radiant (candela for point and spot lights as W/sr, lux for directional ones as W/m^2), as glTF viewers use
  // it.
  void addLight(const tinygltf::Value& extension, const glm::mat4& world, const std::string& where,
                int32_t animationNode) {
    const std::string at = where + ".extensions.KHR_lights_punctual.light";
    if (!extension.Has("light") || !extension.Get("light").IsInt()) failLoad(file_, at + ": expected a light index");
    const int index = extension.Get("light").GetNumberAsInt();
    if (index < 0 || size_t(index) >= model_.lights.size())
      failLoad(file_, at + ": light " + std::to_string(index) + " does not exist");
    const tinygltf::Light& source = model_.lights[size_t(index)];
    const std::string lightWhere = "extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "]";
    PunctualLight light;
    if (source.type == "point") {
      light.type = PunctualLightType::Point;
    } else if (source.type == "spot") {
      light.type = PunctualLightType::Spot;
      light.cosOuter = std::cos(float(source.spot.outerConeAngle));
      light.cosInner = std::cos(float(source.spot.innerConeAngle));
    } else if (source.type == "directional") {
      light.type = PunctualLightType::Directional;
    } else {
      warnings_.add(file_, lightWhere + ".type '" + source.type + "' is not a light type glTF defines; it is left out");
      return;
    }
    Vec3 color{1, 1, 1};
    if (source.color.size() == 3) color = {float(source.color[0]), float(source.color[1]), float(source.color[2])};
    if (!(color.x >= 0 && color.y >= 0 && color.z >= 0 && source.intensity >= 0)) {
      warnings_.add(file_, lightWhere + " has a negative or non-finite colour or intensity; it is left out");
      return;
    }
    light.intensity = color * float(source.intensity);
    const glm::vec4 position = world * glm::vec4(0, 0, 0, 1), direction = world * glm::vec4(0, 0, -1, 0);
    light.position = {position.x, position.y, position.z};
    light.direction = {direction.x, direction.y, direction.z};  // normalised (or the light dropped) by the repair
    if (source.range > 0.0) ++lightRangesIgnored_;
    if (animationNode >= 0)
      scene_.animation.lights.push_back({uint32_t(scene_.punctualLights.size()), uint32_t(animationNode)});
    scene_.punctualLights.push_back(light);
  }

  void takeCamera(int index, const glm::mat4& world, const std::string& where, int32_t animationNode) {
    if (size_t(index) >= model_.cameras.size())
      failLoad(file_, where + ".camera: camera " + std::to_string(index) + " does not exist");
    const tinygltf::Camera& c = model_.cameras[size_t(index)];
    const bool orthographic = c.type == "orthographic";
    if (c.type != "perspective" && !orthographic) {
      warnings_.add(file_, "cameras[" + std::to_string(index) + "] is of type '" + c.type +
                               "'; only perspective and orthographic cameras are used");
      return;
    }
    glm::vec3 eye = world * glm::vec4(0, 0, 0, 1);
    glm::vec3 forward = glm::normalize(glm::vec3(world * glm::vec4(0, 0, -1, 0)));
    glm::vec3 up = glm::normalize(glm::vec3(world * glm::vec4(0, 1, 0, 0)));
    float yfov = float(c.perspective.yfov) * 180.0f / kPi;
    CameraDescription d;
    d.eye = {eye.x, eye.y, eye.z};
    d.target = {eye.x + forward.x, eye.y + forward.y, eye.z + forward.z};
    d.up = {up.x, up.y, up.z};
    d.verticalFovDegrees = std::isfinite(yfov) && yfov > 0.0f && yfov < 180.0f ? yfov : 40.0f;
    if (orthographic) {
      // ymag is half the view's height; its width follows the image's aspect ratio, as a perspective camera's
      // yfov does (xmag, like aspectRatio, is not used).
      const float halfHeight = float(c.orthographic.ymag);
      if (!(std::isfinite(halfHeight) && halfHeight > 0.0f && halfHeight <= kMaxCameraCoordinate)) {
        warnings_.add(file_, "cameras[" + std::to_string(index) +
                                 "]: orthographic ymag must be positive and at most 1e9; the camera is not used");
        return;
      }
      d.projection = Projection::Orthographic;
      d.orthographicHalfHeight = halfHeight;
    }
    if (!isFinite(d.eye) || !isFinite(d.target) || !isFinite(d.up)) return;
    if (!cameraFound_) {
      scene_.camera = d;
      scene_.cameraIndex = int32_t(scene_.cameras.size());
    }
    cameraFound_ = true;
    if (animationNode >= 0)
      scene_.animation.cameras.push_back({uint32_t(scene_.cameras.size()), uint32_t(animationNode)});
    scene_.cameras.push_back({c.name.empty() ? "cameras[" + std::to_string(index) + "] at " + where : c.name, d});
  }

  // Whether the node's mesh is skinned or morphed: the node then gets a mesh of its own to deform.
  bool deforms(const tinygltf::Node& node) const {
    const bool skinned = node.skin >= 0 && size_t(node.skin) < model_.skins.size();
    return node.mesh >= 0 && size_t(node.mesh) < model_.meshes.size() &&
           (skinned || morphTargetCount(model_, int(&node - model_.nodes.data())) > 0);
  }

  // Per node of the file: whether it needs an entry in the animation's nodes of its own: an animated node, a
  // skin's joint, or a node with a skinned or morphed mesh.
  std::vector<bool> posedNodes() const {
    std::vector<bool> posed = animated_;
    for (size_t n = 0; n < model_.nodes.size(); ++n) {
      const tinygltf::Node& node = model_.nodes[n];
      if (!deforms(node)) continue;
      posed[n] = true;
      if (node.skin >= 0 && size_t(node.skin) < model_.skins.size())
        for (int joint : model_.skins[size_t(node.skin)].joints)
          if (joint >= 0 && size_t(joint) < posed.size()) posed[size_t(joint)] = true;
    }
    return posed;
  }

  // A mesh of its own for node `index`, whose skin or morph targets deform it (SceneAnimation::deformations).
  std::optional<uint32_t> deformedMeshFor(int index, int32_t animationNode) {
    const tinygltf::Node& node = model_.nodes[size_t(index)];
    std::vector<GltfVertexOrigin> origins;
    Mesh mesh = convertMesh(node.mesh, &origins);
    if (mesh.triangleCount() == 0) return std::nullopt;
    const size_t targets = morphTargetCount(model_, index);
    deformedVertices_ += mesh.positions.size() * (1 + targets);
    if (deformedVertices_ > kMaxDeformedVertices)
      failLoad(file_, "nodes[" + std::to_string(index) + "]: skinned and morphed meshes of more than " +
                          std::to_string(kMaxDeformedVertices) +
                          " vertices in all, counted once per morph target too (each node deforms a copy of its "
                          "mesh of its own)");
    MeshDeformation d;
    d.mesh = uint32_t(scene_.meshes.size());
    d.node = uint32_t(animationNode);
    d.positions = mesh.positions;
    d.normals = mesh.normals;
    d.tangents = mesh.tangents;
    readGltfMorphTargets(model_, accessors_, node.mesh, index, origins, file_, d);
    if (node.skin >= 0 && size_t(node.skin) < model_.skins.size() &&
        readGltfSkinWeights(model_, accessors_, node.mesh, node.skin, origins, file_, warnings_, d)) {
      d.skin = node.skin;  // the file's skin until resolveSkins
    }
    if (d.targetCount > 0 || d.skin >= 0) scene_.animation.deformations.push_back(std::move(d));
    scene_.meshes.push_back(std::move(mesh));
    return uint32_t(scene_.meshes.size() - 1);
  }

  // Replaces the file's skin indices of the deformations by indices into the animation's skins, read once each;
  // a deformation whose skin has joints outside the scene keeps only its morph targets.
  void resolveSkins() {
    std::map<int, std::optional<uint32_t>> skins;
    auto& deformations = scene_.animation.deformations;
    for (MeshDeformation& d : deformations) {
      if (d.skin < 0) continue;
      auto it = skins.find(d.skin);
      if (it == skins.end()) {
        std::optional<Skin> skin = readGltfSkin(model_, accessors_, d.skin, animationNodes_, file_, warnings_);
        std::optional<uint32_t> id;
        if (skin) {
          id = uint32_t(scene_.animation.skins.size());
          scene_.animation.skins.push_back(std::move(*skin));
        }
        it = skins.emplace(d.skin, id).first;
      }
      d.skin = it->second ? int32_t(*it->second) : -1;
      if (d.skin < 0) {
        d.joints.clear();
        d.jointWeights.clear();
      }
    }
    std::erase_if(deformations, [](const MeshDeformation& d) { return d.skin < 0 && d.targetCount == 0; });
  }

  std::optional<uint32_t> meshFor(int gltfMesh) {
    auto it = meshes_.find(gltfMesh);
    if (it != meshes_.end()) return it->second;
    auto [same, added] = meshesBySignature_.emplace(meshSignature(gltfMesh), std::nullopt);
    if (added) {
      Mesh mesh = convertMesh(gltfMesh);
      if (mesh.triangleCount() > 0) {
        same->second = uint32_t(scene_.meshes.size());
        scene_.meshes.push_back(std::move(mesh));
      }
    }
    meshes_[gltfMesh] = same->second;
    return same->second;
  }

  uint32_t defaultMaterial() {
    if (!defaultMaterial_) {
      Material m;  // glTF's default material: white, fully metallic, fully rough
      m.type = MaterialType::Pbr;
      m.baseColor = {1, 1, 1};
      m.metallic = 1.0f;
      m.roughness = 1.0f;
      m.doubleSided = 0;
      defaultMaterial_ = uint32_t(scene_.materials.size());
      scene_.materials.push_back(m);
      scene_.materialNames.push_back("default");
    }
    return *defaultMaterial_;
  }

  // The accessors a primitive's vertices are read from, and the material whose uv transform they take: primitives
  // that agree on them share one set of vertices.
  using VertexSource = std::array<int, 6>;  // POSITION, NORMAL, TEXCOORD_n, its uv transform's material, COLOR_0,
                                            // TANGENT

  // Vertices read from one set of accessors, and the triangles of the primitives that share them.
  struct MeshPart {
    std::vector<Vec3> positions, normals;
    std::vector<Vec2> uvs;
    std::vector<Vec4> tangents;
    std::vector<Vec3> colors;
    std::vector<uint32_t> indices;
    std::vector<uint32_t> triangleMaterials;
  };

  void readVertices(const tinygltf::Primitive& prim, const VertexSource& source, const std::string& where,
                    MeshPart& part) {
    part.positions = accessors_.readVec3(source[0], where + ".attributes.POSITION");
    const size_t n = part.positions.size();
    auto sameCount = [&](size_t count, const std::string& what) {
      if (count != n)
        failLoad(file_, where + ".attributes." + what + ": " + std::to_string(count) + " elements for " +
                            std::to_string(n) + " positions");
    };
    if (source[1] >= 0) {
      part.normals = accessors_.readVec3(source[1], where + ".attributes.NORMAL");
      sameCount(part.normals.size(), "NORMAL");
    }
    const std::string texCoord =
        "TEXCOORD_" + std::to_string(prim.material >= 0 ? texCoords_[size_t(prim.material)] : 0);
    if (source[2] >= 0) {
      part.uvs = accessors_.readVec2(source[2], where + ".attributes." + texCoord);
      sameCount(part.uvs.size(), texCoord);
      if (source[3] >= 0)
        for (Vec2& uv : part.uvs) uv = uvTransforms_[size_t(source[3])]->apply(uv);
    } else if (texCoord != "TEXCOORD_0") {
      warnings_.add(file_, where + ": the material's textures read " + texCoord + ", which the primitive lacks");
    }
    if (source[4] >= 0) {
      std::vector<Vec4> rgba = accessors_.readColours(source[4], where + ".attributes.COLOR_0");
      sameCount(rgba.size(), "COLOR_0");
      part.colors.resize(rgba.size());
      bool translucent = false;
      for (size_t i = 0; i < rgba.size(); ++i) {
        part.colors[i] = {rgba[i].x, rgba[i].y, rgba[i].z};
        translucent |= rgba[i].w < 1.0f;
      }
      if (translucent) warnings_.add(file_, where + ".attributes.COLOR_0: the alpha of vertex colours is ignored");
    }
    if (source[5] >= 0) {
      part.tangents = accessors_.readVec4(source[5], where + ".attributes.TANGENT");
      sameCount(part.tangents.size(), "TANGENT");
    }
  }

  VertexSource vertexSourceOf(const tinygltf::Primitive& prim) const {
    auto attribute = [&](const std::string& name) {
      auto it = prim.attributes.find(name);
      return it == prim.attributes.end() ? -1 : it->second;
    };
    const bool known = prim.material >= 0 && size_t(prim.material) < model_.materials.size();
    const int texCoord = known ? texCoords_[size_t(prim.material)] : 0;
    const int uvTransform = known && uvTransforms_[size_t(prim.material)] ? prim.material : -1;
    return {attribute("POSITION"), attribute("NORMAL"),  attribute("TEXCOORD_" + std::to_string(texCoord)),
            uvTransform,           attribute("COLOR_0"), attribute("TANGENT")};
  }

  // What a static mesh is made of: its primitives' accessors, modes and materials. glTF meshes that agree on it
  // are one mesh of the scene, instanced by every node that names one of them.
  std::vector<std::tuple<VertexSource, int, int, int>> meshSignature(int meshIndex) const {
    std::vector<std::tuple<VertexSource, int, int, int>> signature;
    for (const tinygltf::Primitive& prim : model_.meshes[size_t(meshIndex)].primitives)
      signature.emplace_back(vertexSourceOf(prim), prim.indices, prim.mode, prim.material);
    return signature;
  }

  // With `origins`, also where each vertex of the mesh came from (for its morph targets and skin weights); each
  // primitive then has vertices of its own, as its morph targets may differ. Running out of memory is said so,
  // naming the mesh and its size.
  Mesh convertMesh(int meshIndex, std::vector<GltfVertexOrigin>* origins = nullptr) {
    try {
      return buildMesh(meshIndex, origins);
    } catch (const std::bad_alloc&) {
      uint64_t vertices = 0, indices = 0;
      for (const tinygltf::Primitive& prim : model_.meshes[size_t(meshIndex)].primitives) {
        auto position = prim.attributes.find("POSITION");
        if (position != prim.attributes.end() && size_t(position->second) < model_.accessors.size())
          vertices += model_.accessors[size_t(position->second)].count;
        if (prim.indices >= 0 && size_t(prim.indices) < model_.accessors.size())
          indices += model_.accessors[size_t(prim.indices)].count;
      }
      failLoad(file_, "meshes[" + std::to_string(meshIndex) + "]: not enough memory for its " +
                          std::to_string(vertices) + " vertices and " + std::to_string(indices) + " indices (with " +
                          std::to_string(scene_.meshes.size()) + " meshes built before it)");
    }
  }

  Mesh buildMesh(int meshIndex, std::vector<GltfVertexOrigin>* origins) {
    const tinygltf::Mesh& gm = model_.meshes[size_t(meshIndex)];
    const std::string meshWhere = "meshes[" + std::to_string(meshIndex) + "]";
    std::vector<MeshPart> parts;
    std::vector<uint32_t> partPrimitives;  // per part, its (first) index in gm.primitives
    std::map<VertexSource, size_t> partOf;
    // A primitive with the vertices, indices and mode of an earlier one draws the same triangles again.
    std::set<std::tuple<VertexSource, int, int>> drawn;
    size_t repeats = 0;
    for (size_t p = 0; p < gm.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = gm.primitives[p];
      std::string where = meshWhere + ".primitives[" + std::to_string(p) + "]";
      if (prim.mode < TINYGLTF_MODE_TRIANGLES && prim.mode >= 0) {
        warnings_.add(file_, where + ": points and lines are not rendered");
        continue;
      }
      if (prim.mode > TINYGLTF_MODE_TRIANGLE_FAN)
        failLoad(file_, where + ".mode: unknown mode " + std::to_string(prim.mode));
      if (prim.material >= 0 && size_t(prim.material) >= model_.materials.size())
        failLoad(file_, where + ".material: material " + std::to_string(prim.material) + " does not exist");
      const VertexSource source = vertexSourceOf(prim);
      if (source[0] < 0) failLoad(file_, where + ".attributes: POSITION is missing");
      if (!origins && !drawn.emplace(source, prim.indices, prim.mode).second) {
        ++repeats;
        continue;
      }
      auto shared = origins ? partOf.end() : partOf.find(source);
      MeshPart fresh;
      MeshPart& part = shared != partOf.end() ? parts[shared->second] : fresh;
      if (shared == partOf.end()) readVertices(prim, source, where, fresh);
      const size_t n = part.positions.size();
      std::vector<uint32_t> indices;
      if (prim.indices >= 0) {
        indices = accessors_.readIndices(prim.indices, where + ".indices");
        for (size_t i = 0; i < indices.size(); ++i)
          if (indices[i] >= n)
            failLoad(file_, where + ".indices: index " + std::to_string(indices[i]) + " (element " + std::to_string(i) +
                                ") is beyond the " + std::to_string(n) + " vertices");
      } else {
        indices.resize(n);
        for (size_t i = 0; i < n; ++i) indices[i] = uint32_t(i);
      }
      const std::vector<uint32_t> triangles = toTriangleList(indices, prim.mode);
      part.indices.insert(part.indices.end(), triangles.begin(), triangles.end());
      part.triangleMaterials.insert(part.triangleMaterials.end(), triangles.size() / 3,
                                    prim.material >= 0 ? uint32_t(prim.material) : defaultMaterial());
      if (shared == partOf.end() && !part.indices.empty()) {
        if (!origins) partOf.emplace(source, parts.size());
        parts.push_back(std::move(fresh));
        partPrimitives.push_back(uint32_t(p));
      }
    }
    if (repeats > 0)
      warnings_.add(file_, meshWhere + ": " + std::to_string(repeats) +
                               " primitives draw the triangles of an earlier primitive again and are left out");

    Mesh mesh;
    mesh.name = gm.name.empty() ? "meshes[" + std::to_string(meshIndex) + "]" : gm.name;
    bool anyNormals = false, allNormals = true, anyUvs = false, anyColors = false, allTangents = !parts.empty();
    for (const MeshPart& p : parts) {
      anyNormals |= !p.normals.empty();
      allNormals &= !p.normals.empty();
      anyUvs |= !p.uvs.empty();
      anyColors |= !p.colors.empty();
      allTangents &= !p.tangents.empty();
    }
    for (size_t part = 0; part < parts.size(); ++part) {
      MeshPart& p = parts[part];
      // glTF asks for flat shading where normals are missing; when other primitives of the mesh have normals,
      // this primitive's triangles get their own vertices with the face normal.
      const bool unwelded = anyNormals && !allNormals && p.normals.empty();
      if (origins) {
        const size_t n = unwelded ? p.indices.size() : p.positions.size();
        for (size_t v = 0; v < n; ++v)
          origins->push_back({partPrimitives[part], unwelded ? p.indices[v] : uint32_t(v)});
      }
      if (unwelded) unweldWithFaceNormals(p);
      if (mesh.positions.size() + p.positions.size() > uint64_t(UINT32_MAX))
        failLoad(file_, "meshes[" + std::to_string(meshIndex) + "]: too many vertices");
      uint32_t base = uint32_t(mesh.positions.size());
      mesh.positions.insert(mesh.positions.end(), p.positions.begin(), p.positions.end());
      if (anyNormals) mesh.normals.insert(mesh.normals.end(), p.normals.begin(), p.normals.end());
      if (anyUvs) {
        if (p.uvs.empty()) p.uvs.resize(p.positions.size());
        mesh.uvs.insert(mesh.uvs.end(), p.uvs.begin(), p.uvs.end());
      }
      if (anyColors) {
        if (p.colors.empty()) p.colors.resize(p.positions.size(), Vec3{1, 1, 1});
        mesh.colors.insert(mesh.colors.end(), p.colors.begin(), p.colors.end());
      }
      if (allTangents) mesh.tangents.insert(mesh.tangents.end(), p.tangents.begin(), p.tangents.end());
      for (uint32_t i : p.indices) mesh.indices.push_back(base + i);
      mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), p.triangleMaterials.begin(),
                                    p.triangleMaterials.end());
    }
    return mesh;
  }

  static std::vector<uint32_t> toTriangleList(const std::vector<uint32_t>& in, int mode) {
    std::vector<uint32_t> out;
    if (mode == TINYGLTF_MODE_TRIANGLES || mode < 0) {
      out.assign(in.begin(), in.begin() + std::ptrdiff_t(in.size() / 3 * 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (size_t i = 2; i < in.size(); ++i) {
        bool odd = i % 2 == 1;
        out.insert(out.end(), {in[i - 2], odd ? in[i] : in[i - 1], odd ? in[i - 1] : in[i]});
      }
    } else {
      for (size_t i = 2; i < in.size(); ++i) out.insert(out.end(), {in[0], in[i - 1], in[i]});
    }
    return out;
  }

  static void unweldWithFaceNormals(MeshPart& part) {
    auto& [positions, normals, uvs, tangents, colors, indices, triangleMaterials] = part;
    std::vector<Vec3> p, col;
    std::vector<Vec2> uv;
    std::vector<Vec4> tg;
    for (size_t t = 0; t < indices.size() / 3; ++t) {
      const uint32_t* c = &indices[3 * t];
      Vec3 n = cross(positions[c[1]] - positions[c[0]], positions[c[2]] - positions[c[0]]);
      float len = length(n);
      for (int k = 0; k < 3; ++k) {
        p.push_back(positions[c[k]]);
        if (!uvs.empty()) uv.push_back(uvs[c[k]]);
        if (!tangents.empty()) tg.push_back(tangents[c[k]]);
        if (!colors.empty()) col.push_back(colors[c[k]]);
        normals.push_back(len > 0.0f ? n / len : Vec3{});
      }
    }
    for (size_t i = 0; i < indices.size(); ++i) indices[i] = uint32_t(i);
    positions = std::move(p);
    uvs = std::move(uv);
    tangents = std::move(tg);
    colors = std::move(col);
  }

  int32_t texture(int index, bool srgb) {
    std::string where = "textures[" + std::to_string(index) + "]";
    if (index < 0 || size_t(index) >= model_.textures.size()) {
      warnings_.add(file_, where + " does not exist; the material is left untextured");
      return kNoTexture;
    }
    const tinygltf::Texture& t = model_.textures[size_t(index)];
    auto wrapMode = [](int w) {
      return w == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? TextureWrap::Clamp
             : w == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? TextureWrap::Mirror
                                                          : TextureWrap::Repeat;
    };
    TextureWrap wrapU = TextureWrap::Repeat, wrapV = TextureWrap::Repeat;
    if (t.sampler >= 0 && size_t(t.sampler) < model_.samplers.size()) {
      wrapU = wrapMode(model_.samplers[size_t(t.sampler)].wrapS);
      wrapV = wrapMode(model_.samplers[size_t(t.sampler)].wrapT);
    }
    const int source = textureImageIndex(t);
    if (source < 0 || size_t(source) >= model_.images.size()) {
      std::string ext =
          t.extensions.empty() ? "" : " (it uses " + t.extensions.begin()->first + ", which is not supported)";
      warnings_.add(file_, where + " has no image" + ext + "; the material is left untextured");
      return kNoTexture;
    }
    const tinygltf::Image& image = model_.images[size_t(source)];
    std::string imageWhere = "images[" + std::to_string(source) + "]";
    if (!image.image.empty())
      return textures_.fromMemory(file_ + ": " + imageWhere, file_ + ": " + imageWhere, image.image, srgb, wrapU,
                                  wrapV);
    if (!image.uri.empty() && !baseDir_.empty()) {
      std::optional<std::string> path = uriToPath(image.uri);
      if (path && !path->empty())
        return textures_.fromFile(confineModelPath(joinModelPath(baseDir_, *path), files_), srgb, wrapU, wrapV);
      warnings_.add(file_, imageWhere + ".uri '" + image.uri +
                               "' names no file in the glTF file's folder (a "
                               "relative path with valid %-escapes); the material is left untextured");
      return kNoTexture;
    }
    warnings_.add(file_, imageWhere + " has no data; the material is left untextured");
    return kNoTexture;
  }

  // The mean texel of textures[index] from a small decode of its image, for what needs one number for a
  // texture (gltf_materials.h); nothing where the image cannot be read.
  std::optional<Vec4> textureMean(int index, bool srgb) {
    if (index < 0 || size_t(index) >= model_.textures.size()) return std::nullopt;
    const int source = textureImageIndex(model_.textures[size_t(index)]);
    if (source < 0 || size_t(source) >= model_.images.size()) return std::nullopt;
    const tinygltf::Image& image = model_.images[size_t(source)];
    const std::string name = file_ + ": images[" + std::to_string(source) + "]";
    try {
      std::vector<uint8_t> bytes;
      if (!image.image.empty()) {
        bytes = image.image;
      } else {
        std::optional<std::string> path = image.uri.empty() || baseDir_.empty() ? std::nullopt : uriToPath(image.uri);
        if (!path || path->empty()) return std::nullopt;
        const ResolvedPath resolved = confineModelPath(joinModelPath(baseDir_, *path), files_);
        if (!resolved.allowed()) return std::nullopt;
        bytes = readFileBytes(resolved.path);
      }
      constexpr uint32_t kMeanSide = 16;
      const Texture t = decodeImage(name, bytes.data(), bytes.size(), srgb, kMeanSide, kMeanSide);
      const size_t texels = size_t(t.width) * t.height;
      if (texels == 0) return std::nullopt;
      double sum[4] = {0, 0, 0, 0};
      for (size_t i = 0; i < texels; ++i)
        for (uint32_t c = 0; c < 4; ++c) {
          const uint32_t from = t.channels == 1 ? 0 : std::min(c, t.channels - 1);
          const size_t at = i * t.channels + from;
          float v = t.floats.empty() ? float(t.bytes[at]) / 255.0f : t.floats[at];
          if (t.channels == 1 && c == 3) v = 1.0f;  // grey images have no alpha
          sum[c] += c < 3 && t.srgb ? srgbToLinear(v) : v;
        }
      return Vec4{float(sum[0] / double(texels)), float(sum[1] / double(texels)), float(sum[2] / double(texels)),
                  float(sum[3] / double(texels))};
    } catch (const LoadError&) {
      return std::nullopt;
    }
  }

  const tinygltf::Model& model_;
  std::string file_;
  PathRule files_;
  std::string baseDir_;
  LoadWarnings& warnings_;
  GltfAccessorReader accessors_;
  Scene scene_;
  TextureTable ownTextures_;
  TextureTable& textures_;
  bool sharesTextures_;
  std::vector<std::optional<UvTransform>> uvTransforms_;
  std::vector<int> texCoords_;                     // the TEXCOORD set each material's textures read
  std::map<int, std::optional<uint32_t>> meshes_;  // by glTF mesh
  std::map<std::vector<std::tuple<VertexSource, int, int, int>>, std::optional<uint32_t>> meshesBySignature_;
  std::optional<uint32_t> defaultMaterial_;
  bool cameraFound_ = false;
  size_t lightRangesIgnored_ = 0;
  std::vector<bool> animated_;           // per node of the file: a channel moves it
  std::vector<bool> posed_;              // per node of the file: it has an entry in scene_.animation.nodes
  size_t deformedVertices_ = 0;          // of the meshes deformedMeshFor made
  std::vector<int32_t> animationNodes_;  // per node of the file: its entry in scene_.animation.nodes, or -1
  enum class NodeState : uint8_t { Unvisited, OnPath, Done };
  std::vector<NodeState> nodeStates_;  // by node index, for the traversal
};

Scene loadFromBytes(const std::string& name, const uint8_t* data, size_t size, const PathRule& files,
                    LoadWarnings& warnings, TextureTable* sharedTextures) {
  const std::string& baseDir = files.folder;
  if (size == 0) failLoad(name, "file is empty");
  bool binary = isGlb(data, size);
  if (binary) checkGlbLengths(name, data, size);
  auto [json, jsonSize] = binary ? glbJson(data, size) : std::pair{reinterpret_cast<const char*>(data), size};
  if (json && jsonDepth(json, jsonSize) > kMaxJsonDepth)
    failLoad(name, "JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
  checkGltfByteRanges(data, size, name);
  // Draco primitives as tinygltf accepts them (gltf_draco.h); decodeDracoPrimitives fills them in after parsing.
  const std::optional<std::vector<uint8_t>> forTinygltf = withoutDracoIndices(data, size);
  if (forTinygltf) {
    data = forTinygltf->data();
    size = forTinygltf->size();
    std::tie(json, jsonSize) = binary ? glbJson(data, size) : std::pair{reinterpret_cast<const char*>(data), size};
  }
  // Meshopt fallback buffers as tinygltf accepts them (gltf_meshopt.h); decodeMeshoptBufferViews supersedes them.
  const std::optional<std::vector<uint8_t>> withPlaceholders = withMeshoptPlaceholderBuffers(data, size);
  if (withPlaceholders) {
    data = withPlaceholders->data();
    size = withPlaceholders->size();
    std::tie(json, jsonSize) = binary ? glbJson(data, size) : std::pair{reinterpret_cast<const char*>(data), size};
  }

  const GltfBufferList buffers(json ? std::string_view(json, jsonSize) : std::string_view());
  GltfBufferCharge bufferCharge(buffers, name);  // kept until the model that holds the buffers is gone
  tinygltf::TinyGLTF loader;
  FileAccess access{baseDir, files, buffers, {}, {}};
  loader.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile, &access});
  loader.SetImageLoader(&keepEncodedImage, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  bool ok = false;
  try {
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, unsigned(std::min<size_t>(size, UINT32_MAX)),
                                              baseDir)
                : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(data),
                                             unsigned(std::min<size_t>(size, UINT32_MAX)), baseDir);
  } catch (const std::bad_alloc&) {
    throw;  // the caller's out-of-memory report, as for every loader
  } catch (const std::exception& e) {
    // tinygltf's own checks miss some malformed files (a .glb's buffer of byteLength 0 reads its first byte).
    failLoad(name, std::string("tinygltf cannot read it: ") + e.what());
  }
  if (!ok) {
    // An extension candela lacks explains the failure best: a meshopt-compressed file's buffer of decoded data
    // has no URI, which would otherwise be reported as a buffer that names no file.
    if (json) refuseUnsupportedRequiredExtensions(json, jsonSize, name);
    if (!access.refusal.empty()) failLoad(name, access.refusal);
    failLoad(name, err.empty() ? "not a valid glTF file" : firstLine(err));
  }
  std::istringstream lines(warn);
  std::string line;
  while (std::getline(lines, line))
    if (!firstLine(line).empty()) warnings.add(name, firstLine(line));
  checkGltfExtensions(model, name, warnings);
  decodeDracoPrimitives(model, name, bufferCharge);
  decodeMeshoptBufferViews(model, name, bufferCharge);
  Scene scene = GltfSceneBuilder(model, name, files, warnings, sharedTextures).build();
  scene.inputFiles.insert(scene.inputFiles.begin(), access.filesRead.begin(), access.filesRead.end());
  return scene;
}

}  // namespace

Scene loadGltf(const std::string& path, LoadWarnings& warnings, OutsidePaths outside, SharedModelAssets* shared) {
  std::vector<uint8_t> bytes = readFileBytes(path);
  Scene scene = loadFromBytes(path, bytes.data(), bytes.size(), PathRule::forFile(path, outside), warnings,
                              shared ? &shared->textures : nullptr);
  scene.inputFiles.insert(scene.inputFiles.begin(), path);
  return scene;
}

Scene loadGltfBytes(const std::string& name, const uint8_t* data, size_t size, LoadWarnings& warnings) {
  return loadFromBytes(name, data, size, PathRule{}, warnings, nullptr);
}

}  // namespace candela
