#include "scene/loaders/pbrt/pbrt_loader.h"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <map>
#include <optional>
#include <vector>

#include "io/file_bytes.h"
#include "io/load_budget.h"
#include "scene/loaders/pbrt/pbrt_camera.h"
#include "scene/loaders/pbrt/pbrt_context.h"
#include "scene/loaders/pbrt/pbrt_curves.h"
#include "scene/loaders/pbrt/pbrt_film.h"
#include "scene/loaders/pbrt/pbrt_lights.h"
#include "scene/loaders/pbrt/pbrt_materials.h"
#include "scene/loaders/pbrt/pbrt_media.h"
#include "scene/loaders/pbrt/pbrt_parameters.h"
#include "scene/loaders/pbrt/pbrt_shape_key.h"
#include "scene/loaders/pbrt/pbrt_shapes.h"
#include "scene/loaders/pbrt/pbrt_spectrum_files.h"
#include "scene/loaders/pbrt/pbrt_textures.h"
#include "scene/loaders/pbrt/pbrt_tokenizer.h"
#include "scene/loaders/pbrt/pbrt_transforms.h"
#include "scene/scene_repair.h"
#include "scene/transform.h"

namespace candela {

namespace {

// Bounds on what a scene may ask for, so that a hostile file cannot recurse or multiply without end.
constexpr int kMaxIncludeDepth = 32;
constexpr size_t kMaxIncludedFiles = 4096;
constexpr size_t kMaxAttributeDepth = 4096;
// Triangles the loader makes beyond those the files hold (tessellated quadrics, subdivision): a line of text
// that asks for a sphere yields thousands, so they are bounded apart from the file sizes.
constexpr size_t kMaxGeneratedTriangles = size_t(1) << 25;

// Bytes a mesh holds, as the load's memory budget counts them.
uint64_t meshBytes(const Mesh& m) {
  return m.positions.size() * sizeof(Vec3) + m.normals.size() * sizeof(Vec3) + m.uvs.size() * sizeof(Vec2) +
         m.tangents.size() * sizeof(Vec4) + m.colors.size() * sizeof(Vec3) + m.indices.size() * sizeof(uint32_t) +
         m.triangleMaterials.size() * sizeof(uint32_t);
}

struct GraphicsState {
  glm::mat4 ctm{1.0f};
  bool reverseOrientation = false;
  std::optional<PbrtMaterial> material;  // none: pbrt's default diffuse, or the material named below
  std::string materialName;              // a NamedMaterial not made yet: pbrt-v4 resolves names once the scene is read
  std::optional<PbrtAreaLight> areaLight;
  // MediumInterface: the slots (PbrtMedia) of the media inside and outside the shapes that follow; the camera is
  // in the outside one when it is declared.
  MediumInterface media;
};

// A shape of an object definition (ObjectBegin): its mesh and its transform when the object was defined.
struct ObjectShape {
  uint32_t meshId;
  glm::mat4 worldFromShape;
  MediumInterface media;  // medium slots, as the definition declared them
};

// The texture and value of a shape's `alpha`, which candela keeps in the material.
struct AlphaSpec {
  float value = 1.0f;
  int32_t texture = kNoTexture;
};

// What reading an included file did, kept so that including it again in the same state places the same meshes
// again instead of reading and building them again: the meshes its shapes made (or shared) with their transforms
// relative to the transform at the Include, and the transform it leaves. Only files that do nothing else can be
// placed again (`reusable`): transforms relative to the current one, attribute blocks they close, materials
// chosen inside them, shapes that emit no light and further Includes.
struct IncludeRecording {
  struct Placement {
    uint32_t meshId;
    glm::mat4 relative;
  };
  std::vector<Placement> shapes;
  glm::mat4 relative{1.0f};
  std::vector<glm::mat4> saved;  // `relative` at each attribute block the file opened and has not closed
  bool reusable = true;
};

// The state an included file's effect depends on: the file, and what it would apply to its shapes.
using IncludeKey = std::tuple<std::string, bool, int64_t, std::string, bool>;

// Shapes equal in everything their mesh depends on: the shape's key, its orientation and its material.
using SharedShapeKey = std::tuple<std::string, bool, int64_t, std::string>;

struct PendingShape {
  uint32_t meshId;
  std::string materialName;
  std::vector<Vec3> emission;
  AlphaSpec alpha;
  size_t triangles;
  bool twoSidedLight;
  std::string file;
  size_t line;
};

class PbrtReader {
 public:
  PbrtReader(const std::string& file, LoadWarnings& warnings, OutsidePaths outside)
      : context_(file, warnings, outside), textures_(context_), materials_(context_, textures_), media_(context_) {}

  void readFile(const std::string& path, int depth) {
    if (depth > kMaxIncludeDepth) failLoad(path, "included more than " + std::to_string(kMaxIncludeDepth) + " deep");
    if (++includedFiles_ > kMaxIncludedFiles)
      failLoad(path, "the scene includes more than " + std::to_string(kMaxIncludedFiles) + " files");
    PbrtTokenizer tokens(path, readFileBytes(path));
    readDirectives(tokens, depth);
  }

