// The CPU a-trous filter's contract, the shared fast exponential, tone mapping and AOV files.
#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "image/filters/atrous.h"
#include "image/filters/atrous_kernel.h"
#include "image/filters/fast_exp.h"
#include "image/tonemap.h"
#include "io/images/aov_io.h"

namespace candela {
namespace {

struct NoisyInput {
  Image color;
  AovImages aovs;
};

NoisyInput randomInput(uint32_t w, uint32_t h, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  NoisyInput in{Image(w, h), AovImages(w, h)};
  for (size_t i = 0; i < in.color.pixels.size(); ++i) {
    in.color.pixels[i] = {4.0f * u(rng), 4.0f * u(rng), 4.0f * u(rng)};
    in.aovs.albedo.pixels[i] = {u(rng), u(rng), u(rng)};
    in.aovs.normal.pixels[i] = normalize(Vec3{u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f});
    in.aovs.depth[i] = u(rng) < 0.1f ? 0.0f : 1.0f + u(rng);
  }
  return in;
}

double worstRelativeDifference(const Image& a, const Image& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::fmax(worst, std::fabs(double(a.pixels[i][c]) - b.pixels[i][c]) /
                                   std::fmax(1e-3, std::fabs(b.pixels[i][c])));
  return worst;
}

TEST(Atrous, NoPassesGiveTheImageBack) {
  const NoisyInput in = randomInput(13, 9, 1);
  AtrousParams params;
  params.passes = 0;
  EXPECT_LE(worstRelativeDifference(atrousDenoise(in.color, in.aovs, params), in.color), 1e-6);
}

// The weights are normalised: a constant colour over a constant albedo stays, whatever the guides say.
TEST(Atrous, KeepsAConstantImage) {
  NoisyInput in = randomInput(37, 29, 2);
  for (Vec3& c : in.color.pixels) c = {0.3f, 0.6f, 0.9f};
  for (Vec3& a : in.aovs.albedo.pixels) a = {0.5f, 0.5f, 0.5f};
  const Image out = atrousDenoise(in.color, in.aovs, AtrousParams{});
  EXPECT_LE(worstRelativeDifference(out, in.color), 1e-5);
}

// Colour differences remain where the guides say that surfaces differ: a step in the normals keeps a step in
// the colour, which the same filter blind to normals smooths.
TEST(Atrous, NormalsStopTheFilter) {
  const uint32_t w = 32, h = 16;
  NoisyInput in{Image(w, h), AovImages(w, h)};
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      in.color.pixels[i] = x < w / 2 ? Vec3{1, 1, 1} : Vec3{0.5f, 0.5f, 0.5f};
      in.aovs.albedo.pixels[i] = {1, 1, 1};
      in.aovs.normal.pixels[i] = x < w / 2 ? Vec3{0, 0, -1} : Vec3{1, 0, 0};
      in.aovs.depth[i] = 2.0f;
    }
  AtrousParams params;
  params.colorSigma = 1e3f;  // only the normals may stop it
  params.normalSigma = 0.2f;
  const Image guided = atrousDenoise(in.color, in.aovs, params);
  EXPECT_NEAR(guided.at(w / 2 - 1, h / 2).x, 1.0f, 1e-3f);
  EXPECT_NEAR(guided.at(w / 2, h / 2).x, 0.5f, 1e-3f);
  params.normalSigma = 1e3f;
  const Image blind = atrousDenoise(in.color, in.aovs, params);
  EXPECT_LT(blind.at(w / 2 - 1, h / 2).x, 0.9f);
}

TEST(Atrous, RejectsBadInput) {
  const NoisyInput in = randomInput(8, 8, 3);
  AtrousParams params;
  params.passes = kMaxAtrousPasses + 1;
  EXPECT_THROW(atrousDenoise(in.color, in.aovs, params), std::invalid_argument);
  params = {};
  params.normalSigma = 0.0f;
  EXPECT_THROW(atrousDenoise(in.color, in.aovs, params), std::invalid_argument);
  const NoisyInput other = randomInput(8, 7, 3);
  EXPECT_THROW(atrousDenoise(in.color, other.aovs, AtrousParams{}), std::invalid_argument);
}

// A flat lit plane (albedo 0.7, radiance 0.7) with an 8x8 emitter of albedo zero and radiance (17, 12, 4) in it, all
// seen directly, with no variance known (as after one sample): the emitter's light is no reflected light. Divided
// by its zero albedo and multiplied back by the plane's, it made the plane next to it far brighter than the light.
// Kept apart and filtered on its own, the emission is smoothed only across the emitter's edge, as the filter smooths
// the noise of pixels that straddle an edge: the pixels on either side of the edge mix, the rest keep their values.
TEST(AtrousEmission, ABlackEmitterDoesNotSpreadIntoItsNeighbours) {
  const uint32_t w = 24, h = 24;
  NoisyInput in{Image(w, h), AovImages(w, h)};
  const Vec3 light{17, 12, 4};
  auto inside = [](uint32_t x, uint32_t y, uint32_t margin) {
    return x >= 8 + margin && x < 16 - margin && y >= 8 + margin && y < 16 - margin;
  };
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const bool emitter = inside(x, y, 0);
      in.color.pixels[i] = emitter ? light : Vec3{0.7f, 0.7f, 0.7f};
      in.aovs.emission.pixels[i] = emitter ? light : Vec3{};
      in.aovs.albedo.pixels[i] = emitter ? Vec3{} : Vec3{0.7f, 0.7f, 0.7f};
      in.aovs.normal.pixels[i] = {0, 0, -1};
      in.aovs.depth[i] = 1.0f;
    }
  const Image out = atrousDenoise(in.color, in.aovs, AtrousParams{});
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const float r = out.at(x, y).x;
      const bool pastTheEdge = x + 1 >= 8 && x < 17 && y + 1 >= 8 && y < 17 && !inside(x, y, 0);
      if (inside(x, y, 1))
        EXPECT_NEAR(r, light.x, 0.05f * light.x) << x << ", " << y;
      else if (inside(x, y, 0))
        EXPECT_GT(r, 0.25f * light.x) << x << ", " << y;  // on the emitter's edge
      else if (pastTheEdge)
        EXPECT_LT(r, 0.7f + 1.0f) << x << ", " << y;
      else
        EXPECT_NEAR(r, 0.7f, 0.05f * 0.7f) << x << ", " << y;
    }
}

