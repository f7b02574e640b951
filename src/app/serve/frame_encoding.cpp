#include "app/serve/frame_encoding.h"

#include <stb/stb_image_write.h>
#include <turbojpeg.h>

#include <memory>
#include <stdexcept>

#include "image/tonemap.h"

namespace candela {

DisplayImage displayImage(const Image& linear, const DisplaySettings& display) {
  DisplayImage out{linear.width, linear.height, std::vector<uint8_t>(linear.pixels.size() * 3)};
  for (size_t i = 0; i < linear.pixels.size(); ++i) {
    const Vec3 c = toneMap(linear.pixels[i], display.exposure, display.toneMapper);
    out.rgb[3 * i + 0] = displayByte(c.x);
    out.rgb[3 * i + 1] = displayByte(c.y);
    out.rgb[3 * i + 2] = displayByte(c.z);
  }
  return out;
}

DisplayImage displayImage(FrameImages& frame) { return displayImage(frame.filtered(), frame.post().display); }

std::string encodeJpeg(const DisplayImage& image, int quality) {
  std::unique_ptr<void, int (*)(tjhandle)> compressor(tjInitCompress(), tjDestroy);
  if (!compressor) throw std::runtime_error(std::string("libjpeg-turbo: ") + tjGetErrorStr());
  unsigned char* jpeg = nullptr;
  unsigned long size = 0;
  // 4:2:0 chroma halves the bytes of a frame; the eye misses the colour detail in a moving picture.
  const int status = tjCompress2(compressor.get(), image.rgb.data(), int(image.width), 0, int(image.height), TJPF_RGB,
                                 &jpeg, &size, TJSAMP_420, quality, TJFLAG_FASTDCT);
  std::unique_ptr<unsigned char, void (*)(unsigned char*)> owned(jpeg, tjFree);
  if (status != 0) throw std::runtime_error(std::string("libjpeg-turbo: ") + tjGetErrorStr2(compressor.get()));
  return std::string(reinterpret_cast<const char*>(jpeg), size);
}

std::string encodePng(const DisplayImage& image) {
  std::string png;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
  };
  if (!stbi_write_png_to_func(append, &png, int(image.width), int(image.height), 3, image.rgb.data(),
                              int(image.width) * 3))
    throw std::runtime_error("the PNG could not be encoded");
  return png;
}

}  // namespace candela
