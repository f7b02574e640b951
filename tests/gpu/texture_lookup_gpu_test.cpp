// Texture lookups through CUDA texture objects (DeviceTextures) agree with the host's bilinear lookup in
// kernel/texture.h for every wrap mode, texel format and channel count, within the bound below.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <sstream>

#include "backends/optix/device_buffer.h"
#include "backends/optix/device_textures.h"
#include "texture_lookup_kernel.h"

namespace candela {
namespace {

// An odd, non-square size: a swapped u and v or a flipped v cannot pass by symmetry.
constexpr uint32_t kWidth = 7;
constexpr uint32_t kHeight = 5;

float channelOf(Vec4 v, int c) { return c == 0 ? v.x : (c == 1 ? v.y : (c == 2 ? v.z : v.w)); }

struct TestTexture {
  std::vector<TextureView> views;
  std::vector<uint8_t> bytes;
  std::vector<float> floats;

  TexelArrays hostArrays() const { return {views.data(), uint32_t(views.size()), bytes.data(), floats.data()}; }
};

// Random texels: 8-bit over the whole range, floats over [0, 4) (values past 1, as in HDR images).
TestTexture randomTexture(TexelFormat format, TextureWrap wrap, uint32_t channels, bool srgb, uint32_t seed) {
  std::mt19937 rng(seed);
  TestTexture t;
  TextureView view;
  view.width = kWidth;
  view.height = kHeight;
  view.channels = channels;
  view.format = format;
  view.srgb = srgb ? 1u : 0u;
  view.wrapU = view.wrapV = wrap;
  const size_t count = size_t(kWidth) * kHeight * channels;
  for (size_t i = 0; i < count; ++i) {
    if (format == TexelFormat::Unorm8)
      t.bytes.push_back(uint8_t(rng() & 0xFF));
    else
      t.floats.push_back(std::uniform_real_distribution<float>(0.0f, 4.0f)(rng));
  }
  t.views.push_back(view);
  return t;
}

// Coordinates over several periods on both sides of [0, 1], and the texel centres themselves.
std::vector<Vec2> lookupCoordinates() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> range(-1.5f, 2.5f);
  std::vector<Vec2> uvs;
  for (int i = 0; i < 4000; ++i) uvs.push_back({range(rng), range(rng)});
  for (uint32_t y = 0; y < kHeight; ++y)
    for (uint32_t x = 0; x < kWidth; ++x) uvs.push_back({(float(x) + 0.5f) / kWidth, (float(y) + 0.5f) / kHeight});
  return uvs;
}

// The distance between the linear values of the 8-bit sRGB code that decodes to `linear` and its brighter
// neighbour (its darker one at the top code).
float srgbStepAt(float linear) {
  const float encoded = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
  const int code = std::clamp(int(std::lround(encoded * 255.0f)), 0, 254);
  return srgbToLinear(float(code + 1) / 255.0f) - srgbToLinear(float(code) / 255.0f);
}

// How far the texture unit may be from the host's exact bilinear lookup, per channel.
// - The unit holds the bilinear weights in 9-bit fixed point with 8 fractional bits (CUDA Programming Guide,
//   "Texture Fetching", linear filtering), so each weight is off by at most 2^-8; a weight off by d moves
//   the result by at most d times the spread (max - min) of the four texels along that axis: 2 * 2^-8 * spread.
// - 8-bit formats: the unit's result may be off by one step of the 8-bit input as decoded: 1/255 for linear
//   data; for sRGB colour, one step of the sRGB curve at the brightest of the four texels (up to 0.0089 at the
//   top; the unit decodes sRGB by table before filtering), at least 1/255. Float formats: 1e-5 of the largest
//   texel for float rounding.
// A half-texel shift, a flipped v, a wrong wrap mode or a missing sRGB decode moves results by a good part of
// the spread, far past this bound (TextureLookupBound.RejectsCommonMistakes).
float lookupBound(const TexelArrays& arrays, Vec2 uv, int channel) {
  const TextureView& t = arrays.textures[0];
  float x = uv.x * float(t.width) - 0.5f, y = uv.y * float(t.height) - 0.5f;
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float lo = INFINITY, hi = -INFINITY;
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const int xi = wrapTexel(x0 + dx, int(t.width), t.wrapU), yi = wrapTexel(y0 + dy, int(t.height), t.wrapV);
      Vec4 c = fetchTexel(arrays, t, textureLevel(t, 0), xi, yi);
      lo = std::min(lo, channelOf(c, channel));
      hi = std::max(hi, channelOf(c, channel));
    }
  const float weights = 2.0f * (hi - lo) / 256.0f;
  if (t.format == TexelFormat::Float32) return weights + 1e-5f * std::max(std::fabs(hi), 1.0f);
  const bool alpha = channel == 3 && (t.channels == 2 || t.channels == 4);
  return weights + (t.srgb && !alpha ? std::max(1.0f / 255.0f, srgbStepAt(hi)) : 1.0f / 255.0f);
}

struct Outliers {
  size_t count = 0;
  std::string first;
};

Outliers outsideBound(const TexelArrays& reference, const std::vector<Vec2>& uvs, const std::vector<Vec4>& values) {
  Outliers o;
  for (size_t i = 0; i < uvs.size(); ++i) {
    Vec4 expected = sampleTexture(reference, 0, uvs[i]);
    for (int c = 0; c < 4; ++c) {
      float bound = lookupBound(reference, uvs[i], c);
      const float value = channelOf(values[i], c), want = channelOf(expected, c);
      if (std::fabs(value - want) <= bound) continue;
      if (o.count++ == 0) {
        std::ostringstream s;
        s << "uv (" << uvs[i].x << ", " << uvs[i].y << ") channel " << c << ": " << value << " vs " << want
          << ", bound " << bound;
        o.first = s.str();
      }
    }
  }
  return o;
}