  // An Include: read the file, or, when it was read before in the same state and did nothing but place
  // shapes, place the same meshes again.
  void include(const std::string& path, int depth) {
    if (recording_ || state_.areaLight) {
      readFile(path, depth);
      return;
    }
    const IncludeKey key{path, state_.reverseOrientation, materialKey(), state_.materialName, activeEndOnly_};
    if (auto found = includes_.find(key); found != includes_.end()) {
      if (++includedFiles_ > kMaxIncludedFiles)
        failLoad(path, "the scene includes more than " + std::to_string(kMaxIncludedFiles) + " files");
      for (const IncludeRecording::Placement& shape : found->second.shapes)
        putMesh(shape.meshId, state_.ctm * shape.relative, path, 0);
      state_.ctm = state_.ctm * found->second.relative;
      return;
    }
    const GraphicsState before = state_;
    const size_t stackDepth = stack_.size();
    recording_.emplace();
    readFile(path, depth);
    IncludeRecording recording = std::move(*recording_);
    recording_.reset();
    const bool sameState = state_.reverseOrientation == before.reverseOrientation &&
                           materialKey() == materialKeyOf(before) && state_.materialName == before.materialName &&
                           !state_.areaLight && stack_.size() == stackDepth;
    if (recording.reusable && sameState && recording.saved.empty()) includes_.emplace(key, std::move(recording));
  }

  static int64_t materialKeyOf(const GraphicsState& state) { return state.material ? int64_t(state.material->id) : -1; }
  int64_t materialKey() const { return materialKeyOf(state_); }

  // Whether an included file that uses directive `d` can be placed again without reading it (IncludeRecording).
  static bool replayable(const std::string& d) {
    for (const char* allowed : {"Translate", "Scale", "Rotate", "LookAt", "ConcatTransform", "AttributeBegin",
                                "AttributeEnd", "TransformBegin", "TransformEnd", "ReverseOrientation", "Shape",
                                "Material", "NamedMaterial", "Include", "Import"})
      if (d == allowed) return true;
    return false;
  }

  void readText(const std::string& name, const std::string& text) {
    textOnly_ = true;
    context_.filesAllowed = false;
    PbrtTokenizer tokens(name, text);
    readDirectives(tokens, 0);
  }

  Scene finish() {
    if (!worldBegun_) chooseWorldMirror();
    assignPendingMaterials();
    textures_.bakeImages();
    Scene& scene = context_.scene;
    PbrtFilm film = readPbrtFilm(film_ ? &*film_ : nullptr, camera_ ? &*camera_ : nullptr, context_);
    scene.renderHints.width = film.width;
    scene.renderHints.height = film.height;
    scaleSceneLights(scene, film.imagingRatio);
    placeMedia(scene);
    if (camera_) {
      scene.camera = makePbrtCamera(cameraType_, *camera_, cameraFromWorld_, film, mirrorX_, context_);
      context_.warnUnused("camera '" + cameraType_ + "'", *camera_);
    } else {
      PbrtParameters none;
      none.file = context_.mainFile;
      scene.camera = makePbrtCamera("perspective", none, glm::mat4(1.0f), film, mirrorX_, context_);
    }
    if (samplerSamples_) scene.renderHints.samplesPerPixel = *samplerSamples_;
    scene.renderHints.maxDepth = maxDepth_;
    return std::move(scene);
  }

 private:
  [[noreturn]] void fail(const PbrtTokenizer& tokens, size_t line, const std::string& what) {
    failLoad(tokens.file(), line, what);
  }

  float readNumber(PbrtTokenizer& tokens, const std::string& directive) {
    PbrtToken t = tokens.next();
    char* end = nullptr;
    float v = t.kind == PbrtToken::Kind::Word ? std::strtof(t.text.c_str(), &end) : 0.0f;
    if (t.kind != PbrtToken::Kind::Word || t.text.empty() || *end != '\0' || !std::isfinite(v))
      fail(tokens, t.line, directive + " expects numbers, found '" + t.text + "'");
    return v;
  }

  // `count` numbers, bare or in brackets.
  std::vector<double> readNumbers(PbrtTokenizer& tokens, size_t count, const std::string& directive) {
    bool bracketed = tokens.peek().kind == PbrtToken::Kind::OpenBracket;
    if (bracketed) tokens.next();
    std::vector<double> values;
    for (size_t i = 0; i < count; ++i) values.push_back(readNumber(tokens, directive));
    if (bracketed && tokens.next().kind != PbrtToken::Kind::CloseBracket)
      fail(tokens, tokens.line(), directive + " expects " + std::to_string(count) + " numbers in brackets");
    return values;
  }

  // The parameters of a directive that may name spectrum files (materials, textures, lights), with those read.
  PbrtParameters readParametersWithSpectra(PbrtTokenizer& tokens) {
    PbrtParameters params = parsePbrtParameters(tokens);
    readPbrtSpectrumFiles(params, context_);
    return params;
  }

