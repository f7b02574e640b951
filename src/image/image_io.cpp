#include "image/image_io.h"
#include "core/file_extension.h"

#include <stb/stb_image_write.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace candela {

namespace {

[[noreturn]] void cannotWrite(const std::string& path, const std::string& why) {
  throw std::runtime_error("cannot write '" + path + "': " + why);
}

void writePng(const std::string& path, const Image& image, const DisplaySettings& display) {
  std::vector<uint8_t> bytes(size_t(image.width) * image.height * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    Vec3 c = toneMap(image.pixels[i], display.exposure, display.toneMapper);
    bytes[3 * i + 0] = uint8_t(c.x * 255.0f + 0.5f);
    bytes[3 * i + 1] = uint8_t(c.y * 255.0f + 0.5f);
    bytes[3 * i + 2] = uint8_t(c.z * 255.0f + 0.5f);
  }
  if (!stbi_write_png(path.c_str(), int(image.width), int(image.height), 3, bytes.data(), int(image.width) * 3))
    cannotWrite(path, "the file could not be created or written");
}

void writeExr(const std::string& path, const Image& image) {
  const char* base = reinterpret_cast<const char*>(image.pixels.data());
  writeExrChannels(path, image.width, image.height,
                   {{"R", base, sizeof(Vec3)}, {"G", base + sizeof(float), sizeof(Vec3)},
                    {"B", base + 2 * sizeof(float), sizeof(Vec3)}});
}

// Portable float map: little-endian (negative scale), rows bottom to top.
void writePfm(const std::string& path, const Image& image) {
  std::ofstream out(path, std::ios::binary);
  if (!out) cannotWrite(path, "the file could not be created");
  out << "PF\n" << image.width << " " << image.height << "\n-1.0\n";
  for (uint32_t y = image.height; y-- > 0;)
    out.write(reinterpret_cast<const char*>(&image.at(0, y)), std::streamsize(sizeof(Vec3) * image.width));
  if (!out) cannotWrite(path, "writing failed");
}

}  // namespace

void writeExrChannels(const std::string& path, uint32_t width, uint32_t height,
                      const std::vector<ExrChannel>& channels) {
  try {
    Imf::Header header{int(width), int(height)};
    for (const ExrChannel& c : channels) header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(path.c_str(), header);
    Imf::FrameBuffer fb;
    for (const ExrChannel& c : channels)
      fb.insert(c.name, Imf::Slice(Imf::FLOAT, const_cast<char*>(c.base), c.xStride, c.xStride * width));
    file.setFrameBuffer(fb);
    file.writePixels(int(height));
  } catch (const std::exception& e) {
    cannotWrite(path, e.what());
  }
}

const char* toneMapperName(ToneMapper mapper) {
  switch (mapper) {
    case ToneMapper::Clamp: return "clamp";
    case ToneMapper::Reinhard: return "reinhard";
    case ToneMapper::AcesFilmic: break;
  }
  return "aces";
}

ToneMapper parseToneMapper(const std::string& name) {
  for (ToneMapper m : {ToneMapper::AcesFilmic, ToneMapper::Clamp, ToneMapper::Reinhard})
    if (name == toneMapperName(m)) return m;
  throw std::invalid_argument("unknown tone mapper '" + name + "' (use aces, clamp or reinhard)");
}

bool isSupportedImageExtension(const std::string& path) {
  std::string ext = lowerCaseExtension(path);
  return ext == ".png" || ext == ".exr" || ext == ".pfm";
}

void writeImage(const std::string& path, const Image& image, const DisplaySettings& display) {
  std::string ext = lowerCaseExtension(path);
  if (ext == ".png")
    writePng(path, image, display);
  else if (ext == ".exr")
    writeExr(path, image);
  else if (ext == ".pfm")
    writePfm(path, image);
  else
    cannotWrite(path, "unknown image format '" + ext + "' (use .png, .exr or .pfm)");
}

}  // namespace candela