// A glint (a 2x2 block of radiance 200 to 500, reflected light, beside pixels of about 0.5) on a noisy flat plane:
// the colour weights must not smear it into a halo. Pixels beyond the ring around it stay within the plane's noise
// (0.5 +- 30%), whether the variance is unknown (one sample) or known (here a noise of 0.05 and the glint's own).
// With the variance known the glint also keeps most of its light: the filter's loss there is more than its noise
// explains, and the raw value stays.
TEST(AtrousHdr, AGlintDoesNotSmearIntoAHalo) {
  const uint32_t w = 33, h = 33;
  NoisyInput in{Image(w, h), AovImages(w, h)};
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (size_t i = 0; i < in.color.pixels.size(); ++i) {
    const float v = 0.5f * (0.7f + 0.6f * u(rng));
    in.color.pixels[i] = {v, v, v};
    in.aovs.albedo.pixels[i] = {0.5f, 0.5f, 0.5f};
    in.aovs.normal.pixels[i] = {0, 0, -1};
    in.aovs.depth[i] = 1.0f;
  }
  const float glint[2][2] = {{500, 300}, {400, 200}};
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 2; ++x) in.color.at(16 + x, 16 + y) = Vec3{1, 1, 1} * glint[y][x];
  for (bool known : {false, true}) {
    if (known)
      for (size_t i = 0; i < in.aovs.variance.size(); ++i) {
        const float v = in.color.pixels[i].x;
        in.aovs.variance[i] = v > 100.0f ? 0.25f * v * v : 0.0025f;
      }
    const Image out = atrousDenoise(in.color, in.aovs, AtrousParams{});
    float glintSum = 0.0f;
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        const bool ring = x >= 15 && x <= 18 && y >= 15 && y <= 18;
        if (ring && x >= 16 && x <= 17 && y >= 16 && y <= 17) glintSum += out.at(x, y).x;
        if (!ring) {
          EXPECT_NEAR(out.at(x, y).x, 0.5f, 0.16f) << x << ", " << y;
        }
      }
    if (known) {
      EXPECT_GT(glintSum, 0.5f * 1400.0f);
    }
  }
}

