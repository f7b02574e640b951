#include "image/image_io.h"

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

std::string extensionOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

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
  try {
    Imf::Header header(int(image.width), int(image.height));
    header.channels().insert("R", Imf::Channel(Imf::FLOAT));
    header.channels().insert("G", Imf::Channel(Imf::FLOAT));
    header.channels().insert("B", Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(path.c_str(), header);
    Imf::FrameBuffer fb;
    char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
    size_t xStride = sizeof(Vec3), yStride = sizeof(Vec3) * image.width;
    fb.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
    fb.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
    fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
    file.setFrameBuffer(fb);
    file.writePixels(int(image.height));
  } catch (const std::exception& e) {
    cannotWrite(path, e.what());
  }
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

bool isSupportedImageExtension(const std::string& path) {
  std::string ext = extensionOf(path);
  return ext == ".png" || ext == ".exr" || ext == ".pfm";
}

void writeImage(const std::string& path, const Image& image, const DisplaySettings& display) {
  std::string ext = extensionOf(path);
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
