#include "scene/loaders/pbrt/pbrt_textures.h"

#include <algorithm>
#include <cmath>

#include "core/file_extension.h"
#include "io/file_bytes.h"
#include "io/images/exr_decoding.h"
#include "io/images/image_decoding.h"
#include "io/load_budget.h"
#include "scene/loaders/pbrt/pbrt_pfm.h"
#include "scene/loaders/texture_limits.h"

namespace candela {

namespace {

Vec3 meanOf(const PbrtTexture& t) { return t.factor * (t.image == kNoTexture ? 1.0f : 0.5f); }

// Calls f(x, y, (u, v)) at the centre of each texel of a width x height image over pbrt's unit (u, v) square, row by
// row from the top (v runs up, the rows down): where a mix's bake and its mean both look at its inputs.
template <class F>
void forEachTexelCentre(uint32_t width, uint32_t height, F&& f) {
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x)
      f(x, y, Vec2{(float(x) + 0.5f) / float(width), 1.0f - (float(y) + 0.5f) / float(height)});
}

// The texel of `image` nearest to (s, t) in pbrt's texture space (t runs up, the image's rows down), as linear
// colour, wrapped as the image says.
Vec3 texelAt(const Texture& image, float s, float t) {
  auto index = [](float coordinate, uint32_t size, TextureWrap wrap) {
    float x = std::floor(coordinate * float(size));
    if (!std::isfinite(x)) return 0u;
    if (wrap == TextureWrap::Clamp) return uint32_t(std::clamp(x, 0.0f, float(size - 1)));
    const double period = double(size);
    return uint32_t(std::clamp(double(x) - period * std::floor(double(x) / period), 0.0, period - 1.0));
  };
  const uint32_t x = index(s, image.width, image.wrapU), y = index(1.0f - t, image.height, image.wrapV);
  const size_t at = (size_t(y) * image.width + x) * image.channels;
  float c[3];
  for (uint32_t k = 0; k < 3; ++k) {
    const uint32_t channel = image.channels >= 3 ? k : 0;
    float v = image.floats.empty() ? float(image.bytes[at + channel]) / 255.0f : image.floats[at + channel];
    c[k] = image.floats.empty() && image.srgb ? srgbToLinear(v) : v;
  }
  return {c[0], c[1], c[2]};
}

}  // namespace

Vec3 PbrtTextures::colourAt(const PbrtTexture& t, float u, float v) const {
  if (t.image == kNoTexture) return t.factor;
  const Texture& image = context_.scene.textures[size_t(t.image)];
  return t.factor * texelAt(image, t.uvScale.x * u + t.uvOffset.x, t.uvScale.y * v + t.uvOffset.y);
}

Vec3 PbrtTextures::colourAt(const Mix& mix, float u, float v) const {
  return lerp(colourAt(mix.amount, u, v).x, colourAt(mix.first, u, v), colourAt(mix.second, u, v));
}

int32_t PbrtTextures::mixedImage(const PbrtTexture& first, const PbrtTexture& second, const PbrtTexture& amount,
                                 const std::string& where, const std::string& name) {
  // A key of every number the image depends on; numbers that are not finite would break its ordering, and such a
  // mix is not shared.
  std::array<float, 24> key{};
  bool finite = true;
  size_t at = 0;
  for (const PbrtTexture* t : {&first, &second, &amount})
    for (float v : {t->factor.x, t->factor.y, t->factor.z, float(t->image), t->uvScale.x, t->uvScale.y, t->uvOffset.x,
                    t->uvOffset.y}) {
      finite = finite && std::isfinite(v);
      key[at++] = v;
    }
  if (auto found = finite ? mixes_.find(key) : mixes_.end(); found != mixes_.end()) return found->second;
  // As fine as the finest input over pbrt's unit square, each input's repetitions counted, within the texture
  // size limit (--max-texture-size) and 4096 texels a side.
  const float side = float(std::min<uint32_t>(4096, textureLimits().maxSize));
  uint32_t width = 1, height = 1;
  for (const PbrtTexture* t : {&first, &second, &amount}) {
    if (t->image == kNoTexture) continue;
    const Texture& image = context_.scene.textures[size_t(t->image)];
    width = std::max(width, uint32_t(std::min(side, std::ceil(float(image.width) * std::fabs(t->uvScale.x)))));
    height = std::max(height, uint32_t(std::min(side, std::ceil(float(image.height) * std::fabs(t->uvScale.y)))));
  }
  chargeLoadMemory(uint64_t(width) * height * 3 * sizeof(float), where,
                   "mix texture '" + name + "' baked at " + std::to_string(width) + "x" + std::to_string(height) +
                       " texels");
  Texture out;
  out.name = "mix texture";
  out.width = width;
  out.height = height;
  out.channels = 3;
  const int32_t index = int32_t(context_.scene.textures.size());
  context_.scene.textures.push_back(std::move(out));
  unbaked_[index] = Mix{first, second, amount};
  if (finite) mixes_[key] = index;
  return index;
}