  std::string readString(PbrtTokenizer& tokens, const std::string& directive) {
    PbrtToken t = tokens.next();
    if (t.kind != PbrtToken::Kind::String) fail(tokens, t.line, directive + " expects a quoted string");
    return t.text;
  }

  void applyTransform(const glm::mat4& m, PbrtTokenizer& tokens, size_t line, bool replace) {
    if (!isFiniteMatrix(m)) fail(tokens, line, "transform is not finite");
    if (activeEndOnly_) return;  // pbrt's end-of-shutter transform: candela renders the start of the shutter
    state_.ctm = replace ? m : state_.ctm * m;
    if (recording_) recording_->relative = replace ? m : recording_->relative * m;
  }

  void chooseWorldMirror() {
    mirrorX_ = pbrtWorldNeedsMirror(camera_ ? cameraFromWorld_ : glm::mat4(1.0f));
    worldFromPbrt_ = pbrtScale({mirrorX_ ? -1.0f : 1.0f, 1.0f, 1.0f});
  }

  void readDirectives(PbrtTokenizer& tokens, int depth) {
    for (;;) {
      PbrtToken t = tokens.next();
      if (t.kind == PbrtToken::Kind::End) return;
      if (t.kind != PbrtToken::Kind::Word) fail(tokens, t.line, "expected a directive, found '" + t.text + "'");
      const std::string& d = t.text;
      if (recording_ && !replayable(d)) recording_->reusable = false;
      if (d != "Shape") ++curveRun_;  // whatever changes what curves take ends a run of them (readCurve)
      if (d == "Identity") {
        applyTransform(glm::mat4(1.0f), tokens, t.line, true);
      } else if (d == "Translate") {
        auto v = readNumbers(tokens, 3, d);
        applyTransform(pbrtTranslate({float(v[0]), float(v[1]), float(v[2])}), tokens, t.line, false);
      } else if (d == "Scale") {
        auto v = readNumbers(tokens, 3, d);
        applyTransform(pbrtScale({float(v[0]), float(v[1]), float(v[2])}), tokens, t.line, false);
      } else if (d == "Rotate") {
        auto v = readNumbers(tokens, 4, d);
        const std::string problem = pbrtRotateProblem(float(v[0]), {float(v[1]), float(v[2]), float(v[3])});
        if (!problem.empty()) fail(tokens, t.line, "Rotate: " + problem);
        applyTransform(pbrtRotate(float(v[0]), {float(v[1]), float(v[2]), float(v[3])}), tokens, t.line, false);
      } else if (d == "LookAt") {
        auto v = readNumbers(tokens, 9, d);
        const std::string problem =
            pbrtLookAtProblem({float(v[0]), float(v[1]), float(v[2])}, {float(v[3]), float(v[4]), float(v[5])},
                              {float(v[6]), float(v[7]), float(v[8])});
        if (!problem.empty()) fail(tokens, t.line, "LookAt: " + problem);
        applyTransform(pbrtLookAt({float(v[0]), float(v[1]), float(v[2])}, {float(v[3]), float(v[4]), float(v[5])},
                                  {float(v[6]), float(v[7]), float(v[8])}),
                       tokens, t.line, false);
      } else if (d == "Transform" || d == "ConcatTransform") {
        auto v = readNumbers(tokens, 16, d);
        applyTransform(pbrtMatrix(v.data()), tokens, t.line, d == "Transform");
      } else if (d == "CoordinateSystem") {
        namedFrames_[readString(tokens, d)] = state_.ctm;
      } else if (d == "CoordSysTransform") {
        std::string name = readString(tokens, d);
        auto found = namedFrames_.find(name);
        if (found == namedFrames_.end())
          context_.warn("coordinate system " + name, tokens.file() + ":" + std::to_string(t.line) +
                                                         ": unknown coordinate system '" + name + "' ignored");
        else
          state_.ctm = found->second;
      } else if (d == "ActiveTransform") {
        PbrtToken which = tokens.next();
        activeEndOnly_ = which.text == "EndTime";
        if (which.text != "All") context_.warn("motion", "motion blur is not rendered: the start transforms are used");
      } else if (d == "TransformTimes") {
        readNumbers(tokens, 2, d);
      } else if (d == "ReverseOrientation") {
        state_.reverseOrientation = !state_.reverseOrientation;
      } else if (d == "AttributeBegin" || d == "TransformBegin") {
        if (stack_.size() >= kMaxAttributeDepth) fail(tokens, t.line, d + " nested too deep");
        stack_.push_back({state_, d == "TransformBegin"});
        if (recording_) recording_->saved.push_back(recording_->relative);
      } else if (d == "AttributeEnd" || d == "TransformEnd") {
        if (stack_.empty()) fail(tokens, t.line, d + " without a matching begin");
        auto [saved, transformOnly] = stack_.back();
        stack_.pop_back();
        if (recording_ && recording_->saved.empty()) recording_->reusable = false;  // closes a block of the includer
        if (recording_ && !recording_->saved.empty()) {
          recording_->relative = recording_->saved.back();
          recording_->saved.pop_back();
        }
        if (transformOnly)
          state_.ctm = saved.ctm;
        else
          state_ = saved;
      } else if (d == "Attribute") {
        readString(tokens, d);
        parsePbrtParameters(tokens);
        context_.warn("Attribute", "'Attribute' defaults for shapes, lights and materials are not applied");
      } else if (d == "Option" || d == "ColorSpace" || d == "Accelerator") {
        if (d == "Option") {
          PbrtToken name = tokens.next();
          if (name.kind == PbrtToken::Kind::String && name.text.find(' ') != std::string::npos) tokens.next();
        } else {
          std::string name = readString(tokens, d);
          if (d == "ColorSpace" && name != "srgb")
            context_.warn("color space", "colour space '" + name + "' is read as sRGB");
          parsePbrtParameters(tokens);
        }
      } else if (d == "Camera") {
        cameraType_ = readString(tokens, d);
        camera_ = parsePbrtParameters(tokens);
        camera_->line = t.line;  // the camera's errors name the directive's line, also when it has no parameters
        cameraFromWorld_ = state_.ctm;
        cameraMedium_ = state_.media.outside;
        // As in every pbrt, "camera" names the camera's frame in the world: what is placed in it after
        // CoordSysTransform "camera" moves with the camera (a headlight).
        glm::mat4 worldFromCamera = glm::inverse(state_.ctm);
        if (!isFiniteMatrix(worldFromCamera))
          fail(tokens, t.line, "Camera: the CTM at the Camera directive is not invertible");
        namedFrames_["camera"] = worldFromCamera;
      } else if (d == "Film") {
        std::string type = readString(tokens, d);
        film_ = parsePbrtParameters(tokens);
        if (type == "spectral") context_.warn("spectral film", "the spectral film is rendered as an RGB film");
      } else if (d == "Sampler") {
        readString(tokens, d);
        PbrtParameters p = parsePbrtParameters(tokens);
        int samples = p.getInt("pixelsamples", 16);
        if (samples > 0) samplerSamples_ = uint32_t(std::min(samples, 1 << 24));
      } else if (d == "Integrator") {
        std::string type = readString(tokens, d);
        PbrtParameters p = parsePbrtParameters(tokens);
        maxDepth_ = uint32_t(std::clamp(p.getInt("maxdepth", 5), 1, 1024));
        if (type != "path" && type != "volpath")
          context_.warn("integrator", "integrator '" + type + "' is rendered with candela's path tracer");
      } else if (d == "PixelFilter") {
        readString(tokens, d);
        parsePbrtParameters(tokens);
        context_.warn("pixel filter", "the pixel filter is noted but candela's own is used (docs/pbrt-v4.md)");
      } else if (d == "MakeNamedMedium") {
        std::string name = readString(tokens, d);
        PbrtParameters params = readParametersWithSpectra(tokens);
        media_.define(name, params, worldFromPbrt_ * state_.ctm);
        context_.warnUnused("medium '" + params.getString("type", "") + "'", params);
      } else if (d == "MediumInterface") {
        // One name: the same medium on both sides; two: inside, then outside.
        std::string inside = readString(tokens, d);
        std::string outside = tokens.peek().kind == PbrtToken::Kind::String ? readString(tokens, d) : inside;
        state_.media = {media_.slot(inside, tokens.file(), t.line), media_.slot(outside, tokens.file(), t.line)};
      } else if (d == "WorldBegin") {
        state_.ctm = glm::mat4(1.0f);
        namedFrames_["world"] = state_.ctm;
        if (!worldBegun_) chooseWorldMirror();
        worldBegun_ = true;
      } else if (d == "WorldEnd") {
        // pbrt-v3's end of the scene; pbrt-v4 reads to the end of the file.
      } else if (d == "Include" || d == "Import") {
        std::string file = readString(tokens, d);
        if (textOnly_) fail(tokens, t.line, d + " of '" + file + "' in a scene read from memory");
        include(context_.resolve(file, tokens.file(), t.line), depth + 1);
        ++curveRun_;  // its curves and those after it are placed apart (an Include may be placed again)
      } else if (d == "Texture") {
        std::string name = readString(tokens, d), valueType = readString(tokens, d), className = readString(tokens, d);
        PbrtParameters params = readParametersWithSpectra(tokens);
        textures_.define(name, valueType, className, params);  // its parameters are checked when it is used
      } else if (d == "Material") {
        std::string type = readString(tokens, d);
        PbrtParameters params = readParametersWithSpectra(tokens);
        state_.material = materials_.make(type, params);
        state_.materialName.clear();
        context_.warnUnused("material '" + type + "'", params);
      } else if (d == "MakeNamedMaterial") {
        std::string name = readString(tokens, d);
        PbrtParameters params = readParametersWithSpectra(tokens);
        materials_.defineNamed(name, params);
        context_.warnUnused("material '" + params.getString("type", "") + "'", params);
      } else if (d == "NamedMaterial") {
        std::string name = readString(tokens, d);
        state_.material.reset();
        state_.materialName = name;
        if (materials_.isNamed(name)) state_.material = materials_.named(name, tokens.file(), t.line);
      } else if (d == "LightSource") {
        std::string type = readString(tokens, d);
        PbrtParameters params = readParametersWithSpectra(tokens);
        readLight(type, params);
        context_.warnUnused("light '" + type + "'", params);
      } else if (d == "AreaLightSource") {
        std::string type = readString(tokens, d);
        PbrtParameters params = readParametersWithSpectra(tokens);
        state_.areaLight = makePbrtAreaLight(type, params, context_);
        context_.warnUnused("area light '" + type + "'", params);
      } else if (d == "Shape") {
        std::string type = readString(tokens, d);
        PbrtParameters params = parsePbrtParameters(tokens);
        readShape(type, params);
        context_.warnUnused("shape '" + type + "'", params);
      } else if (d == "ObjectBegin") {
        if (currentObject_) fail(tokens, t.line, "ObjectBegin inside the definition of '" + *currentObject_ + "'");
        if (stack_.size() >= kMaxAttributeDepth) fail(tokens, t.line, d + " nested too deep");
        stack_.push_back({state_, false});
        currentObject_ = readString(tokens, d);
        objects_[*currentObject_].clear();
      } else if (d == "ObjectEnd") {
        if (!currentObject_) fail(tokens, t.line, "ObjectEnd without ObjectBegin");
        currentObject_.reset();
        if (!stack_.empty()) {
          state_ = stack_.back().first;
          stack_.pop_back();
        }
      } else if (d == "ObjectInstance") {
        std::string name = readString(tokens, d);
        instantiate(name, tokens, t.line);
      } else {
        fail(tokens, t.line, "unknown directive '" + d + "'");
      }
    }
  }

