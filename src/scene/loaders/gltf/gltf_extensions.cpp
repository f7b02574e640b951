#include "scene/loaders/gltf/gltf_extensions.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <string_view>
#include <vector>

#include "scene/loaders/gltf/gltf_draco.h"
#include "scene/loaders/gltf/gltf_meshopt.h"

namespace candela {

namespace {

// Read fully or in part; where in part, the loader warns about what it leaves out.
constexpr std::array<std::string_view, 16> kSupported = {
    "EXT_mesh_gpu_instancing",  "EXT_texture_webp",          "KHR_lights_punctual",
    "KHR_materials_anisotropy", "KHR_materials_clearcoat",   "KHR_materials_emissive_strength",
    "KHR_materials_ior",        "KHR_materials_iridescence", "KHR_materials_pbrSpecularGlossiness",
    "KHR_materials_sheen",      "KHR_materials_specular",    "KHR_materials_transmission",
    "KHR_materials_unlit",      "KHR_materials_volume",      "KHR_mesh_quantization",
    "KHR_texture_transform"};

constexpr std::string_view kDraco = "KHR_draco_mesh_compression";  // where candela is built with Draco
constexpr std::string_view kMeshopt = "EXT_meshopt_compression";   // where candela is built with meshoptimizer
// Alternative materials a viewer may switch to; each primitive's `material` stays its default look, which is what
// candela renders. Blender lists the extension as required, though the file is complete without it.
constexpr std::string_view kVariants = "KHR_materials_variants";

bool contains(auto& list, const std::string& name) { return std::find(list.begin(), list.end(), name) != list.end(); }

bool supported(const std::string& name) {
  return contains(kSupported, name) || name == kVariants || (name == kDraco && gltfDracoAvailable()) ||
         (name == kMeshopt && gltfMeshoptAvailable());
}

void refuseUnsupported(const std::vector<std::string>& required, const std::string& file) {
  std::string refused;
  for (const std::string& name : required)
    if (!supported(name)) refused += (refused.empty() ? "" : ", ") + name;
  if (refused.empty()) return;
  const bool many = refused.find(',') != std::string::npos;
  if (refused == kMeshopt)
    failLoad(file, "requires the glTF extension " + refused +
                       ", which this build of candela does not support: it was built without meshoptimizer (install "
                       "libmeshoptimizer-dev and configure again)");
  if (refused == kDraco)
    failLoad(file, "requires the glTF extension " + refused +
                       ", which this build of candela does not support: it was built without Draco (install "
                       "libdraco-dev and configure again)");
  failLoad(file, "requires the glTF extension" + std::string(many ? "s " : " ") + refused +
                     ", which candela does not support");
}

}  // namespace

void refuseUnsupportedRequiredExtensions(const char* json, size_t size, const std::string& file) {
  nlohmann::json doc = nlohmann::json::parse(json, json + size, nullptr, false);
  if (!doc.is_object() || !doc.contains("extensionsRequired") || !doc["extensionsRequired"].is_array()) return;
  std::vector<std::string> required;
  for (const auto& name : doc["extensionsRequired"])
    if (name.is_string()) required.push_back(name.get<std::string>());
  refuseUnsupported(required, file);
}

void checkGltfExtensions(const tinygltf::Model& model, const std::string& file, LoadWarnings& warnings) {
  refuseUnsupported(model.extensionsRequired, file);
  for (const std::string& name : model.extensionsUsed)
    if (!supported(name))
      warnings.add(file, "uses the glTF extension " + name + ", which candela does not support; it is ignored");
    else if (name == kVariants)
      warnings.add(file, "uses the glTF extension " + name + ": each primitive's default material is rendered");
}

int textureImageIndex(const tinygltf::Texture& texture) {
  const auto webp = texture.extensions.find("EXT_texture_webp");
  if (webp != texture.extensions.end() && webp->second.Has("source") && webp->second.Get("source").IsInt())
    return webp->second.Get("source").GetNumberAsInt();
  return texture.source;
}

}  // namespace candela
