// compare_exr A.exr B.exr [tolerance]: compares two OpenEXR files channel by channel. Unsigned-integer channels
// (a checkpoint's sample counts) must be equal; float channels may differ by `tolerance` relative to the larger
// magnitude (default 0: equal). Also prints the mean of each float channel of both, for the statistical checks.
// Exit status 0 when they match, 1 with the first difference otherwise.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace {

struct Channels {
  int width = 0, height = 0;
  std::map<std::string, std::vector<float>> floats;
  std::map<std::string, std::vector<unsigned>> uints;
};

Channels read(const char* path) {
  Imf::InputFile file(path);
  const Imath::Box2i window = file.header().dataWindow();
  Channels c;
  c.width = window.max.x - window.min.x + 1;
  c.height = window.max.y - window.min.y + 1;
  const size_t pixels = size_t(c.width) * size_t(c.height);
  Imf::FrameBuffer frame;
  for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
    char* base = nullptr;
    size_t stride = 0;
    if (it.channel().type == Imf::UINT) {
      base = reinterpret_cast<char*>(c.uints[it.name()].assign(pixels, 0), c.uints[it.name()].data());
      stride = sizeof(unsigned);
    } else {
      base = reinterpret_cast<char*>(c.floats[it.name()].assign(pixels, 0.0f), c.floats[it.name()].data());
      stride = sizeof(float);
    }
    frame.insert(it.name(), Imf::Slice(it.channel().type == Imf::UINT ? Imf::UINT : Imf::FLOAT, base, stride,
                                       stride * size_t(c.width)));
  }
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: compare_exr A.exr B.exr [relative tolerance]\n");
    return 2;
  }
  const double tolerance = argc > 3 ? std::atof(argv[3]) : 0.0;
  const Channels a = read(argv[1]), b = read(argv[2]);
  if (a.width != b.width || a.height != b.height) {
    std::printf("sizes differ: %dx%d and %dx%d\n", a.width, a.height, b.width, b.height);
    return 1;
  }
  for (const auto& [name, values] : a.uints) {
    const auto other = b.uints.find(name);
    if (other == b.uints.end()) return std::printf("channel %s is missing from %s\n", name.c_str(), argv[2]), 1;
    for (size_t i = 0; i < values.size(); ++i)
      if (values[i] != other->second[i])
        return std::printf("%s differs at pixel %zu: %u and %u\n", name.c_str(), i, values[i], other->second[i]), 1;
  }
  double largest = 0.0;
  for (const auto& [name, values] : a.floats) {
    const auto other = b.floats.find(name);
    if (other == b.floats.end()) return std::printf("channel %s is missing from %s\n", name.c_str(), argv[2]), 1;
    double sumA = 0.0, sumB = 0.0;
    for (size_t i = 0; i < values.size(); ++i) {
      const double x = values[i], y = other->second[i];
      sumA += x;
      sumB += y;
      const double difference = std::fabs(x - y), scale = std::max({std::fabs(x), std::fabs(y), 1e-30});
      largest = std::max(largest, difference / scale);
      if (difference > tolerance * scale)
        return std::printf("%s differs at pixel %zu: %.9g and %.9g\n", name.c_str(), i, x, y), 1;
    }
    std::printf("%s: mean %.9g and %.9g\n", name.c_str(), sumA / double(values.size()), sumB / double(values.size()));
  }
  if (a.floats.size() != b.floats.size() || a.uints.size() != b.uints.size())
    return std::printf("%s has channels that %s has not\n", argv[2], argv[1]), 1;
  std::printf("equal within %g (largest relative difference %.3g)\n", tolerance, largest);
  return 0;
}