  void readLight(const std::string& type, const PbrtParameters& params) {
    if (!worldBegun_) chooseWorldMirror();
    if (type == "point" || type == "spot" || type == "distant") {
      context_.scene.punctualLights.push_back(makePbrtPunctualLight(type, params, worldFromPbrt_ * state_.ctm));
      return;
    }
    if (type != "infinite") {
      params.markAllUsed();
      context_.warn("light " + type, "'" + type + "' lights are not supported: left out");
      return;
    }
    if (environmentSet_) context_.warn("several infinite lights", "only the first infinite light is used");
    if (environmentSet_) return;
    context_.scene.environment = makePbrtInfiniteLight(params, state_.ctm, mirrorX_, context_);
    environmentSet_ = true;
  }

  AlphaSpec shapeAlpha(const PbrtParameters& params) {
    AlphaSpec alpha;
    if (std::optional<std::string> texture = params.getTexture("alpha")) {
      PbrtParameters lookup = params;
      PbrtTexture t = textures_.value(lookup, "alpha", {1, 1, 1});
      alpha.value = t.factor.x;
      alpha.texture = t.image;
    } else {
      alpha.value = std::clamp(params.getFloat("alpha", 1.0f), 0.0f, 1.0f);
    }
    return alpha;
  }

  // The material a shape's triangles use: `base` with the shape's emission and alpha (cached: many shapes share
  // one light or cut-out).
  // `singleSided`: the variant's back faces are not there for rays (a two-sided light's two copies, below).
  uint32_t variant(uint32_t base, Vec3 emission, AlphaSpec alpha, bool singleSided) {
    // Not-a-number (from infinite areas or radiance in a hostile file) would break the ordering of the cache's
    // keys; it emits nothing, and scene repair clamps what is too bright.
    for (float* c : {&emission.x, &emission.y, &emission.z})
      if (std::isnan(*c)) *c = 0.0f;
    if (isBlack(emission) && alpha.value >= 1.0f && alpha.texture == kNoTexture) return base;
    auto key = std::make_tuple(base, emission.x, emission.y, emission.z, alpha.value, alpha.texture, singleSided);
    auto found = variants_.find(key);
    if (found != variants_.end()) return found->second;
    Material m = context_.scene.materials[base];
    m.emission = emission;
    if (singleSided) m.doubleSided = 0;
    if (alpha.value < 1.0f || alpha.texture != kNoTexture) {
      m.alphaMode = AlphaMode::Blend;  // pbrt-v4 lets rays through with probability 1 - alpha
      m.opacity *= alpha.value;
      m.opacityTexture = alpha.texture;
    }
    uint32_t id = uint32_t(context_.scene.materials.size());
    context_.scene.materials.push_back(m);
    context_.scene.materialNames.push_back(context_.scene.materialNames[base]);
    variants_[key] = id;
    materials_.noteVariant(base, id);
    return id;
  }

