#include "io/images/image_io.h"
#include "core/file_extension.h"

#include <stb/stb_image_write.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>

namespace candela {

namespace {

[[noreturn]] void cannotWrite(const std::string& path, const std::string& why) {
  throw WriteError("cannot write '" + path + "': " + why);
}

// OpenEXR's output stream into an AtomicFile. OpenEXR seeks back to write the table of line offsets last.
class AtomicFileStream : public Imf::OStream {
 public:
  explicit AtomicFileStream(AtomicFile& file) : Imf::OStream(file.target().c_str()), file_(file) {}
  void write(const char c[], int n) override { file_.write(c, size_t(n)); }
  // OpenEXR's output file asks for the position as it goes, outside its own error handling: after a failure,
  // which the file keeps and reports, these do nothing.
  uint64_t tellp() override { return file_.stream() ? uint64_t(ftello(file_.stream())) : 0; }
  void seekp(uint64_t position) override {
    if (file_.stream() && fseeko(file_.stream(), off_t(position), SEEK_SET) != 0)
      throw std::runtime_error(std::strerror(errno));
  }

 private:
  AtomicFile& file_;
};

void writeToneMappedPng(AtomicFile& file, const Image& image, const DisplaySettings& display) {
  std::vector<uint8_t> bytes(size_t(image.width) * image.height * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    Vec3 c = toneMap(image.pixels[i], display.exposure, display.toneMapper);
    bytes[3 * i + 0] = displayByte(c.x);
    bytes[3 * i + 1] = displayByte(c.y);
    bytes[3 * i + 2] = displayByte(c.z);
  }
  writePngTo(file, int(image.width), int(image.height), 3, bytes.data(), int(image.width) * 3);
}

void writeExrImage(AtomicFile& file, const Image& image) {
  const char* base = reinterpret_cast<const char*>(image.pixels.data());
  writeExrChannelsTo(file, image.width, image.height,
                     {{"R", base, sizeof(Vec3)},
                      {"G", base + sizeof(float), sizeof(Vec3)},
                      {"B", base + 2 * sizeof(float), sizeof(Vec3)}});
}

// Portable float map: little-endian (negative scale), rows bottom to top.
void writePfm(AtomicFile& file, const Image& image) {
  const std::string header = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  file.write(header.data(), header.size());
  for (uint32_t y = image.height; y-- > 0;) file.write(&image.at(0, y), sizeof(Vec3) * image.width);
}

}  // namespace

void writePngTo(AtomicFile& file, int width, int height, int channels, const uint8_t* pixels, int strideBytes) {
  // stb calls back with the encoded bytes; an exception must not cross its C frames, so the first one is kept.
  struct Sink {
    AtomicFile& file;
    std::exception_ptr error;
  } sink{file, nullptr};
  auto write = [](void* context, void* data, int size) {
    auto* s = static_cast<Sink*>(context);
    if (s->error) return;
    try {
      s->file.write(data, size_t(size));
    } catch (...) {
      s->error = std::current_exception();
    }
  };
  const int ok = stbi_write_png_to_func(write, &sink, width, height, channels, pixels, strideBytes);
  if (sink.error) std::rethrow_exception(sink.error);
  if (!ok) cannotWrite(file.target(), "PNG encoding failed");
}

void writePngFile(const std::string& path, int width, int height, int channels, const uint8_t* pixels,
                  int strideBytes) {
  AtomicFile file(path);
  writePngTo(file, width, height, channels, pixels, strideBytes);
  file.commit();
}

void writeExrChannelsTo(AtomicFile& file, uint32_t width, uint32_t height, const std::vector<ExrChannel>& channels,
                        const ExrAttributes& attributes) {
  const auto type = [](const ExrChannel& c) { return c.isUint ? Imf::UINT : Imf::FLOAT; };
  try {
    Imf::Header header{int(width), int(height)};
    for (const auto& [name, value] : attributes) header.insert(name, Imf::StringAttribute(value));
    for (const ExrChannel& c : channels) header.channels().insert(c.name, Imf::Channel(type(c)));
    AtomicFileStream stream(file);
    // The output file writes its table of line offsets when it goes, so it goes before the file is finished.
    Imf::OutputFile exr(stream, header);
    Imf::FrameBuffer fb;
    for (const ExrChannel& c : channels)
      fb.insert(c.name, Imf::Slice(type(c), const_cast<char*>(c.base), c.xStride, c.xStride * width));
    exr.setFrameBuffer(fb);
    exr.writePixels(int(height));
  } catch (const WriteError&) {
    throw;
  } catch (const std::exception& e) {
    cannotWrite(file.target(), e.what());
  }
  // OpenEXR ignores failures while writing the line offsets as the file closes; the stream remembers them.
  file.finish();
}

void writeExrChannels(const std::string& path, uint32_t width, uint32_t height,
                      const std::vector<ExrChannel>& channels) {
  AtomicFile file(path);
  writeExrChannelsTo(file, width, height, channels);
  file.commit();
}

void writeImageTo(AtomicFile& file, const Image& image, const DisplaySettings& display) {
  const std::string ext = lowerCaseExtension(file.target());
  if (ext == ".png")
    writeToneMappedPng(file, image, display);
  else if (ext == ".exr")
    writeExrImage(file, image);
  else if (ext == ".pfm")
    writePfm(file, image);
  else
    cannotWrite(file.target(), "unknown image format '" + ext + "' (use .png, .exr or .pfm)");
}

bool isSupportedImageExtension(const std::string& path) {
  std::string ext = lowerCaseExtension(path);
  return ext == ".png" || ext == ".exr" || ext == ".pfm";
}

void writeImage(const std::string& path, const Image& image, const DisplaySettings& display) {
  if (!isSupportedImageExtension(path))
    cannotWrite(path, "unknown image format '" + lowerCaseExtension(path) + "' (use .png, .exr or .pfm)");
  AtomicFile file(path);
  writeImageTo(file, image, display);
  file.commit();
}

}  // namespace candela
