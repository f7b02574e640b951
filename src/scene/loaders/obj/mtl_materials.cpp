#include "scene/loaders/obj/mtl_materials.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace candela {

namespace {

Vec3 rgb(const tinyobj::real_t (&c)[3]) { return {float(c[0]), float(c[1]), float(c[2])}; }

bool isPbr(const tinyobj::material_t& m) {
  return m.roughness > 0 || m.metallic > 0 || m.sheen > 0 || m.clearcoat_thickness > 0 || m.clearcoat_roughness > 0 ||
         m.anisotropy > 0 || !m.roughness_texname.empty() || !m.metallic_texname.empty() || !m.sheen_texname.empty();
}

bool hasTransform(const tinyobj::texture_option_t& o) {
  return o.origin_offset[0] != 0 || o.origin_offset[1] != 0 || o.scale[0] != 1 || o.scale[1] != 1;
}

class TextureSlots {
 public:
  TextureSlots(const tinyobj::material_t& mtl, const std::string& mtlFile, const std::string& directory,
               const PathRule& files, TextureTable& textures, LoadWarnings& warnings)
      : mtl_(mtl), mtlFile_(mtlFile), directory_(directory), files_(files), textures_(textures), warnings_(warnings) {}

  int32_t use(const std::string& name, const tinyobj::texture_option_t& options, bool srgb, const char* statement) {
    if (name.empty()) return kNoTexture;
    if (hasTransform(options)) warn(std::string(statement) + " has an -o/-s texture transform, which is ignored");
    std::string file = name;
    std::replace(file.begin(), file.end(), '\\', '/');
    std::filesystem::path path =
        std::filesystem::path(file).is_absolute() ? std::filesystem::path(file) : directory_ / file;
    TextureWrap wrap = options.clamp ? TextureWrap::Clamp : TextureWrap::Repeat;
    return textures_.fromFile(confineModelPath(path.lexically_normal().string(), files_), srgb, wrap, wrap);
  }

  void ignore(const std::string& name, const std::string& why) {
    if (!name.empty()) warn(why);
  }

 private:
  void warn(const std::string& what) { warnings_.add(mtlFile_, "material '" + mtl_.name + "': " + what); }

  const tinyobj::material_t& mtl_;
  const std::string& mtlFile_;
  std::filesystem::path directory_;
  const PathRule& files_;
  TextureTable& textures_;
  LoadWarnings& warnings_;
};

}  // namespace

Material materialFromMtl(const tinyobj::material_t& mtl, const std::string& mtlFile,
                         const std::string& textureDirectory, const PathRule& files, TextureTable& textures,
                         LoadWarnings& warnings) {
  Material m;
  TextureSlots slots(mtl, mtlFile, textureDirectory, files, textures, warnings);
  Vec3 kd = rgb(mtl.diffuse), ks = rgb(mtl.specular), tf = rgb(mtl.transmittance);
  m.baseColor = kd;
  m.emission = rgb(mtl.emission);
  m.specularColor = ks;
  m.shininess = std::max(float(mtl.shininess), 0.0f);
  m.ior = mtl.ior > 1.0f ? float(mtl.ior) : 1.5f;

  switch (mtl.illum) {
    case 3:
    case 5:
      m.type = MaterialType::Mirror;
      if (isBlack(ks)) m.specularColor = {1, 1, 1};
      break;
    case 4:
    case 6:
    case 7:
      m.type = MaterialType::Glass;
      m.baseColor = isBlack(tf) ? Vec3{1, 1, 1} : tf;
      break;
    default:
      if (isPbr(mtl)) {
        m.type = MaterialType::Disney;
        m.roughness = std::clamp(float(mtl.roughness), 0.0f, 1.0f);
        m.metallic = std::clamp(float(mtl.metallic), 0.0f, 1.0f);
        m.sheen = std::max(float(mtl.sheen), 0.0f);
        m.clearcoat = std::max(float(mtl.clearcoat_thickness), 0.0f);
        m.clearcoatGloss = 1.0f - std::clamp(float(mtl.clearcoat_roughness), 0.0f, 1.0f);
        m.anisotropic = std::clamp(float(mtl.anisotropy), 0.0f, 1.0f);
      } else if (!isBlack(ks)) {
        m.type = MaterialType::BlinnPhong;
      } else {
        m.type = MaterialType::Diffuse;
      }
  }

  float dissolve = std::clamp(float(mtl.dissolve), 0.0f, 1.0f);
  if (dissolve < 1.0f) {
    m.alphaMode = AlphaMode::Blend;
    m.opacity = dissolve;
  }
  m.baseColorTexture = slots.use(mtl.diffuse_texname, mtl.diffuse_texopt, true, "map_Kd");
  m.emissionTexture = slots.use(mtl.emissive_texname, mtl.emissive_texopt, true, "map_Ke");
  m.opacityTexture = slots.use(mtl.alpha_texname, mtl.alpha_texopt, false, "map_d");
  if (m.opacityTexture != kNoTexture) m.alphaMode = AlphaMode::Mask;
  m.normalTexture = slots.use(mtl.normal_texname, mtl.normal_texopt, false, "norm");
  if (m.type == MaterialType::Disney) {
    m.roughnessTexture = slots.use(mtl.roughness_texname, mtl.roughness_texopt, false, "map_Pr");
    m.metallicTexture = slots.use(mtl.metallic_texname, mtl.metallic_texopt, false, "map_Pm");
    slots.ignore(mtl.sheen_texname, "map_Ps is ignored: the material model has no sheen texture");
  }
  slots.ignore(mtl.specular_texname, "map_Ks is ignored: the material model has no specular-colour texture");
  slots.ignore(mtl.specular_highlight_texname, "map_Ns is ignored: the material model has no shininess texture");
  slots.ignore(mtl.bump_texname, "bump height map is ignored: give a tangent-space normal map with 'norm'");
  if (!isFinite(m.baseColor) || !isFinite(m.emission) || !isFinite(m.specularColor) || !std::isfinite(m.shininess) ||
      !std::isfinite(m.ior))
    failLoad(mtlFile, "material '" + mtl.name + "' has a non-finite parameter");
  return m;
}

}  // namespace candela