  // The radiance each triangle of a shape emits. With `power`, pbrt-v4 normalises each of its lights: one per
  // triangle of a mesh, per patch of a bilinear mesh (two triangles here), one for a whole quadric.
  static std::vector<Vec3> areaLightEmission(const PbrtAreaLight& light, const std::string& type, const Mesh& mesh,
                                             const Affine3x4& toWorld) {
    size_t triangles = mesh.triangleCount();
    if (!(light.power > 0.0f)) return std::vector<Vec3>(triangles, light.radiance);
    std::vector<float> area(triangles);
    for (size_t t = 0; t < triangles; ++t) {
      Vec3 a = toWorld.point(mesh.positions[mesh.indices[3 * t]]);
      Vec3 b = toWorld.point(mesh.positions[mesh.indices[3 * t + 1]]);
      Vec3 c = toWorld.point(mesh.positions[mesh.indices[3 * t + 2]]);
      area[t] = 0.5f * length(cross(b - a, c - a));
    }
    std::vector<Vec3> emission(triangles);
    size_t group = type == "bilinearmesh" ? 2 : 1;
    if (type == "sphere" || type == "disk" || type == "cylinder") group = std::max<size_t>(triangles, 1);
    for (size_t first = 0; first < triangles; first += group) {
      size_t last = std::min(first + group, triangles);
      float shapeArea = 0.0f;
      for (size_t t = first; t < last; ++t) shapeArea += area[t];
      for (size_t t = first; t < last; ++t) emission[t] = pbrtAreaLightRadiance(light, shapeArea);
    }
    return emission;
  }