// Two signals filtered together (their guide terms computed once for both) come out as each filtered alone: where
// both are non-zero, where one is zero in whole rows or columns (it skips them alone), and with the first pass's
// variance and the first level given for the first signal only.
TEST(AtrousWorkspace, TwoSignalsFilterAsEachAlone) {
  const uint32_t w = 61, h = 47;
  const NoisyInput in = randomInput(w, h, 9);
  std::mt19937 rng(10);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Vec3> first(size_t(w) * h), second(size_t(w) * h);
  std::vector<float> variance(size_t(w) * h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      first[i] = y < 30 ? Vec3{u(rng), 2.0f * u(rng), u(rng)} : Vec3{};
      second[i] = y > 40 && x > 20 && x < 40 ? Vec3{5.0f * u(rng), u(rng), 3.0f * u(rng)} : Vec3{};
      variance[i] = u(rng) < 0.3f ? -1.0f : u(rng);
    }
  AtrousParams params;
  params.passes = 4;
  auto read = [&](const RgbPlanes& planes) {
    std::vector<Vec3> out(first.size());
    for (size_t i = 0; i < out.size(); ++i) out[i] = planes.get(i);
    return out;
  };
  auto filterAlone = [&](const std::vector<Vec3>& signal, const float* firstPassVariance,
                         std::vector<Vec3>* firstLevel) {
    AtrousWorkspace workspace;
    workspace.setGuides(in.aovs);
    for (size_t i = 0; i < signal.size(); ++i) workspace.signal(0).set(i, signal[i]);
    const auto out = workspace.runPasses(
        params, 1, [&](const RgbPlanes& level) { *firstLevel = read(level); }, firstPassVariance);
    return read(out[0]);
  };
  std::vector<Vec3> firstLevelAlone, secondLevel, firstLevelTogether;
  const std::vector<Vec3> firstAlone = filterAlone(first, variance.data(), &firstLevelAlone);
  const std::vector<Vec3> secondAlone = filterAlone(second, nullptr, &secondLevel);
  AtrousWorkspace workspace;
  workspace.setGuides(in.aovs);
  for (size_t i = 0; i < first.size(); ++i) {
    workspace.signal(0).set(i, first[i]);
    workspace.signal(1).set(i, second[i]);
  }
  const auto together = workspace.runPasses(
      params, 2, [&](const RgbPlanes& level) { firstLevelTogether = read(level); }, variance.data());
  const std::vector<Vec3> firstTogether = read(together[0]), secondTogether = read(together[1]);
  int zeroRowsOfTheSecond = 0;
  for (size_t i = 0; i < first.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(firstTogether[i][c], firstAlone[i][c], 1e-5f * std::fabs(firstAlone[i][c])) << i;
      EXPECT_NEAR(secondTogether[i][c], secondAlone[i][c], 1e-5f * std::fabs(secondAlone[i][c])) << i;
      EXPECT_NEAR(firstLevelTogether[i][c], firstLevelAlone[i][c], 1e-5f * std::fabs(firstLevelAlone[i][c])) << i;
      if (c == 0 && i < 5 * w && secondAlone[i][c] == 0.0f && secondTogether[i][c] == 0.0f) ++zeroRowsOfTheSecond;
    }
  EXPECT_EQ(zeroRowsOfTheSecond, 5 * int(w));  // beyond the four passes' reach (30 rows) of its first non-zero one
}

