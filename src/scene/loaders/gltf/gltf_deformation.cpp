#include "scene/loaders/gltf/gltf_deformation.h"

#include <cmath>
#include <map>

namespace candela {

namespace {

std::string primitiveWhere(int mesh, size_t primitive) {
  return "meshes[" + std::to_string(mesh) + "].primitives[" + std::to_string(primitive) + "]";
}

int attributeOf(const std::map<std::string, int>& attributes, const char* name) {
  auto it = attributes.find(name);
  return it == attributes.end() ? -1 : it->second;
}

// Reads an attribute of each primitive once, for gathering it by vertex origin.
template <class T, class Read>
class PerPrimitive {
 public:
  explicit PerPrimitive(Read read) : read_(std::move(read)) {}
  // The attribute of `primitive`, checked to have `count` elements (the primitive's vertices).
  const std::vector<T>& of(uint32_t primitive) {
    auto it = values_.find(primitive);
    if (it == values_.end()) it = values_.emplace(primitive, read_(primitive)).first;
    return it->second;
  }

 private:
  Read read_;
  std::map<uint32_t, std::vector<T>> values_;
};

template <class T, class Read>
PerPrimitive<T, Read> perPrimitive(Read read) {
  return PerPrimitive<T, Read>(std::move(read));
}

size_t vertexCount(const tinygltf::Model& model, const GltfAccessorReader& accessors, int mesh, size_t primitive) {
  const tinygltf::Primitive& p = model.meshes[size_t(mesh)].primitives[primitive];
  return accessors.count(attributeOf(p.attributes, "POSITION"),
                         primitiveWhere(mesh, primitive) + ".attributes.POSITION");
}

}  // namespace

void readGltfMorphTargets(const tinygltf::Model& model, const GltfAccessorReader& accessors, int mesh, int node,
                          const std::vector<GltfVertexOrigin>& origins, const std::string& file,
                          MeshDeformation& deformation) {
  const tinygltf::Mesh& source = model.meshes[size_t(mesh)];
  const size_t targets = source.primitives.empty() ? 0 : source.primitives[0].targets.size();
  bool anyNormalDeltas = false, anyTangentDeltas = false;
  for (size_t p = 0; p < source.primitives.size(); ++p) {
    if (source.primitives[p].targets.size() != targets)
      failLoad(file, primitiveWhere(mesh, p) + ".targets: " + std::to_string(source.primitives[p].targets.size()) +
                         " morph targets, but the mesh's first primitive has " + std::to_string(targets));
    for (const auto& target : source.primitives[p].targets) {
      anyNormalDeltas |= target.count("NORMAL") > 0;
      anyTangentDeltas |= target.count("TANGENT") > 0;
    }
  }
  const size_t n = origins.size();
  deformation.targetCount = uint32_t(targets);
  deformation.positionDeltas.assign(targets * n, Vec3{0, 0, 0});
  if (anyNormalDeltas && !deformation.normals.empty()) deformation.normalDeltas.assign(targets * n, Vec3{0, 0, 0});
  if (anyTangentDeltas && !deformation.tangents.empty()) deformation.tangentDeltas.assign(targets * n, Vec3{0, 0, 0});
  for (size_t t = 0; t < targets; ++t) {
    auto deltas = [&](const char* name) {
      return perPrimitive<Vec3>([&, name](uint32_t primitive) {
        const auto& target = source.primitives[primitive].targets[t];
        const int accessor = attributeOf(target, name);
        const size_t count = vertexCount(model, accessors, mesh, primitive);
        if (accessor < 0) return std::vector<Vec3>(count, Vec3{0, 0, 0});
        const std::string where = primitiveWhere(mesh, primitive) + ".targets[" + std::to_string(t) + "]." + name;
        std::vector<Vec3> values = accessors.readVec3(accessor, where);
        if (values.size() != count)
          failLoad(file, where + ": " + std::to_string(values.size()) + " elements for " + std::to_string(count) +
                             " positions");
        // A delta that is not finite would move its vertex to not-a-number at any weight but zero, which the
        // player cannot pose; it is refused as non-finite animation values are (gltf_animation.cpp).
        for (size_t k = 0; k < values.size(); ++k)
          if (!isFinite(values[k])) failLoad(file, where + ": value " + std::to_string(k) + " is not finite");
        return values;
      });
    };
    auto positions = deltas("POSITION");
    auto normals = deltas("NORMAL");
    auto tangents = deltas("TANGENT");
    for (size_t v = 0; v < n; ++v) {
      const GltfVertexOrigin o = origins[v];
      deformation.positionDeltas[t * n + v] = positions.of(o.primitive)[o.vertex];
      if (!deformation.normalDeltas.empty()) deformation.normalDeltas[t * n + v] = normals.of(o.primitive)[o.vertex];
      if (!deformation.tangentDeltas.empty()) deformation.tangentDeltas[t * n + v] = tangents.of(o.primitive)[o.vertex];
    }
  }
  const std::vector<double>& nodeWeights = model.nodes[size_t(node)].weights;
  const std::vector<double>& weights = nodeWeights.size() == targets ? nodeWeights : source.weights;
  deformation.weights.assign(targets, 0.0f);
  if (weights.size() == targets)
    for (size_t t = 0; t < targets; ++t) deformation.weights[t] = std::isfinite(weights[t]) ? float(weights[t]) : 0.0f;
}

bool readGltfSkinWeights(const tinygltf::Model& model, const GltfAccessorReader& accessors, int mesh, int skin,
                         const std::vector<GltfVertexOrigin>& origins, const std::string& file, LoadWarnings& warnings,
                         MeshDeformation& deformation) {
  const tinygltf::Mesh& source = model.meshes[size_t(mesh)];
  const size_t jointCount = model.skins[size_t(skin)].joints.size();
  auto hasSet = [](const std::map<std::string, int>& attributes, int set) {
    const std::string suffix = std::to_string(set);
    return attributeOf(attributes, ("JOINTS_" + suffix).c_str()) >= 0 &&
           attributeOf(attributes, ("WEIGHTS_" + suffix).c_str()) >= 0;
  };
  bool secondSet = false, moreSets = false;
  for (size_t p = 0; p < source.primitives.size(); ++p) {
    const auto& attributes = source.primitives[p].attributes;
    if (!hasSet(attributes, 0)) {
      warnings.add(file,
                   primitiveWhere(mesh, p) + " lacks JOINTS_0 or WEIGHTS_0; the skinned mesh is left in its bind pose");
      return false;
    }
    secondSet |= hasSet(attributes, 1);
    moreSets |= attributeOf(attributes, "JOINTS_2") >= 0;
  }
  // One set of four influences per vertex, or two where any primitive has JOINTS_1 and WEIGHTS_1 (the others' second
  // set is then unused).
  const uint32_t sets = secondSet ? 2 : 1;
  auto read = [&](const std::string& name) {
    return perPrimitive<Vec4>([&, name](uint32_t primitive) {
      const size_t count = vertexCount(model, accessors, mesh, primitive);
      const int accessor = attributeOf(source.primitives[primitive].attributes, name.c_str());
      if (accessor < 0) return std::vector<Vec4>(count, Vec4{0, 0, 0, 0});
      const std::string where = primitiveWhere(mesh, primitive) + ".attributes." + name;
      std::vector<Vec4> values = accessors.readVec4(accessor, where);
      if (values.size() != count)
        failLoad(file, where + ": " + std::to_string(values.size()) + " elements for " + std::to_string(count) +
                           " positions");
      return values;
    });
  };
  auto joints0 = read("JOINTS_0"), weights0 = read("WEIGHTS_0");
  auto joints1 = read("JOINTS_1"), weights1 = read("WEIGHTS_1");
  const size_t n = origins.size(), influences = 4 * sets;
  deformation.influences = uint32_t(influences);
  deformation.joints.resize(influences * n);
  deformation.jointWeights.resize(influences * n);
  for (size_t v = 0; v < n; ++v) {
    const GltfVertexOrigin o = origins[v];
    float js[8], ws[8];
    for (uint32_t set = 0; set < sets; ++set) {
      const bool secondOfPrimitive = set == 1 && hasSet(source.primitives[o.primitive].attributes, 1);
      const Vec4 j = set == 0            ? joints0.of(o.primitive)[o.vertex]
                     : secondOfPrimitive ? joints1.of(o.primitive)[o.vertex]
                                         : Vec4{0, 0, 0, 0};
      const Vec4 w = set == 0            ? weights0.of(o.primitive)[o.vertex]
                     : secondOfPrimitive ? weights1.of(o.primitive)[o.vertex]
                                         : Vec4{0, 0, 0, 0};
      const float jv[4] = {j.x, j.y, j.z, j.w}, wv[4] = {w.x, w.y, w.z, w.w};
      for (int k = 0; k < 4; ++k) {
        js[4 * set + k] = jv[k];
        ws[4 * set + k] = wv[k];
      }
    }
    float sum = 0.0f;
    auto used = [&](size_t k) {
      return js[k] >= 0.0f && js[k] < float(jointCount) && std::isfinite(ws[k]) && ws[k] > 0.0f;
    };
    for (size_t k = 0; k < influences; ++k) {
      // An unused slot may name any joint; only those with weight must exist.
      if (!(js[k] >= 0.0f && js[k] < float(jointCount)) && ws[k] != 0.0f)
        failLoad(file, primitiveWhere(mesh, o.primitive) + ".attributes.JOINTS_" + std::to_string(k / 4) + ": vertex " +
                           std::to_string(o.vertex) + " names joint " + std::to_string(js[k]) + " of a skin with " +
                           std::to_string(jointCount) + " joints");
      deformation.joints[influences * v + k] = used(k) ? uint32_t(js[k]) : 0u;
      sum += used(k) ? ws[k] : 0.0f;
    }
    // glTF's weights sum to one over all the vertex's influences; others are normalised, and a vertex without
    // weight follows the first joint.
    const bool weightless = !(sum > 0.0f) || !std::isfinite(sum);
    for (size_t k = 0; k < influences; ++k)
      deformation.jointWeights[influences * v + k] = weightless ? (k == 0 ? 1.0f : 0.0f) : used(k) ? ws[k] / sum : 0.0f;
  }
  if (moreSets)
    warnings.add(file, "meshes[" + std::to_string(mesh) +
                           "]: joints beyond the first eight per vertex (JOINTS_2 and later) are ignored");
  return true;
}

std::optional<Skin> readGltfSkin(const tinygltf::Model& model, const GltfAccessorReader& accessors, int skin,
                                 const std::vector<int32_t>& animationNodes, const std::string& file,
                                 LoadWarnings& warnings) {
  const std::string where = "skins[" + std::to_string(skin) + "]";
  const tinygltf::Skin& source = model.skins[size_t(skin)];
  Skin out;
  for (int joint : source.joints) {
    const int32_t node = joint >= 0 && size_t(joint) < animationNodes.size() ? animationNodes[size_t(joint)] : -1;
    if (node < 0) {
      warnings.add(file, where + ".joints: node " + std::to_string(joint) +
                             " is not in the scene; meshes with this skin are left in their bind pose");
      return std::nullopt;
    }
    out.joints.push_back(uint32_t(node));
  }
  out.inverseBinds.resize(out.joints.size());
  if (source.inverseBindMatrices >= 0) {
    const std::vector<float> m = accessors.readMatrices(source.inverseBindMatrices, where + ".inverseBindMatrices");
    if (m.size() < 16 * out.joints.size())
      failLoad(file, where + ".inverseBindMatrices: " + std::to_string(m.size() / 16) + " matrices for " +
                         std::to_string(out.joints.size()) + " joints");
    for (size_t j = 0; j < out.joints.size(); ++j)
      for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 4; ++col) {
          const float value = m[16 * j + size_t(4 * col + row)];  // column-major
          if (!std::isfinite(value))
            failLoad(file, where + ".inverseBindMatrices: matrix " + std::to_string(j) + " is not finite");
          out.inverseBinds[j].m[4 * row + col] = value;
        }
  }
  return out;
}

}  // namespace candela
