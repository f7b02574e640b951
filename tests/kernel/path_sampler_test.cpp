// The path sampler's numbers: the Sobol kind's stratification (as pbrt-v4's samplers_test checks its samplers'
// elementary intervals), its independence across pixels and dimensions, and the independent kind's white noise.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <vector>

#include "core/path_sampler.h"
#include "support/chi2.h"

namespace candela {
namespace {

// The 2D numbers that sample `index` of `pixel` draws after `skip` 1D numbers.
Vec2 pairAt(uint32_t pixel, uint32_t index, uint32_t seed, uint32_t skip) {
  PathSampler sampler(pixel, index, seed, SamplerKind::Sobol);
  for (uint32_t i = 0; i < skip; ++i) sampler.next1D();
  return sampler.next2D();
}

float singleAt(uint32_t pixel, uint32_t index, uint32_t seed, uint32_t skip) {
  PathSampler sampler(pixel, index, seed, SamplerKind::Sobol);
  for (uint32_t i = 0; i < skip; ++i) sampler.next1D();
  return sampler.next1D();
}

// Whether `points` hold exactly one point in every elementary interval of area 1/points.size() (a (0,m,2)-net).
bool isZeroNet(const std::vector<Vec2>& points, std::string& why) {
  uint32_t m = 0;
  while ((1u << m) < points.size()) ++m;
  for (uint32_t xBits = 0; xBits <= m; ++xBits) {
    uint32_t yBits = m - xBits;
    std::vector<int> counts(size_t(1) << m, 0);
    for (Vec2 p : points) {
      uint32_t cx = uint32_t(p.x * float(1u << xBits)), cy = uint32_t(p.y * float(1u << yBits));
      ++counts[(size_t(cy) << xBits) | cx];
    }
    for (size_t c = 0; c < counts.size(); ++c)
      if (counts[c] != 1) {
        why = std::to_string(points.size()) + " points, intervals " + std::to_string(1u << xBits) + " x " +
              std::to_string(1u << yBits) + ": interval " + std::to_string(c) + " holds " + std::to_string(counts[c]);
        return false;
      }
  }
  return true;
}

TEST(SobolSequence, StartsWithTheKnownPoints) {
  const float x[] = {0.0f, 0.5f, 0.25f, 0.75f, 0.125f, 0.625f, 0.375f, 0.875f};
  const float y[] = {0.0f, 0.5f, 0.75f, 0.25f, 0.625f, 0.125f, 0.375f, 0.875f};
  for (uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(float(sobolDimension0(i)) * 0x1p-32f, x[i]) << i;
    EXPECT_EQ(float(sobolDimension1(i)) * 0x1p-32f, y[i]) << i;
  }
}

// The second dimension by its definition: the index's bits select columns v_k of the generator matrix, v_0 = 2^31
// and v_k = v_{k-1} ^ (v_{k-1} >> 1).
uint32_t sobolDimension1ByColumns(uint32_t index) {
  uint32_t result = 0;
  for (uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1u) result ^= v;
  return result;
}

TEST(SobolSequence, SecondDimensionMatchesItsGeneratorMatrix) {
  uint32_t index = 0;
  for (uint32_t i = 0; i < 100000; ++i, index = index * 1664525u + 1013904223u) {
    ASSERT_EQ(sobolDimension1(i), sobolDimension1ByColumns(i)) << i;
    ASSERT_EQ(sobolDimension1(index), sobolDimension1ByColumns(index)) << index;
  }
}

// The Sobol sampler's numbers by their definition, written as plainly as possible: bits reversed one at a time, the
// second dimension from its generator matrix's columns, Owen scrambling as reverse, hash (Burley 2020), reverse, and
// the top 24 bits as the float. The sampler computes them with reversals that cancel taken out (and a table on the
// host), so it is held to draw exactly these numbers.
uint32_t reverseBitsOneByOne(uint32_t v) {
  uint32_t r = 0;
  for (int bit = 0; bit < 32; ++bit) r |= ((v >> bit) & 1u) << (31 - bit);
  return r;
}

uint32_t owenScrambleByDefinition(uint32_t v, uint32_t seed) {
  uint32_t r = reverseBitsOneByOne(v) + seed;
  r ^= r * 0x6c50b47cu;
  r ^= r * 0xb82f1e52u;
  r ^= r * 0xc7afe638u;
  r ^= r * 0x8d22f6e6u;
  return reverseBitsOneByOne(r);
}

float unitFloatByDefinition(uint32_t bits) { return float(bits >> 8) / 16777216.0f; }

struct SobolSamplerByDefinition {
  uint32_t pixel, sampleIndex, seed;
  uint32_t dimension = 0;

  // The dimension's seeds in the sample's half (even or odd sample index), and the point's scrambled index there.
  Uint4 seedsOf(uint32_t d) const { return pcg4d({pixel, d, seed, 0x50B01u + (sampleIndex & 1u)}); }

  float next1D() {
    const Uint4 seeds = seedsOf(dimension++);
    const uint32_t index = owenScrambleByDefinition(sampleIndex / 2, seeds.x);
    return unitFloatByDefinition(owenScrambleByDefinition(reverseBitsOneByOne(index), seeds.y));
  }

