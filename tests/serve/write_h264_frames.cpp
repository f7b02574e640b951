// Encodes frames with candela serve's H.264 encoder into <folder>/frame-<i>.h264 (the access units, the first an
// IDR frame) and <folder>/frame-<i>.rgb (the pixels that went in), for video_decode.mjs to decode in a browser:
//   write_h264_frames <folder> <width> <height> <frames>   a moving test pattern, at the stream's rest settings
//   write_h264_frames <folder> rest|moving <frame.png>...  rendered frames, at the settings the stream has on a
//                                                          fast link at rest or while the camera moves
// Both at the frame rate the stream has there, on a link that delivers 60 frames a second: 60 moving,
// StreamQuality::kRestFrameRate at rest (each rest frame stands for that much time: of a still camera's
// accumulation, take every third frame of one sample). The last line gives the size, the count and the rate of the
// frames after the first (the key frame, which a stream sends once): "<width> <height> <frames> frames, <rate>
// Mbit/s at <fps> frames a second after the key frame".
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "app/serve/stream_quality.h"
#include "io/file_bytes.h"
#include "io/images/png_decoding.h"
#include "io/video/h264_encoder.h"

namespace {

// The rate a fast link takes frames at, as serve measures it; the stream at rest goes slower (StreamQuality).
constexpr double kMeasuredFramesPerSecond = 60.0;

struct Frame {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgb;
};

// Smooth colour ramps over the whole range of each channel, moving with the frame. No sharp edge: 4:2:0 chroma
// (JPEG's too) blurs one in any codec, which says nothing about the stream's colours.
Frame pattern(uint32_t width, uint32_t height, uint32_t frame) {
  Frame f{width, height, std::vector<uint8_t>(size_t(width) * height * 3)};
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      uint8_t* p = &f.rgb[3 * (size_t(y) * width + x)];
      const float u = float(x + 2 * frame) / float(width), v = float(y) / float(height);
      p[0] = uint8_t(255.0f * std::fabs(1.0f - std::fmod(u, 2.0f)));  // a triangle wave: no edge
      p[1] = uint8_t(255.0f * v);
      p[2] = uint8_t(255.0f * (0.5f + 0.5f * std::sin(6.0f * u + 4.0f * v)));
    }
  return f;
}

// A PNG's pixels as they are (8-bit sRGB, as candela writes them), grey expanded and alpha dropped.
Frame readPng(const std::string& path) {
  const std::vector<uint8_t> bytes = candela::readFileBytes(path);
  const candela::ImageInfo info = candela::pngInfo(path, bytes.data(), bytes.size());
  const candela::Texture texture = candela::decodePng(path, bytes.data(), bytes.size(), info.width, info.height);
  Frame f{texture.width, texture.height, std::vector<uint8_t>(size_t(texture.width) * texture.height * 3)};
  for (size_t p = 0; p < size_t(f.width) * f.height; ++p)
    for (size_t c = 0; c < 3; ++c)
      f.rgb[3 * p + c] = texture.bytes[texture.channels * p + std::min<size_t>(c, texture.channels - 1)];
  return f;
}

// The stream's settings once a link that delivers every frame quickly has raised the moving quality as far as it
// goes (stream_quality.h): what a browser on loopback or a fast network gets.
candela::H264Settings fastLinkSettings(bool moving) {
  candela::StreamQuality quality;
  for (int i = 0; i < 20; ++i) quality.recordDelivery(1000000, 0.001, true);
  return quality.videoSettings(moving, kMeasuredFramesPerSecond);
}

}  // namespace

int main(int argc, char** argv) try {
  const bool pngs = argc >= 4 && (std::string(argv[2]) == "rest" || std::string(argv[2]) == "moving");
  if (!pngs && argc != 5) {
    std::fprintf(stderr,
                 "usage: write_h264_frames <folder> <width> <height> <frames>\n"
                 "       write_h264_frames <folder> rest|moving <frame.png>...\n");
    return 2;
  }
  const std::string folder = argv[1];
  const uint32_t frames = pngs ? uint32_t(argc - 3) : uint32_t(std::atoi(argv[4]));
  const candela::H264Settings settings =
      pngs ? fastLinkSettings(std::string(argv[2]) == "moving")
           : candela::StreamQuality().videoSettings(/*moving=*/false, kMeasuredFramesPerSecond);
  candela::H264Encoder encoder;
  size_t bytesAfterKey = 0;
  Frame frame;
  for (uint32_t i = 0; i < frames; ++i) {
    frame = pngs ? readPng(argv[3 + i]) : pattern(uint32_t(std::atoi(argv[2])), uint32_t(std::atoi(argv[3])), i);
    const candela::H264Frame encoded = encoder.encode(frame.rgb.data(), frame.width, frame.height, settings, false);
    const std::string name = folder + "/frame-" + std::to_string(i);
    std::ofstream(name + ".h264", std::ios::binary).write(encoded.bytes.data(), std::streamsize(encoded.bytes.size()));
    std::ofstream(name + ".rgb", std::ios::binary)
        .write(reinterpret_cast<const char*>(frame.rgb.data()), std::streamsize(frame.rgb.size()));
    std::printf("frame %u: %s%s, %zu bytes\n", i, encoded.codec.c_str(), encoded.key ? " (key)" : "",
                encoded.bytes.size());
    if (i > 0) bytesAfterKey += encoded.bytes.size();
  }
  const double framesPerSecond = settings.framesPerSecond;
  std::printf("rate factor %.1f, at most %u kbit/s, deblocking %s\n", double(settings.rateFactor),
              settings.maxKilobitsPerSecond, settings.deblocking ? "on" : "off");
  std::printf("%u %u %u frames, %.2f Mbit/s at %.0f frames a second after the key frame\n", frame.width, frame.height,
              frames, frames > 1 ? double(bytesAfterKey) * 8.0 * framesPerSecond / double(frames - 1) / 1e6 : 0.0,
              framesPerSecond);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "write_h264_frames: %s\n", e.what());
  return 1;
}