void PbrtTextures::bakeThrough(int32_t image) {
  while (!unbaked_.empty() && unbaked_.begin()->first <= image) {
    auto node = unbaked_.extract(unbaked_.begin());
    Texture& out = context_.scene.textures[size_t(node.key())];
    std::visit([&](const auto& how) { bake(out, how); }, node.mapped());
  }
}

void PbrtTextures::bake(Texture& out, const Mix& mix) const {
  const uint32_t width = out.width, height = out.height;
  noteLoadProgress(context_.mainFile,
                   "baking a mix texture of " + std::to_string(width) + "x" + std::to_string(height) + " texels");
  std::vector<float> texels(size_t(width) * height * 3);
  forEachTexelCentre(width, height, [&](uint32_t x, uint32_t y, Vec2 uv) {
    const Vec3 c = colourAt(mix, uv.x, uv.y);
    float* texel = texels.data() + (size_t(y) * width + x) * 3;
    texel[0] = c.x;
    texel[1] = c.y;
    texel[2] = c.z;
  });
  out.floats = std::move(texels);
}

void PbrtTextures::bake(Texture& out, const Mapping& mapping) const {
  const Texture& source = context_.scene.textures[size_t(mapping.source)];
  const size_t pixels = size_t(source.width) * source.height;
  std::vector<float> texels(pixels);
  for (size_t i = 0; i < pixels; ++i) {
    const size_t at = i * source.channels;
    float v = source.floats.empty() ? float(source.bytes[at]) / 255.0f : source.floats[at];
    if (source.floats.empty() && source.srgb) v = srgbToLinear(v);
    texels[i] = mapping.map(v);
  }
  out.floats = std::move(texels);
}

int32_t PbrtTextures::loadImage(const std::string& path, bool srgb, const std::string& file, size_t line) {
  std::string resolved = context_.resolve(path, file, line);
  auto key = std::make_pair(resolved, srgb);
  if (auto found = images_.find(key); found != images_.end()) return found->second;
  int32_t index = kNoTexture;
  try {
    std::string ext = lowerCaseExtension(resolved);
    Texture image;
    if (ext == ".exr") {
      const TextureLimits limits = textureLimits();
      std::pair<uint32_t, uint32_t> inFile{0, 0};
      const std::vector<uint8_t> bytes = readFileBytes(resolved);
      image = decodeExr(resolved, bytes.data(), bytes.size(), UINT64_MAX, limits.maxSize, &inFile);
      const TextureExtent full{inFile.first, inFile.second, 3 * uint32_t(sizeof(float))};
      if (image.width != full.width || image.height != full.height)
        context_.warnings.add(context_.mainFile,
                              downscaleWarning(resolved, full, {image.width, image.height, full.bytesPerPixel},
                                               limits));
    } else if (ext == ".pfm") {
      const TextureLimits limits = textureLimits();
      TextureExtent full;
      image = readPfm(resolved, limits.maxSize, &full);
      const TextureExtent fitted{image.width, image.height, full.bytesPerPixel};
      if (fitted.width != full.width || fitted.height != full.height)
        context_.warnings.add(context_.mainFile, downscaleWarning(resolved, full, fitted, limits));
    } else {
      // Decoded no larger than the texture size limit, checked on the header: a small PNG can claim 16000x16000
      // pixels. The scene's memory limit applies once all its textures are read (fitSceneTextures).
      std::vector<uint8_t> bytes = readFileBytes(resolved);
      const ImageInfo info = inspectImage(resolved, bytes.data(), bytes.size());
      const TextureLimits limits = textureLimits();
      const TextureExtent full{info.width, info.height, info.channels * (info.hdr ? 4u : 1u)};
      const TextureExtent fitted = fitTextureLimits({full}, {limits.maxSize, UINT64_MAX}).front();
      if (fitted.width != full.width || fitted.height != full.height)
        context_.warnings.add(context_.mainFile, downscaleWarning(resolved, full, fitted, limits));
      image = decodeImage(resolved, bytes.data(), bytes.size(), srgb, fitted.width, fitted.height);
    }
    image.name = resolved;
    index = int32_t(context_.scene.textures.size());
    context_.scene.textures.push_back(std::move(image));
  } catch (const LoadBudgetError&) {
    throw;
  } catch (const LoadError& e) {
    context_.warnings.add(context_.mainFile, std::string("image left out: ") + e.what());
  }
  images_[key] = index;
  return index;
}

