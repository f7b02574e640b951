// write_striped_jpeg <file> <width> <height> <threads>: packs a striped JPEG frame of a test pattern into <file>,
// for the unpacking test of the page's module (striped_jpeg_message_test.mjs).
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <vector>

#include "io/images/striped_jpeg.h"

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: write_striped_jpeg <file> <width> <height> <threads>\n");
    return 2;
  }
  const uint32_t width = uint32_t(std::atoi(argv[2])), height = uint32_t(std::atoi(argv[3]));
  std::vector<uint8_t> rgb(size_t(width) * height * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t((i / 3 % width) * 255 / width + (i % 3) * 40);
  candela::StripedJpegEncoder encoder(unsigned(std::atoi(argv[4])));
  const std::string message = candela::packStripedJpeg(encoder.encode(rgb.data(), width, height, 80));
  std::ofstream(argv[1], std::ios::binary).write(message.data(), std::streamsize(message.size()));
  return 0;
}
