#include "scene/loaders/texture_table.h"

#include <tbb/parallel_for.h>
#include <exception>

#include <optional>

#include "io/file_bytes.h"
#include "io/images/image_decoding.h"
#include "io/load_budget.h"
#include "scene/loaders/texture_limits.h"

namespace candela {

int32_t TextureTable::add(const std::string& key, Request request) {
  auto [it, inserted] =
      index_.try_emplace({key, request.srgb, request.wrapU, request.wrapV}, int32_t(requests_.size()));
  if (inserted) requests_.push_back(std::move(request));
  return it->second;
}

int32_t TextureTable::fromFile(const ResolvedPath& file, bool srgb, TextureWrap wrapU, TextureWrap wrapV) {
  Request r;
  r.name = file.path;
  r.path = file.path;
  r.refusal = file.refusal;
  r.srgb = srgb;
  r.wrapU = wrapU;
  r.wrapV = wrapV;
  // A file one model may read and another may not (they lie in different folders) is two requests.
  return add((file.allowed() ? "file:" : "refused file:") + file.path, std::move(r));
}

int32_t TextureTable::fromMemory(const std::string& key, const std::string& name, std::vector<uint8_t> bytes, bool srgb,
                                 TextureWrap wrapU, TextureWrap wrapV) {
  Request r;
  r.name = name;
  r.bytes = std::move(bytes);
  r.srgb = srgb;
  r.wrapU = wrapU;
  r.wrapV = wrapV;
  return add("memory:" + key, std::move(r));
}

void TextureTable::finish(Scene& scene, size_t firstMaterial, LoadWarnings& warnings) {
  if (requests_.empty()) return;  // no material holds a provisional index
  // Headers first, so that the sizes to decode at are known before any pixel is: a texture over the limits
  // (texture_limits.h) is decoded smaller, never whole.
  std::vector<std::optional<ImageInfo>> infos(requests_.size());
  std::vector<std::string> failures(requests_.size());
  tbb::parallel_for(size_t(0), requests_.size(), [&](size_t i) {
    Request& r = requests_[i];
    try {
      if (!r.refusal.empty()) failLoad(r.path, r.refusal);
      if (!r.path.empty()) r.bytes = readFileBytes(r.path);
      infos[i] = inspectImage(r.name, r.bytes.data(), r.bytes.size());
    } catch (const LoadError& e) {
      failures[i] = e.what();
      r.bytes = {};
    }
  });
  std::vector<TextureExtent> extents;
  for (const std::optional<ImageInfo>& info : infos)
    if (info) extents.push_back({info->width, info->height, info->channels * (info->hdr ? 4u : 1u)});
  const TextureLimits limits = textureLimits();
  const std::vector<TextureExtent> fitted = fitTextureLimits(extents, limits);
  std::vector<TextureExtent> targets(requests_.size());
  for (size_t i = 0, k = 0; i < requests_.size(); ++i)
    if (infos[i]) {
      targets[i] = fitted[k];
      if (fitted[k].width != extents[k].width || fitted[k].height != extents[k].height)
        warnings.messages.push_back(downscaleWarning(requests_[i].name, extents[k], fitted[k], limits));
      ++k;
    }

  std::vector<std::optional<Texture>> decoded(requests_.size());
  std::vector<std::exception_ptr> overBudget(requests_.size());  // the load stops: no texture is left out for it
  tbb::parallel_for(size_t(0), requests_.size(), [&](size_t i) {
    Request& r = requests_[i];
    if (!infos[i]) return;
    try {
      decoded[i] = decodeImage(r.name, r.bytes.data(), r.bytes.size(), r.srgb, targets[i].width, targets[i].height);
      decoded[i]->wrapU = r.wrapU;
      decoded[i]->wrapV = r.wrapV;
    } catch (const LoadBudgetError&) {
      overBudget[i] = std::current_exception();
    } catch (const LoadError& e) {
      failures[i] = e.what();
    }
    r.bytes = {};
  });
  for (const std::exception_ptr& e : overBudget)
    if (e) std::rethrow_exception(e);

  std::vector<int32_t> finalIndex(requests_.size(), kNoTexture);
  for (size_t i = 0; i < requests_.size(); ++i) {
    if (!requests_[i].path.empty() && requests_[i].refusal.empty()) scene.inputFiles.push_back(requests_[i].path);
    if (!decoded[i]) {
      warnings.messages.push_back(failures[i] + " (the texture is left out)");
      continue;
    }
    finalIndex[i] = int32_t(scene.textures.size());
    scene.textures.push_back(std::move(*decoded[i]));
  }
  auto remap = [&](int32_t& t) {
    if (t != kNoTexture) t = finalIndex[size_t(t)];
  };
  for (size_t m = firstMaterial; m < scene.materials.size(); ++m) {
    Material& mat = scene.materials[m];
    for (int32_t* t : {&mat.baseColorTexture, &mat.metallicRoughnessTexture, &mat.roughnessTexture,
                       &mat.metallicTexture, &mat.emissionTexture, &mat.normalTexture, &mat.opacityTexture,
                       &mat.iridescenceTexture, &mat.iridescenceThicknessTexture})
      remap(*t);
  }
  requests_.clear();
  index_.clear();
}

}  // namespace candela