int32_t PbrtTextures::invertedImage(int32_t image) {
  if (auto found = inverted_.find(image); found != inverted_.end()) return found->second;
  const Texture& source = context_.scene.textures[size_t(image)];
  chargeLoadMemory(uint64_t(source.width) * source.height * source.channels * sizeof(float), source.name,
                   "its inverted copy");
  Texture out;
  out.name = source.name + " (inverted)";
  out.width = source.width;
  out.height = source.height;
  out.channels = source.channels;
  out.wrapU = source.wrapU;
  out.wrapV = source.wrapV;
  size_t values = size_t(source.width) * source.height * source.channels;
  out.floats.resize(values);
  for (size_t i = 0; i < values; ++i) {
    uint32_t channel = uint32_t(i % source.channels);
    bool alpha = (source.channels == 4 && channel == 3) || (source.channels == 2 && channel == 1);
    float v = source.floats.empty() ? float(source.bytes[i]) / 255.0f : source.floats[i];
    if (!source.floats.empty() || alpha || !source.srgb) {
      out.floats[i] = alpha ? v : 1.0f - v;
    } else {
      out.floats[i] = 1.0f - srgbToLinear(v);
    }
  }
  int32_t index = int32_t(context_.scene.textures.size());
  context_.scene.textures.push_back(std::move(out));
  inverted_[image] = index;
  return index;
}

int32_t PbrtTextures::checkerboardImage(Vec3 first, Vec3 second) {
  auto key = std::make_tuple(first.x, first.y, first.z, second.x, second.y, second.z);
  bool finite = isFinite(first) && isFinite(second);  // not-a-number would break the ordering of the keys
  if (auto found = checkerboards_.find(key); finite && found != checkerboards_.end()) return found->second;
  if (checkerboards_.size() >= kMaxCheckerboardImages || !finite) {
    context_.warn("many checkerboards", "checkerboards beyond the first " + std::to_string(kMaxCheckerboardImages) +
                                            " distinct ones (or of colours that are not finite) become their mean");
    return kNoTexture;
  }
  // pbrt's check at (s, t) is tex1 where floor(s) + floor(t) is even. The image spans s and t in [0, 2), and
  // its rows run down while t runs up: the top half is t in [1, 2).
  constexpr uint32_t kSize = 64;
  Texture image;
  image.name = "checkerboard";
  image.width = image.height = kSize;
  image.channels = 3;
  image.floats.resize(size_t(kSize) * kSize * 3);
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      int s = x >= kSize / 2 ? 1 : 0, t = y < kSize / 2 ? 1 : 0;
      Vec3 c = (s + t) % 2 == 0 ? first : second;
      float* out = image.floats.data() + (size_t(y) * kSize + x) * 3;
      out[0] = c.x;
      out[1] = c.y;
      out[2] = c.z;
    }
  int32_t index = int32_t(context_.scene.textures.size());
  context_.scene.textures.push_back(std::move(image));
  checkerboards_[key] = index;
  return index;
}

int32_t PbrtTextures::mappedImage(int32_t image, const std::string& key, const std::function<float(float)>& map,
                                  const std::string& where, const std::string& element) {
  auto cacheKey = std::make_pair(image, key);
  if (auto found = mapped_.find(cacheKey); found != mapped_.end()) return found->second;
  // The source's size and wrap are known before its texels are (a mix not baked yet); its wrap is taken now, as a
  // later imagemap of the same file may change the shared image's.
  const Texture& source = context_.scene.textures[size_t(image)];
  chargeLoadMemory(uint64_t(source.width) * source.height * sizeof(float), where,
                   element + " at " + std::to_string(source.width) + "x" + std::to_string(source.height) + " texels");
  Texture out;
  out.name = source.name + " (" + key + ")";
  out.width = source.width;
  out.height = source.height;
  out.channels = 1;
  out.wrapU = source.wrapU;
  out.wrapV = source.wrapV;
  const int32_t index = int32_t(context_.scene.textures.size());
  context_.scene.textures.push_back(std::move(out));
  unbaked_[index] = Mapping{image, map};
  mapped_[cacheKey] = index;
  return index;
}