  void readShape(const std::string& type, const PbrtParameters& params) {
    if (!worldBegun_) chooseWorldMirror();
    noteLoadProgress(params.file + ":" + std::to_string(params.line), "shape '" + type + "'");
    if (!state_.material && !state_.materialName.empty() && materials_.isNamed(state_.materialName))
      state_.material = materials_.named(state_.materialName, params.file, params.line);
    if (type == "curve") return readCurve(params);
    // A shape equal to one made before shares its mesh, unless it emits: its emission depends on where it is.
    std::optional<PbrtShapeKey> key;
    if (!state_.areaLight) key = pbrtShapeKey(type, params);
    std::optional<SharedShapeKey> sharedKey;
    if (key) {
      sharedKey = SharedShapeKey{key->key, state_.reverseOrientation, materialKey(), state_.materialName};
      if (auto found = sharedMeshes_.find(*sharedKey); found != sharedMeshes_.end()) {
        params.markAllUsed();
        placeMesh(found->second, key->shapeFromMesh, params.file, params.line);
        return;
      }
    }
    PbrtShapeInputs inputs{[&](const std::string& ref) { return context_.resolve(ref, params.file, params.line); },
                           [&](const std::string& feature, const std::string& what) { context_.warn(feature, what); }};
    std::optional<Mesh> shape = makePbrtShape(type, key && key->unitShape ? key->unitParams : params, inputs);
    if (!shape) {
      params.markAllUsed();
      return;
    }
    Mesh& mesh = *shape;
    chargeLoadMemory(meshBytes(mesh), params.file + ":" + std::to_string(params.line),
                     "shape '" + type + "' of " + std::to_string(mesh.triangleCount()) + " triangles");
    if (type == "sphere" || type == "disk" || type == "cylinder" || type == "loopsubdiv") {
      generatedTriangles_ += mesh.triangleCount();
      if (generatedTriangles_ > kMaxGeneratedTriangles)
        failLoad(params.file, params.line,
                 "the scene's quadrics and subdivision surfaces make more than " +
                     std::to_string(kMaxGeneratedTriangles) + " triangles");
    }
    mesh.name = "pbrt " + type;
    // Orientation: the front of a shape follows its normals when it has them, else its winding; each
    // negated by ReverseOrientation (pbrt-v4's rule; candela's instances keep the object-space front).
    if (state_.reverseOrientation) {
      for (Vec3& n : mesh.normals) n = -n;
      if (mesh.normals.empty())
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    }
    windTrianglesAlongNormals(mesh);

    AlphaSpec alpha = shapeAlpha(params);
    Affine3x4 toWorld = toAffine(worldFromPbrt_ * state_.ctm);
    std::vector<Vec3> emission;  // per triangle; empty when the shape does not emit
    if (state_.areaLight && !currentObject_) {
      emission = areaLightEmission(*state_.areaLight, type, mesh, toWorld);
    } else if (state_.areaLight) {
      context_.warn("area light instance", "area lights inside object definitions do not emit (as in pbrt-v4)");
    }
    size_t triangles = mesh.triangleCount();
    // A two-sided light is its triangles twice, the second copy wound the other way, each emitting from its front
    // (so light sampling needs nothing of its own). Each copy's back faces are culled: a ray meets exactly the
    // copy that faces it, whichever of two coincident triangles its backend's traversal reports first.
    const bool twoSidedLight = state_.areaLight && state_.areaLight->twoSided && !currentObject_;
    if (twoSidedLight) {
      for (size_t i = 0; i < 3 * triangles; i += 3)
        mesh.indices.insert(mesh.indices.end(), {mesh.indices[i], mesh.indices[i + 2], mesh.indices[i + 1]});
      mesh.triangleMaterials.resize(2 * triangles);
    }
    uint32_t pendingMesh = uint32_t(context_.scene.meshes.size());
    if (state_.material || state_.materialName.empty()) {
      assignMaterials(mesh, state_.material ? *state_.material : materials_.fallback(), emission, alpha, triangles,
                      twoSidedLight);
    } else {
      pendingShapes_.push_back({pendingMesh, state_.materialName, std::move(emission), alpha, triangles, twoSidedLight,
                                params.file, params.line});
    }
    uint32_t meshId = uint32_t(context_.scene.meshes.size());
    context_.scene.meshes.push_back(std::move(mesh));
    if (sharedKey) sharedMeshes_.emplace(*sharedKey, meshId);
    placeMesh(meshId, key ? key->shapeFromMesh : glm::mat4(1.0f), params.file, params.line);
  }