TEST(Atrous, InteriorVarianceIsTheGeneralOne) {
  constexpr int w = 7, h = 5;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 10.0f);
  std::vector<float> lum(size_t(w) * h);
  for (float& l : lum) l = u(rng);
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      const float* row = &lum[size_t(y) * w];
      EXPECT_FLOAT_EQ(interiorLuminanceVariance(row - w, row, row + w, x),
                      localLuminanceVariance(lum.data(), w, h, x, y))
          << x << ", " << y;
    }
  // A variance the binomial weights give exactly: a bright centre of 16 among zeros has mean 4*16/16 = 4 and mean
  // square 4*256/16 = 64.
  std::vector<float> spike(9, 0.0f);
  spike[4] = 16.0f;
  EXPECT_FLOAT_EQ(interiorLuminanceVariance(&spike[0], &spike[3], &spike[6], 1), 64.0f - 16.0f);
}

// The variance for the mix with the raw pixel is the sample-variance bound scaled by the neighbourhood's ratio of
// the halves' estimate to it: down where the halves agree better than the bound says (stratified samples), never
// up, and not at all where either is unknown.
TEST(AtrousVariance, TheHalvesScaleTheBoundDownOverTheNeighbourhood) {
  const int w = 9, h = 9;
  std::vector<float> bound(size_t(w) * h, 2.0f), halves(size_t(w) * h, 0.5f);
  bound[4 * w + 4] = 4.0f;  // the centre's own bound is kept, scaled
  auto at = [&](const std::vector<float>& v) { return [&v, w](int x, int y) { return v[size_t(y) * w + x]; }; };
  // 25 pixels: halves 12.5, bounds 24 * 2 + 4 = 52.
  EXPECT_NEAR(stratifiedVariance(at(bound), at(halves), w, h, 4, 4), 4.0f * 12.5f / 52.0f, 1e-6f);
  // At a corner only the 3x3 inside the image count: ratio 0.25.
  EXPECT_NEAR(stratifiedVariance(at(bound), at(halves), w, h, 0, 0), 0.5f, 1e-6f);
  std::fill(halves.begin(), halves.end(), 8.0f);
  EXPECT_EQ(stratifiedVariance(at(bound), at(halves), w, h, 4, 4), 4.0f);
  std::fill(halves.begin(), halves.end(), kUnknownVariance);
  EXPECT_EQ(stratifiedVariance(at(bound), at(halves), w, h, 4, 4), 4.0f);
  bound[4 * w + 4] = kUnknownVariance;
  EXPECT_EQ(stratifiedVariance(at(bound), at(halves), w, h, 4, 4), kUnknownVariance);
}

TEST(FastExp, MatchesTheLibraryExponential) {
  double worst = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const float x = -80.0f * float(i) / 200000.0f;
    worst = std::fmax(worst, std::fabs(double(fastExpNonPositive(x)) / std::exp(double(x)) - 1.0));
  }
  EXPECT_LE(worst, 5e-7);
  EXPECT_EQ(fastExpNonPositive(0.0f), 1.0f);
  EXPECT_LT(fastExpNonPositive(-1e30f), 1e-37f);
  EXPECT_LT(fastExpNonPositive(-std::numeric_limits<float>::infinity()), 1e-37f);
}