Vec3 PbrtTextures::meanOfMix(const Texture& out, const Mix& mix) {
  bakeThrough(std::max({mix.first.image, mix.second.image, mix.amount.image}));
  const uint32_t width = std::min(out.width, kMeanGrid), height = std::min(out.height, kMeanGrid);
  double sum[3] = {0, 0, 0};
  forEachTexelCentre(width, height, [&](uint32_t, uint32_t, Vec2 uv) {
    const Vec3 c = colourAt(mix, uv.x, uv.y);
    sum[0] += c.x;
    sum[1] += c.y;
    sum[2] += c.z;
  });
  const double n = double(width) * height;
  return {float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)};
}

Vec3 PbrtTextures::meanColour(const PbrtTexture& texture) {
  if (texture.image == kNoTexture) return texture.factor;
  if (auto found = unbaked_.find(texture.image); found != unbaked_.end())
    if (const Mix* mix = std::get_if<Mix>(&found->second))
      return texture.factor * meanOfMix(context_.scene.textures[size_t(texture.image)], *mix);
  bakeThrough(texture.image);
  const Texture& image = context_.scene.textures[size_t(texture.image)];
  const size_t pixels = size_t(image.width) * image.height;
  if (pixels == 0 || image.channels == 0) return texture.factor;
  double sum[3] = {0, 0, 0};
  for (size_t i = 0; i < pixels; ++i)
    for (uint32_t c = 0; c < 3; ++c) {
      const size_t at = i * image.channels + (image.channels < 3 ? 0 : c);  // grey (and alpha): one channel
      float v = image.floats.empty() ? float(image.bytes[at]) / 255.0f : image.floats[at];
      if (image.floats.empty() && image.srgb) v = srgbToLinear(v);
      sum[c] += v;
    }
  const double n = double(pixels);
  return texture.factor * Vec3{float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)};
}

PbrtTexture PbrtTextures::value(const PbrtParameters& params, const std::string& name, Vec3 fallback) {
  if (std::optional<std::string> texture = params.getTexture(name)) {
    auto found = named_.find(*texture);
    if (found != named_.end()) return made(found->second);
    context_.warn("unknown texture " + *texture, params.file + ":" + std::to_string(params.line) + ": texture '" +
                                                     *texture + "' is not defined: '" + name + "' takes its default");
    return PbrtTexture{fallback};
  }
  if (std::optional<PbrtColor> c = params.getColor(name)) return PbrtTexture{c->rgb};
  return PbrtTexture{fallback};
}

PbrtTexture PbrtTextures::input(const Definition& definition, const std::string& name, Vec3 fallback) {
  const PbrtParameters& params = definition.params;
  if (std::optional<std::string> texture = params.getTexture(name)) {
    auto found = definition.inputs.find(*texture);
    if (found != definition.inputs.end() && found->second) return *found->second->made;
    context_.warn("unknown texture " + *texture, params.file + ":" + std::to_string(params.line) + ": texture '" +
                                                     *texture + "' is not defined: '" + name + "' takes its default");
    return PbrtTexture{fallback};
  }
  if (std::optional<PbrtColor> c = params.getColor(name)) return PbrtTexture{c->rgb};
  return PbrtTexture{fallback};
}

void PbrtTextures::define(const std::string& name, const std::string& valueType, const std::string& className,
                          const PbrtParameters& params) {
  if (valueType != "float" && valueType != "spectrum" && valueType != "color" && valueType != "rgb")
    params.fail("texture '" + name + "' has an unknown value type '" + valueType + "'");
  auto definition = std::make_shared<Definition>(Definition{name, valueType, className, params, {}, std::nullopt});
  for (const PbrtParameter& p : params.list)
    if (p.type == "texture" && !p.strings.empty()) {
      auto found = named_.find(p.strings.front());
      definition->inputs[p.strings.front()] = found == named_.end() ? nullptr : found->second;
    }
  named_[name] = std::move(definition);
}

const PbrtTexture& PbrtTextures::made(const std::shared_ptr<Definition>& definition) {
  std::vector<Definition*> pending{definition.get()};
  while (!pending.empty()) {
    Definition* d = pending.back();
    bool ready = true;
    for (const auto& [inputName, input] : d->inputs)
      if (input && !input->made) {
        pending.push_back(input.get());
        ready = false;
      }
    if (!ready) continue;
    pending.pop_back();
    if (!d->made) {
      d->made = make(*d);
      context_.warnUnused("texture '" + d->className + "'", d->params);
    }
  }
  return *definition->made;
}