  // A curve shape. Hair files hold hundreds of thousands of them, one directive each: a run of curves of one type
  // with no other directive between them (so in the same transform, material, media and object) goes into one
  // mesh of curves, placed once.
  void readCurve(const PbrtParameters& params) {
    chargeLoadMemory(pbrtCurveBytes(params), params.file + ":" + std::to_string(params.line), "shape 'curve'");
    PbrtCurve curve = makePbrtCurve(params);
    if (state_.areaLight)
      context_.warn("curve area light", "curves do not emit light (pbrt-v4 cannot sample them either): left dark");
    if (state_.reverseOrientation)
      for (Vec3& n : curve.normals) n = -n;
    if (!openCurves_ || openCurves_->run != curveRun_ || openCurves_->type != curve.type) {
      const uint32_t meshId = uint32_t(context_.scene.meshes.size());
      Mesh mesh;
      mesh.name = "pbrt curves";
      context_.scene.meshes.push_back(std::move(mesh));
      if (!state_.material && !state_.materialName.empty())
        pendingShapes_.push_back({meshId, state_.materialName, {}, AlphaSpec{}, 0, false, params.file, params.line});
      openCurves_ = OpenCurves{curveRun_, curve.type, meshId};
      placeMesh(meshId, glm::mat4(1.0f), params.file, params.line);
    }
    Mesh& mesh = context_.scene.meshes[openCurves_->meshId];
    const uint32_t material = state_.material               ? state_.material->id
                              : state_.materialName.empty() ? materials_.fallback().id
                                                            : 0;  // assigned once the name is made
    for (size_t v = 0; v < curve.vertices.size(); v += kCurveControlPoints)
      mesh.curveSegments.push_back({uint32_t(mesh.curveVertices.size() + v), material, curve.type});
    mesh.curveVertices.insert(mesh.curveVertices.end(), curve.vertices.begin(), curve.vertices.end());
    mesh.curveNormals.insert(mesh.curveNormals.end(), curve.normals.begin(), curve.normals.end());
    // pbrt-v4 splits curves this many times for its own intersector; Embree and OptiX take whole segments. Read,
    // so that it is not reported as left out.
    params.getInt("splitdepth", 3);
  }

  // A shape's mesh, `shapeFromMesh` in the current transform, recorded for an Include being read.
  void placeMesh(uint32_t meshId, const glm::mat4& shapeFromMesh, const std::string& file, size_t line) {
    if (recording_) recording_->shapes.push_back({meshId, recording_->relative * shapeFromMesh});
    putMesh(meshId, state_.ctm * shapeFromMesh, file, line);
  }

  // A mesh where `ctm` puts it: in the object being defined, or in the scene.
  void putMesh(uint32_t meshId, const glm::mat4& ctm, const std::string& file, size_t line) {
    if (currentObject_)
      objects_[*currentObject_].push_back({meshId, ctm, state_.media});
    else
      addInstance(meshId, toAffine(worldFromPbrt_ * ctm), state_.media, file, line);
  }

  // The materials of a shape's `triangles` (and of their reversed copies after them, for two-sided lights), with
  // its emission and alpha, and its texture coordinates through the material's uv mapping.
  void assignMaterials(Mesh& mesh, const PbrtMaterial& material, const std::vector<Vec3>& emission, AlphaSpec alpha,
                       size_t triangles, bool twoSidedLight) {
    for (size_t t = 0; t < triangles; ++t)
      mesh.triangleMaterials[t] =
          variant(material.id, emission.empty() ? Vec3{0, 0, 0} : emission[t], alpha, twoSidedLight);
    for (size_t t = triangles; t < mesh.triangleMaterials.size(); ++t)
      mesh.triangleMaterials[t] = mesh.triangleMaterials[t - triangles];
    for (CurveSegment& segment : mesh.curveSegments) segment.material = material.id;
    // pbrt's (u, v) through the base colour texture's mapping, then v flipped: candela's v runs down the image.
    auto [scale, offset] = materials_.uvMapping(material.id);
    for (Vec2& uv : mesh.uvs) uv = {scale.x * uv.x + offset.x, 1.0f - (scale.y * uv.y + offset.y)};
  }

  // Shapes whose NamedMaterial was made only after them (pbrt-v4 allows that): materials assigned at the end.
  void assignPendingMaterials() {
    for (PendingShape& p : pendingShapes_)
      assignMaterials(context_.scene.meshes[p.meshId], materials_.named(p.materialName, p.file, p.line), p.emission,
                      p.alpha, p.triangles, p.twoSidedLight);
    pendingShapes_.clear();
  }