TEST(ToneMapping, CurvesAndExposure) {
  // Reinhard maps 1 to 1/2; sRGB encodes 1/2 as 0.7354.
  EXPECT_NEAR(toneMap({1, 1, 1}, 0.0f, ToneMapper::Reinhard).x, 0.735357f, 1e-5f);
  // Exposure in stops scales before the curve: 0.25 at +2 stops is 1, which clamp keeps as 1.
  EXPECT_NEAR(toneMap({0.25f, 0.25f, 0.25f}, 2.0f, ToneMapper::Clamp).x, 1.0f, 1e-6f);
  EXPECT_NEAR(toneMap({4, 4, 4}, 0.0f, ToneMapper::Clamp).x, 1.0f, 1e-6f);
  // ACES filmic (Narkowicz): 0.18 -> 0.2669 before sRGB.
  EXPECT_NEAR(acesFilmic(0.18f), 0.18f * (2.51f * 0.18f + 0.03f) / (0.18f * (2.43f * 0.18f + 0.59f) + 0.14f), 1e-7f);
  for (ToneMapper m : {ToneMapper::AcesFilmic, ToneMapper::Clamp, ToneMapper::Reinhard}) {
    EXPECT_EQ(parseToneMapper(toneMapperName(m)), m);
    float previous = -1.0f;
    for (float v = 0.0f; v < 64.0f; v = v * 1.5f + 0.01f) {
      const float out = toneMap({v, v, v}, 0.0f, m).x;
      EXPECT_GE(out, previous) << toneMapperName(m) << " is monotonic";
      EXPECT_LE(out, 1.0f);
      previous = out;
    }
  }
  EXPECT_THROW(parseToneMapper("filmic"), std::invalid_argument);
}

TEST(AovFiles, ParseTheList) {
  EXPECT_EQ(parseAovList("depth,albedo"), (std::vector<Aov>{Aov::Depth, Aov::Albedo}));
  EXPECT_THROW(parseAovList("albedo,"), std::invalid_argument);
  EXPECT_THROW(parseAovList("albedo,albedo"), std::invalid_argument);
  EXPECT_THROW(parseAovList("position"), std::invalid_argument);
}

TEST(AovFiles, ExrHoldsTheAovsAsLayers) {
  const NoisyInput in = randomInput(5, 4, 4);
  const std::string path = (std::filesystem::temp_directory_path() / "candela_aov_test.exr").string();
  const std::vector<std::string> written =
      writeImageWithAovs(path, in.color, {}, in.aovs, {Aov::Albedo, Aov::Normal, Aov::Depth});
  EXPECT_EQ(written, std::vector<std::string>{path});
  Imf::InputFile file(path.c_str());
  std::vector<float> values(20);
  for (const char* name : {"R", "albedo.G", "normal.Z", "Z"}) {
    ASSERT_NE(file.header().channels().findChannel(name), nullptr) << name;
    Imf::FrameBuffer fb;
    fb.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float), 5 * sizeof(float)));
    file.setFrameBuffer(fb);
    file.readPixels(0, 3);
    const std::string n = name;
    for (size_t i = 0; i < 20; ++i) {
      const float expected = n == "R"          ? in.color.pixels[i].x
                             : n == "albedo.G" ? in.aovs.albedo.pixels[i].y
                             : n == "normal.Z" ? in.aovs.normal.pixels[i].z
                                               : in.aovs.depth[i];
      EXPECT_EQ(values[i], expected) << name << " pixel " << i;
    }
  }
  std::filesystem::remove(path);
}

TEST(AovFiles, PngAndPfmGoBesideTheImage) {
  const NoisyInput in = randomInput(5, 4, 5);
  const auto dir = std::filesystem::temp_directory_path();
  for (const char* ext : {".png", ".pfm"}) {
    const std::string path = (dir / (std::string("candela_aov_test") + ext)).string();
    const std::vector<std::string> written = writeImageWithAovs(path, in.color, {}, in.aovs, {Aov::Normal, Aov::Depth});
    ASSERT_EQ(written.size(), 3u);
    EXPECT_EQ(written[1], (dir / (std::string("candela_aov_test.normal") + ext)).string());
    EXPECT_EQ(written[2], (dir / (std::string("candela_aov_test.depth") + ext)).string());
    for (const std::string& p : written) {
      EXPECT_GT(std::filesystem::file_size(p), 0u) << p;
      std::filesystem::remove(p);
    }
  }
}

}  // namespace
}  // namespace candela
