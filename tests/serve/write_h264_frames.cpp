// write_h264_frames <folder> <width> <height> <frames>: encodes frames of a moving test pattern with candela
// serve's H.264 encoder at its rest settings, into <folder>/frame-<i>.h264 (the access units, the first an IDR
// frame) and <folder>/frame-<i>.rgb (the pixels that went in), for video_decode.mjs to decode in a browser.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "app/serve/stream_quality.h"
#include "io/video/h264_encoder.h"

namespace {

// Smooth colour ramps over the whole range of each channel, moving with the frame. No sharp edge: 4:2:0 chroma
// (JPEG's too) blurs one in any codec, which says nothing about the stream's colours.
std::vector<uint8_t> pattern(uint32_t width, uint32_t height, uint32_t frame) {
  std::vector<uint8_t> rgb(size_t(width) * height * 3);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      uint8_t* p = &rgb[3 * (size_t(y) * width + x)];
      const float u = float(x + 2 * frame) / float(width), v = float(y) / float(height);
      p[0] = uint8_t(255.0f * std::fabs(1.0f - std::fmod(u, 2.0f)));  // a triangle wave: no edge
      p[1] = uint8_t(255.0f * v);
      p[2] = uint8_t(255.0f * (0.5f + 0.5f * std::sin(6.0f * u + 4.0f * v)));
    }
  return rgb;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: write_h264_frames <folder> <width> <height> <frames>\n");
    return 2;
  }
  const std::string folder = argv[1];
  const uint32_t width = uint32_t(std::atoi(argv[2])), height = uint32_t(std::atoi(argv[3]));
  const uint32_t frames = uint32_t(std::atoi(argv[4]));
  candela::H264Encoder encoder;
  const candela::H264Settings settings =
      candela::StreamQuality().videoSettings(/*moving=*/false, /*framesPerSecond=*/60.0);
  for (uint32_t i = 0; i < frames; ++i) {
    const std::vector<uint8_t> rgb = pattern(width, height, i);
    const candela::H264Frame frame = encoder.encode(rgb.data(), width, height, settings, false);
    const std::string name = folder + "/frame-" + std::to_string(i);
    std::ofstream(name + ".h264", std::ios::binary).write(frame.bytes.data(), std::streamsize(frame.bytes.size()));
    std::ofstream(name + ".rgb", std::ios::binary)
        .write(reinterpret_cast<const char*>(rgb.data()), std::streamsize(rgb.size()));
    std::printf("frame %u: %s%s, %zu bytes\n", i, frame.codec.c_str(), frame.key ? " (key)" : "", frame.bytes.size());
  }
  return 0;
}