PbrtTexture PbrtTextures::make(const Definition& definition) {
  const std::string& name = definition.name;
  const std::string& className = definition.className;
  const PbrtParameters& params = definition.params;
  auto value = [&](const PbrtParameters&, const std::string& parameter, Vec3 fallback) {
    return input(definition, parameter, fallback);
  };
  PbrtTexture t;
  if (className == "imagemap") {
    std::string file = params.getString("filename", "");
    if (file.empty()) params.fail("imagemap texture '" + name + "' without 'filename'");
    std::string encoding = params.getString("encoding", "sRGB");
    if (encoding != "sRGB" && encoding != "linear")
      context_.warn("texture encoding " + encoding, "texture encoding '" + encoding + "' read as sRGB");
    t.image = loadImage(file, encoding != "linear", params.file, params.line);
    float scale = params.getFloat("scale", 1.0f);
    t.factor = {scale, scale, scale};
    if (params.getBool("invert", false) && t.image != kNoTexture) t.image = invertedImage(t.image);
    std::string wrap = params.getString("wrap", "repeat");
    if (t.image != kNoTexture) {
      Texture& image = context_.scene.textures[size_t(t.image)];
      image.wrapU = image.wrapV = wrap == "clamp" || wrap == "black" ? TextureWrap::Clamp : TextureWrap::Repeat;
      if (wrap == "black") context_.warn("texture wrap black", "imagemap wrap 'black' is read as 'clamp'");
    }
  } else if (className == "constant") {
    t = value(params, "value", {1, 1, 1});
  } else if (className == "scale") {
    PbrtTexture tex = value(params, "tex", {1, 1, 1}), scale = value(params, "scale", {1, 1, 1});
    if (tex.image != kNoTexture && scale.image != kNoTexture)
      context_.warn("scale of two images", "a 'scale' texture of two images keeps only the first");
    t = tex.image != kNoTexture ? tex : scale;
    t.factor = tex.factor * scale.factor;
  } else if (className == "checkerboard" && params.getInt("dimension", 2) == 2) {
    PbrtTexture a = value(params, "tex1", {1, 1, 1}), b = value(params, "tex2", {0, 0, 0});
    if (a.image != kNoTexture || b.image != kNoTexture)
      context_.warn("checkerboard of images", "checkerboards of image textures use the images' mean colours");
    t.image = checkerboardImage(meanOf(a), meanOf(b));
    if (t.image == kNoTexture) t.factor = 0.5f * (meanOf(a) + meanOf(b));
  } else if (className == "mix") {
    // (1 - amount) tex1 + amount tex2: exact for constants; of images, an image of the mix over pbrt's unit
    // square, each input through its own uv mapping.
    PbrtTexture a = value(params, "tex1", {1, 1, 1}), b = value(params, "tex2", {0, 0, 0});
    PbrtTexture amount = value(params, "amount", {0.5f, 0.5f, 0.5f});
    if (a.image == kNoTexture && b.image == kNoTexture && amount.image == kNoTexture)
      t.factor = lerp(amount.factor.x, a.factor, b.factor);
    else
      t.image = mixedImage(a, b, amount, params.file + ":" + std::to_string(params.line), name);
  } else if (className == "checkerboard") {
    PbrtTexture a = value(params, "tex1", {1, 1, 1}), b = value(params, "tex2", {0, 0, 0});
    t.factor = 0.5f * (meanOf(a) + meanOf(b));
    context_.warn("texture " + className, "3D checkerboard textures are replaced by the mean of their inputs");
  } else {
    params.markAllUsed();
    t.factor = {0.5f, 0.5f, 0.5f};
    context_.warn("texture " + className, "'" + className + "' textures are not supported: grey 0.5 used instead");
  }
  t.uvScale = {params.getFloat("uscale", 1.0f), params.getFloat("vscale", 1.0f)};
  t.uvOffset = {params.getFloat("udelta", 0.0f), params.getFloat("vdelta", 0.0f)};
  if (className == "checkerboard" && t.image != kNoTexture) {
    // The image holds one period of the pattern, two checks of pbrt's unit size along each axis.
    t.uvScale = {0.5f * t.uvScale.x, 0.5f * t.uvScale.y};
    t.uvOffset = {0.5f * t.uvOffset.x, 0.5f * t.uvOffset.y};
  }
  std::string mapping = params.getString("mapping", "uv");
  if (mapping != "uv") context_.warn("texture mapping " + mapping, "texture mapping '" + mapping + "' read as 'uv'");
  return t;
}

}  // namespace candela