  // `media` holds medium slots (PbrtMedia), which placeMedia turns into indices once the scene is read.
  void addInstance(uint32_t meshId, const Affine3x4& toWorld, MediumInterface media, const std::string& file,
                   size_t line) {
    if (context_.scene.instances.size() >= kMaxInstances)
      failLoad(file, line, "more than " + std::to_string(kMaxInstances) + " shape instances");
    context_.scene.instances.push_back({meshId, toWorld, media});
  }

  // The media into the scene, and the instances' and the camera's medium slots into indices of them.
  void placeMedia(Scene& scene) {
    const std::vector<uint32_t> index = media_.finish(scene);
    auto place = [&](uint32_t& slot) { slot = slot == kNoMedium ? kNoMedium : index[slot]; };
    for (Instance& instance : scene.instances) {
      place(instance.media.inside);
      place(instance.media.outside);
    }
    scene.cameraMedium = cameraMedium_;
    place(scene.cameraMedium);
    placeSubsurfaceInteriors(scene);
  }

  // The medium inside each shape of a `subsurface` material (PbrtMaterials::interior), one per material: its
  // instances' inside, the side its surfaces face away from. What a MediumInterface put inside gives way to it.
  void placeSubsurfaceInteriors(Scene& scene) {
    std::map<uint32_t, uint32_t> mediumOfMaterial;
    for (Instance& instance : scene.instances) {
      const std::vector<uint32_t>& materials = scene.meshes[instance.meshId].triangleMaterials;
      const Medium* interior = materials.empty() ? nullptr : materials_.interior(materials[0]);
      if (!interior) continue;
      auto [found, added] = mediumOfMaterial.try_emplace(materials[0], uint32_t(scene.media.size()));
      if (added) scene.media.push_back(*interior);
      if (instance.media.inside != instance.media.outside && instance.media.inside != kNoMedium)
        context_.warn("subsurface inside a medium interface",
                      "a subsurface shape's MediumInterface 'inside' gives way to the material's own medium");
      instance.media.inside = found->second;
    }
  }

  void instantiate(const std::string& name, PbrtTokenizer& tokens, size_t line) {
    if (currentObject_) fail(tokens, line, "ObjectInstance inside an object definition");
    if (!worldBegun_) chooseWorldMirror();
    auto found = objects_.find(name);
    if (found == objects_.end()) {
      context_.warn("unknown object " + name,
                    tokens.file() + ":" + std::to_string(line) + ": object '" + name + "' is not defined: left out");
      return;
    }
    for (const ObjectShape& shape : found->second)
      addInstance(shape.meshId, toAffine(worldFromPbrt_ * state_.ctm * shape.worldFromShape), shape.media,
                  tokens.file(), line);
  }

  PbrtContext context_;
  PbrtTextures textures_;
  PbrtMaterials materials_;
  PbrtMedia media_;
  GraphicsState state_;
  std::vector<std::pair<GraphicsState, bool>> stack_;  // saved state, and whether only its transform returns
  std::map<std::string, glm::mat4> namedFrames_;
  std::map<std::string, std::vector<ObjectShape>> objects_;
  std::optional<std::string> currentObject_;
  std::vector<PendingShape> pendingShapes_;
  std::map<SharedShapeKey, uint32_t> sharedMeshes_;
  // The mesh the curves of the current run go into (readCurve); a run ends at any directive but Shape.
  struct OpenCurves {
    uint64_t run = 0;
    CurveType type = CurveType::Flat;
    uint32_t meshId = 0;
  };
  uint64_t curveRun_ = 0;
  std::optional<OpenCurves> openCurves_;
  std::optional<IncludeRecording> recording_;  // while an included file is read for the first time
  std::map<IncludeKey, IncludeRecording> includes_;
  std::map<std::tuple<uint32_t, float, float, float, float, int32_t, bool>, uint32_t> variants_;
  std::optional<PbrtParameters> camera_, film_;
  std::string cameraType_;
  glm::mat4 cameraFromWorld_{1.0f};
  uint32_t cameraMedium_ = kNoMedium;  // a slot of media_
  std::optional<uint32_t> samplerSamples_;
  uint32_t maxDepth_ = 5;
  bool worldBegun_ = false, mirrorX_ = true, activeEndOnly_ = false, environmentSet_ = false, textOnly_ = false;
  glm::mat4 worldFromPbrt_{1.0f};
  size_t includedFiles_ = 0;
  size_t generatedTriangles_ = 0;
};

}  // namespace

Scene loadPbrt(const std::string& path, LoadWarnings& warnings, OutsidePaths outside) {
  PbrtReader reader(path, warnings, outside);
  reader.readFile(path, 0);
  return reader.finish();
}

Scene loadPbrtText(const std::string& name, const std::string& text, LoadWarnings& warnings) {
  PbrtReader reader(name, warnings, OutsidePaths::Refused);
  reader.readText(name, text);
  return reader.finish();
}

}  // namespace candela