void expectDeviceAgrees(TexelFormat format, TextureWrap wrap, uint32_t channels, bool srgb, uint32_t seed,
                        std::optional<TextureWrap> wrapV = std::nullopt) {
  TestTexture texture = randomTexture(format, wrap, channels, srgb, seed);
  if (wrapV) texture.views[0].wrapV = *wrapV;
  optix::DeviceTextures device(texture.views, texture.bytes, texture.floats);
  ASSERT_NE(device.views()[0].deviceTexture, 0u);
  optix::DeviceBuffer views = optix::DeviceBuffer::fromVector(device.views(), "texture views");
  TexelArrays deviceArrays{views.as<const TextureView>(), 1, nullptr, nullptr};
  std::vector<Vec2> uvs = lookupCoordinates();
  std::vector<Vec4> values = test::sampleTextureOnDevice(deviceArrays, 0, uvs);
  Outliers o = outsideBound(texture.hostArrays(), uvs, values);
  EXPECT_EQ(o.count, 0u) << "first: " << o.first;
}

TEST(GpuTextureLookup, Unorm8AgreesWithTheHostForEveryWrapMode) {
  expectDeviceAgrees(TexelFormat::Unorm8, TextureWrap::Repeat, 4, false, 1);
  expectDeviceAgrees(TexelFormat::Unorm8, TextureWrap::Clamp, 4, false, 2);
  expectDeviceAgrees(TexelFormat::Unorm8, TextureWrap::Mirror, 4, false, 3);
}

TEST(GpuTextureLookup, SrgbAgreesWithTheHostForEveryWrapMode) {
  expectDeviceAgrees(TexelFormat::Unorm8, TextureWrap::Repeat, 4, true, 4);
  expectDeviceAgrees(TexelFormat::Unorm8, TextureWrap::Clamp, 4, true, 5);
  expectDeviceAgrees(TexelFormat::Unorm8, TextureWrap::Mirror, 4, true, 6);
}

TEST(GpuTextureLookup, FloatAgreesWithTheHostForEveryWrapMode) {
  expectDeviceAgrees(TexelFormat::Float32, TextureWrap::Repeat, 4, false, 7);
  expectDeviceAgrees(TexelFormat::Float32, TextureWrap::Clamp, 4, false, 8);
  expectDeviceAgrees(TexelFormat::Float32, TextureWrap::Mirror, 4, false, 9);
}

// glTF samplers give each axis its own mode (wrapS across, wrapT down).
TEST(GpuTextureLookup, WrapModesPerAxisAgreeWithTheHost) {
  expectDeviceAgrees(TexelFormat::Unorm8, TextureWrap::Repeat, 4, false, 40, TextureWrap::Clamp);
  expectDeviceAgrees(TexelFormat::Unorm8, TextureWrap::Clamp, 4, true, 41, TextureWrap::Mirror);
  expectDeviceAgrees(TexelFormat::Float32, TextureWrap::Mirror, 4, false, 42, TextureWrap::Repeat);
}

// Grey, grey + alpha and RGB images are widened to four channels the way the host reads them.
TEST(GpuTextureLookup, FewerChannelsAgreeWithTheHost) {
  for (uint32_t channels = 1; channels <= 3; ++channels) {
    expectDeviceAgrees(TexelFormat::Unorm8, TextureWrap::Repeat, channels, true, 10 + channels);
    expectDeviceAgrees(TexelFormat::Float32, TextureWrap::Clamp, channels, false, 20 + channels);
  }
}

// The bound is tight enough to catch the usual mistakes: host lookups with each mistake made fall outside it.
TEST(TextureLookupBound, RejectsCommonMistakes) {
  std::vector<Vec2> uvs = lookupCoordinates();
  TestTexture srgb = randomTexture(TexelFormat::Unorm8, TextureWrap::Mirror, 4, true, 30);
  auto lookups = [&](const TestTexture& t, auto&& transform) {
    std::vector<Vec4> values;
    for (Vec2 uv : uvs) values.push_back(sampleTexture(t.hostArrays(), 0, transform(uv)));
    return values;
  };
  auto mostlyRejected = [&](const std::vector<Vec4>& values) {
    return outsideBound(srgb.hostArrays(), uvs, values).count > uvs.size();  // of 4 channels per lookup
  };
  EXPECT_TRUE(mostlyRejected(lookups(srgb, [](Vec2 uv) { return Vec2{uv.x + 0.5f / kWidth, uv.y}; })));
  EXPECT_TRUE(mostlyRejected(lookups(srgb, [](Vec2 uv) { return Vec2{uv.x, 1.0f - uv.y}; })));
  TestTexture repeat = srgb;
  repeat.views[0].wrapU = repeat.views[0].wrapV = TextureWrap::Repeat;
  EXPECT_TRUE(mostlyRejected(lookups(repeat, [](Vec2 uv) { return uv; })));
  TestTexture linear = srgb;
  linear.views[0].srgb = 0;
  EXPECT_TRUE(mostlyRejected(lookups(linear, [](Vec2 uv) { return uv; })));
  EXPECT_FALSE(mostlyRejected(lookups(srgb, [](Vec2 uv) { return uv; })));
}

}  // namespace
}  // namespace candela
