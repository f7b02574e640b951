#include "io/images/aov_io.h"
#include "core/file_extension.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace candela {

namespace {

std::string besidePath(const std::string& path, Aov aov) {
  std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "." + aovName(aov) + p.extension().string())).string();
}

Image depthAsImage(const AovImages& aovs, float scale) {
  Image image(aovs.width(), aovs.height());
  for (size_t i = 0; i < aovs.depth.size(); ++i) image.pixels[i] = Vec3{1, 1, 1} * (aovs.depth[i] * scale);
  return image;
}

void writeRawPng(AtomicFile& file, const Image& image, Vec3 (*encode)(Vec3)) {
  std::vector<uint8_t> bytes(image.pixels.size() * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const Vec3 c = encode(image.pixels[i]);
    for (int k = 0; k < 3; ++k) bytes[3 * i + k] = uint8_t(clampf(c[k], 0.0f, 1.0f) * 255.0f + 0.5f);
  }
  writePngTo(file, int(image.width), int(image.height), 3, bytes.data(), int(image.width) * 3);
}

void writeExrWithAovs(const std::string& path, const Image& image, const AovImages& aovs,
                      const std::vector<Aov>& which) {
  auto rgb = [](const Image& source, const char* r, const char* g, const char* b) {
    const char* base = reinterpret_cast<const char*>(source.pixels.data());
    return std::vector<ExrChannel>{{r, base, sizeof(Vec3)},
                                   {g, base + sizeof(float), sizeof(Vec3)},
                                   {b, base + 2 * sizeof(float), sizeof(Vec3)}};
  };
  std::vector<ExrChannel> channels = rgb(image, "R", "G", "B");
  for (Aov aov : which) {
    std::vector<ExrChannel> more;
    if (aov == Aov::Albedo) more = rgb(aovs.albedo, "albedo.R", "albedo.G", "albedo.B");
    if (aov == Aov::Normal) more = rgb(aovs.normal, "normal.X", "normal.Y", "normal.Z");
    if (aov == Aov::Depth) more = {{"Z", reinterpret_cast<const char*>(aovs.depth.data()), sizeof(float)}};
    channels.insert(channels.end(), more.begin(), more.end());
  }
  writeExrChannels(path, image.width, image.height, channels);
}

}  // namespace

const char* aovName(Aov aov) {
  switch (aov) {
    case Aov::Normal: return "normal";
    case Aov::Depth: return "depth";
    case Aov::Albedo: break;
  }
  return "albedo";
}

std::vector<Aov> parseAovList(const std::string& list) {
  std::vector<Aov> result;
  size_t start = 0;
  while (start <= list.size()) {
    size_t end = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, end - start);
    bool known = false;
    for (Aov aov : {Aov::Albedo, Aov::Normal, Aov::Depth})
      if (name == aovName(aov)) {
        if (std::find(result.begin(), result.end(), aov) != result.end())
          throw std::invalid_argument("AOV '" + name + "' is listed twice");
        result.push_back(aov);
        known = true;
      }
    if (!known) throw std::invalid_argument("unknown AOV '" + name + "' (use albedo, normal, depth, comma-separated)");
    start = end + 1;
  }
  return result;
}

std::vector<std::string> writeImageWithAovs(const std::string& path, const Image& image, const DisplaySettings& display,
                                            const AovImages& aovs, const std::vector<Aov>& which) {
  if (!which.empty() && (aovs.width() != image.width || aovs.height() != image.height))
    throw std::invalid_argument("the AOVs differ in size from the image");
  const std::string ext = lowerCaseExtension(path);
  std::vector<std::string> written{path};
  if (ext == ".exr") {
    writeExrWithAovs(path, image, aovs, which);
    return written;
  }
  // Every file is written to its temporary first and renamed only once all are complete, the image last: a
  // failure leaves every previous file as it was.
  std::vector<std::unique_ptr<AtomicFile>> files;
  files.push_back(std::make_unique<AtomicFile>(path));
  writeImageTo(*files.back(), image, display);
  float largestDepth = 0.0f;
  for (float d : aovs.depth) largestDepth = std::max(largestDepth, d);
  for (Aov aov : which) {
    const std::string aovPath = besidePath(path, aov);
    const Image depth = aov == Aov::Depth
                            ? depthAsImage(aovs, ext == ".png" && largestDepth > 0.0f ? 1.0f / largestDepth : 1.0f)
                            : Image();
    const Image& source = aov == Aov::Albedo ? aovs.albedo : aov == Aov::Normal ? aovs.normal : depth;
    files.push_back(std::make_unique<AtomicFile>(aovPath));
    AtomicFile& file = *files.back();
    if (ext != ".png")
      writeImageTo(file, source, display);
    else if (aov == Aov::Albedo)
      writeImageTo(file, source, {0.0f, ToneMapper::Clamp});
    else if (aov == Aov::Normal)
      writeRawPng(file, source, [](Vec3 n) { return n * 0.5f + Vec3{0.5f, 0.5f, 0.5f}; });
    else
      writeRawPng(file, source, [](Vec3 d) { return d; });
    written.push_back(aovPath);
  }
  for (std::unique_ptr<AtomicFile>& file : files) file->finish();
  for (size_t i = files.size(); i-- > 0;) files[i]->commit();
  return written;
}

}  // namespace candela