  Vec2 next2D() {
    const Uint4 seeds = seedsOf(dimension);
    dimension += 2;
    const uint32_t index = owenScrambleByDefinition(sampleIndex / 2, seeds.x);
    return {unitFloatByDefinition(owenScrambleByDefinition(reverseBitsOneByOne(index), seeds.y)),
            unitFloatByDefinition(owenScrambleByDefinition(sobolDimension1ByColumns(index), seeds.z))};
  }
};

TEST(SobolSequence, ReversalsMatchTheOneBitAtATimeReversal) {
  uint32_t v = 1;
  for (uint32_t i = 0; i < 200000; ++i, v = v * 1664525u + 1013904223u)
    for (uint32_t value : {i, v, ~i, 1u << (i % 32)}) {
      ASSERT_EQ(reverseBits(value), reverseBitsOneByOne(value)) << value;
      ASSERT_EQ(reverseBitsHigh24(value), reverseBitsOneByOne(value) >> 8) << value;
      ASSERT_EQ(owenScramble(value, v), owenScrambleByDefinition(value, v)) << value;
    }
}

// Every number the sampler draws, 1D and 2D calls mixed, at small and large sample indices (each half, all 32 bits of
// the index), many pixels, seeds and path lengths, is the number of the definition, bit for bit.
TEST(SobolSampler, DrawsTheNumbersOfItsDefinition) {
  uint32_t state = 12345;
  auto next = [&state] { return state = state * 1664525u + 1013904223u; };
  for (uint32_t trial = 0; trial < 20000; ++trial) {
    const uint32_t pixel = next(), seed = trial % 5 == 0 ? 0u : next();
    const uint32_t sampleIndex = trial % 2 == 0 ? trial / 2 : next();
    const uint32_t pattern = next();
    PathSampler sampler(pixel, sampleIndex, seed, SamplerKind::Sobol);
    SobolSamplerByDefinition reference{pixel, sampleIndex, seed};
    for (uint32_t call = 0; call < 32; ++call) {
      const uint32_t d = reference.dimension;
      if ((pattern >> call) & 1u) {
        const Vec2 got = sampler.next2D(), expected = reference.next2D();
        ASSERT_EQ(got.x, expected.x) << "pixel " << pixel << ", sample " << sampleIndex << ", dimension " << d;
        ASSERT_EQ(got.y, expected.y) << "pixel " << pixel << ", sample " << sampleIndex << ", dimension " << d + 1;
      } else {
        ASSERT_EQ(sampler.next1D(), reference.next1D())
            << "pixel " << pixel << ", sample " << sampleIndex << ", dimension " << d;
      }
    }
  }
}

TEST(SobolSequence, OwenScramblingKeepsLeadingBitsTogether) {
  // Values that share their top k bits still share them after scrambling, whatever the seed.
  for (uint32_t seed : {0u, 1u, 0xDEADBEEFu}) {
    for (uint32_t k = 1; k <= 16; ++k) {
      uint32_t prefix = 0xA5A5A5A5u & ~(0xFFFFFFFFu >> k);
      uint32_t a = owenScramble(prefix | 0x1234u, seed), b = owenScramble(prefix | (0xFFFFFFFFu >> k), seed);
      EXPECT_EQ(a >> (32 - k), b >> (32 - k)) << "seed " << seed << ", " << k << " bits";
    }
  }
}

// Sample i of half h (0: even sample indices, 1: odd) of a pixel.
uint32_t halfIndex(uint32_t half, uint32_t i) { return 2 * i + half; }

// In each half of a pixel's samples, every power-of-two prefix, and every aligned block after it (accumulation that
// resumes), is a (0,m,2)-net in each 2D decision, for any pixel, seed and position in the path.
TEST(SobolSampler, EachPairIsAZeroTwoSequenceInEachHalf) {
  for (uint32_t half : {0u, 1u})
    for (uint32_t pixel : {0u, 7u, 123456u})
      for (uint32_t seed : {0u, 99u})
        for (uint32_t skip : {0u, 3u, 17u})
          for (uint32_t m = 0; m <= 10; ++m)
            for (uint32_t block : {0u, 1u, 5u}) {
              std::vector<Vec2> points;
              for (uint32_t i = 0; i < (1u << m); ++i)
                points.push_back(pairAt(pixel, halfIndex(half, (block << m) + i), seed, skip));
              std::string why;
              ASSERT_TRUE(isZeroNet(points, why)) << "half " << half << ", pixel " << pixel << ", seed " << seed
                                                  << ", after " << skip << " numbers, block " << block << ": " << why;
            }
}

TEST(SobolSampler, EachSingleNumberIsStratifiedInEachHalf) {
  for (uint32_t half : {0u, 1u})
    for (uint32_t pixel : {0u, 31u})
      for (uint32_t skip : {0u, 1u, 9u})
        for (uint32_t m = 0; m <= 12; ++m) {
          std::vector<int> counts(size_t(1) << m, 0);
          for (uint32_t i = 0; i < (1u << m); ++i)
            ++counts[size_t(singleAt(pixel, halfIndex(half, i), 5, skip) * float(1u << m))];
          for (size_t c = 0; c < counts.size(); ++c)
            ASSERT_EQ(counts[c], 1) << "half " << half << ", pixel " << pixel << ", dimension " << skip << ", "
                                    << (1u << m) << " samples";
        }
}

// The two halves are scrambled independently: over the scrambles (pixels), a half's number and the other half's
// number at the same point index fill the square uniformly. (Were the halves one net, or one scramble, they would
// not.)
TEST(SobolSampler, TheHalvesAreScrambledIndependently) {
  for (uint32_t skip : {0u, 4u}) {
    uint32_t counter = 0;
    test::Chi2Options options;
    options.binsX = options.binsY = 64;
    options.sampleCount = 400000;
    options.testCount = 2;
    auto sample = [&](double, double, double) -> std::optional<Vec2> {
      const uint32_t i = counter++, pixel = i / 16, point = i % 16;
      return Vec2{singleAt(pixel, halfIndex(0, point), 3, skip), singleAt(pixel, halfIndex(1, point), 3, skip)};
    };
    test::Chi2Result r = test::chi2TestSquare(
        sample, [](double, double) { return 1.0; }, options);
    EXPECT_TRUE(r.passed) << "after " << skip << " numbers: " << r.message;
  }
}

// A check that the net test above can fail: white noise is not a net.
TEST(SobolSampler, TheNetCheckRejectsWhiteNoise) {
  std::vector<Vec2> points;
  for (uint32_t i = 0; i < 256; ++i) {
    PathSampler sampler(3, i, 1, SamplerKind::Independent);
    points.push_back(sampler.next2D());
  }
  std::string why;
  EXPECT_FALSE(isZeroNet(points, why));
}

// Nets in each decision must not tie decisions together, or estimators of integrands that couple them would be
// biased: over the scrambles (pixels), pairs made of two 1D decisions, of halves of two 2D decisions, and of one
// decision in neighbouring pixels, fill the square uniformly. (Within one pixel the index shuffles that separate
// the dimensions are nested permutations, which leave a weak structure a fine enough grid can see; that is the
// price of a sequence that can be extended one sample at a time, as in Burley 2020 and Cycles.)
enum class Pairing { Dimensions, PairHalves, Pixels };

class SobolPairs : public ::testing::TestWithParam<Pairing> {};

TEST_P(SobolPairs, AreUniformOnTheSquare) {
  const Pairing pairing = GetParam();
  const uint32_t pixels[] = {17, 1000, 999999};
  for (uint32_t pixel : pixels) {
    uint32_t counter = 0;
    test::Chi2Options options;
    options.binsX = options.binsY = 64;
    options.sampleCount = 400000;
    options.testCount = 3 * int(std::size(pixels));
    auto sample = [&](double, double, double) -> std::optional<Vec2> {
      uint32_t i = counter++;
      uint32_t p = pixel + i / 64, index = i % 64;
      switch (pairing) {
        case Pairing::Dimensions: return Vec2{singleAt(p, index, 3, 4), singleAt(p, index, 3, 5)};
        case Pairing::PairHalves: return Vec2{pairAt(p, index, 3, 0).x, pairAt(p, index, 3, 2).y};
        case Pairing::Pixels: return Vec2{singleAt(pixel + 2 * i, 9, 3, 0), singleAt(pixel + 2 * i + 1, 9, 3, 0)};
      }
      return std::nullopt;
    };
    test::Chi2Result r = test::chi2TestSquare(
        sample, [](double, double) { return 1.0; }, options);
    EXPECT_TRUE(r.passed) << "pixel " << pixel << ": " << r.message;
  }
}

INSTANTIATE_TEST_SUITE_P(Sobol, SobolPairs,
                         ::testing::Values(Pairing::Dimensions, Pairing::PairHalves, Pairing::Pixels));

TEST(IndependentSampler, WalksConsecutiveDimensionsOfTheHash) {
  PathSampler sampler(3, 4, 5, SamplerKind::Independent);
  for (uint32_t d = 0; d < 16; d += 4) {
    EXPECT_EQ(sampler.next1D(), randomUniform(3, 4, d, 5));
    EXPECT_EQ(sampler.next1D(), randomUniform(3, 4, d + 1, 5));
    Vec2 pair = sampler.next2D();
    EXPECT_EQ(pair.x, randomUniform(3, 4, d + 2, 5));
    EXPECT_EQ(pair.y, randomUniform(3, 4, d + 3, 5));
  }
}

TEST(PathSampler, NumbersStayInTheUnitInterval) {
  for (SamplerKind kind : {SamplerKind::Sobol, SamplerKind::Independent})
    for (uint32_t i = 0; i < 20000; ++i) {
      PathSampler sampler(i * 2654435761u, i, i % 7u, kind);
      for (int d = 0; d < 4; ++d) {
        float u = sampler.next1D();
        Vec2 p = sampler.next2D();
        ASSERT_TRUE(u >= 0.0f && u < 1.0f && p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f);
      }
    }
}

}  // namespace
}  // namespace candela
