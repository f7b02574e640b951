// Striped JPEG frames (io/images/striped_jpeg.h): the stripes' sizes, their decoding (with libjpeg-turbo's
// decompressor) against the single JPEG of the same pixels, and the message that carries them.
#include <gtest/gtest.h>
#include <turbojpeg.h>

#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/images/striped_jpeg.h"

namespace candela {
namespace {

// A frame with what a rendered one has: smooth gradients, hard edges and some noise.
std::vector<uint8_t> testFrame(uint32_t w, uint32_t h) {
  std::mt19937 rng(1);
  std::normal_distribution<float> noise(0.0f, 6.0f);
  std::vector<uint8_t> rgb(size_t(w) * h * 3);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const float dx = float(x) - 0.4f * float(w), dy = float(y) - 0.5f * float(h);
      const bool disc = dx * dx + dy * dy < 0.09f * float(h * h);
      const float base[3] = {255.0f * float(x) / float(w), 255.0f * float(y) / float(h), disc ? 230.0f : 40.0f};
      for (int c = 0; c < 3; ++c)
        rgb[(size_t(y) * w + x) * 3 + c] = uint8_t(std::fmin(255.0f, std::fmax(0.0f, base[c] + noise(rng))));
    }
  return rgb;
}

using Decompressor = std::unique_ptr<void, int (*)(tjhandle)>;

// Decodes `jpeg` into rows [firstRow, firstRow + rows) of `rgb`, checking its size.
void decodeInto(const std::string& jpeg, uint32_t width, uint32_t firstRow, uint32_t rows, std::vector<uint8_t>& rgb) {
  Decompressor d(tjInitDecompress(), tjDestroy);
  int w = 0, h = 0, subsampling = 0, colorspace = 0;
  auto* bytes = reinterpret_cast<const unsigned char*>(jpeg.data());
  ASSERT_EQ(tjDecompressHeader3(d.get(), bytes, jpeg.size(), &w, &h, &subsampling, &colorspace), 0);
  ASSERT_EQ(uint32_t(w), width);
  ASSERT_EQ(uint32_t(h), rows);
  EXPECT_EQ(subsampling, TJSAMP_420);
  ASSERT_EQ(tjDecompress2(d.get(), bytes, jpeg.size(), rgb.data() + size_t(firstRow) * width * 3, w, 0, h, TJPF_RGB, 0),
            0);
}

std::string singleJpeg(const std::vector<uint8_t>& rgb, uint32_t w, uint32_t h, int quality) {
  std::unique_ptr<void, int (*)(tjhandle)> c(tjInitCompress(), tjDestroy);
  unsigned char* jpeg = nullptr;
  unsigned long size = 0;
  EXPECT_EQ(tjCompress2(c.get(), rgb.data(), int(w), 0, int(h), TJPF_RGB, &jpeg, &size, TJSAMP_420, quality,
                        TJFLAG_FASTDCT),
            0);
  std::string bytes(reinterpret_cast<const char*>(jpeg), size);
  tjFree(jpeg);
  return bytes;
}

double psnr(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  double squares = 0.0;
  for (size_t i = 0; i < a.size(); ++i) squares += double(int(a[i]) - int(b[i])) * double(int(a[i]) - int(b[i]));
  return 10.0 * std::log10(255.0 * 255.0 / (squares / double(a.size())));
}

TEST(JpegStripes, AreMultiplesOf16RowsOnePerThread) {
  EXPECT_EQ(jpegStripeRows(720, 2), 368u);
  EXPECT_EQ(jpegStripeRows(1080, 16), 80u);  // 14 stripes
  EXPECT_EQ(jpegStripeRows(1080, 8), 144u);  // 8 stripes, the last 72 rows
  EXPECT_EQ(jpegStripeRows(200, 16), 80u);   // no stripe below kMinStripeRows: 3
  EXPECT_EQ(jpegStripeRows(40, 4), 48u);     // one stripe
  for (uint32_t height : {16u, 17u, 100u, 719u, 2160u})
    for (unsigned threads : {1u, 3u, 16u}) {
      const uint32_t rows = jpegStripeRows(height, threads);
      EXPECT_EQ(rows % 16, 0u);
      EXPECT_LE((height + rows - 1) / rows, std::max(threads, 1u));
    }
}

// The stripes end at 16-row block boundaries, so each is encoded as that part of the single JPEG; only the
// decoder's chroma upsampling across a boundary differs. The decoded stripes are at most 0.1 dB further from the
// pixels than the single JPEG.
TEST(StripedJpeg, DecodesAsTheSingleJpeg) {
  const uint32_t w = 640, h = 360;
  const std::vector<uint8_t> rgb = testFrame(w, h);
  StripedJpegEncoder encoder(4);
  EXPECT_EQ(encoder.threads(), 4u);
  for (int quality : {35, 70, 92}) {
    const StripedJpeg striped = encoder.encode(rgb.data(), w, h, quality);
    ASSERT_EQ(striped.stripes.size(), 4u);
    EXPECT_GE(striped.milliseconds, 0.0);
    std::vector<uint8_t> decoded(rgb.size()), single(rgb.size());
    uint32_t nextRow = 0;
    for (const JpegStripe& stripe : striped.stripes) {
      EXPECT_EQ(stripe.firstRow, nextRow);
      nextRow += stripe.rows;
      decodeInto(stripe.bytes, w, stripe.firstRow, stripe.rows, decoded);
    }
    EXPECT_EQ(nextRow, h);
    decodeInto(singleJpeg(rgb, w, h, quality), w, 0, h, single);
    const double stripedPsnr = psnr(rgb, decoded), singlePsnr = psnr(rgb, single);
    EXPECT_GE(stripedPsnr, singlePsnr - 0.1) << "quality " << quality;
    EXPECT_GT(singlePsnr, 25.0);
    // The same frame again gives the same bytes, whichever thread took which stripe.
    const StripedJpeg again = encoder.encode(rgb.data(), w, h, quality);
    for (size_t i = 0; i < again.stripes.size(); ++i) EXPECT_EQ(again.stripes[i].bytes, striped.stripes[i].bytes);
  }
}

TEST(StripedJpeg, OneThreadOneStripe) {
  const std::vector<uint8_t> rgb = testFrame(96, 50);
  const StripedJpeg striped = StripedJpegEncoder(1).encode(rgb.data(), 96, 50, 80);
  ASSERT_EQ(striped.stripes.size(), 1u);
  EXPECT_EQ(striped.stripes[0].rows, 50u);
  EXPECT_THROW(StripedJpegEncoder(1).encode(rgb.data(), 0, 50, 80), std::invalid_argument);
}

TEST(StripedJpegMessage, RoundTrips) {
  const std::vector<uint8_t> rgb = testFrame(200, 300);
  const StripedJpeg striped = StripedJpegEncoder(3).encode(rgb.data(), 200, 300, 75);
  ASSERT_EQ(striped.stripes.size(), 3u);
  const std::string message = packStripedJpeg(striped);
  size_t payload = 0;
  for (const JpegStripe& s : striped.stripes) payload += s.bytes.size();
  EXPECT_EQ(message.size(), 12 + 8 * 3 + payload);
  const StripedJpeg back = unpackStripedJpeg(message);
  EXPECT_EQ(back.width, 200u);
  EXPECT_EQ(back.height, 300u);
  ASSERT_EQ(back.stripes.size(), striped.stripes.size());
  for (size_t i = 0; i < back.stripes.size(); ++i) {
    EXPECT_EQ(back.stripes[i].firstRow, striped.stripes[i].firstRow);
    EXPECT_EQ(back.stripes[i].rows, striped.stripes[i].rows);
    EXPECT_EQ(back.stripes[i].bytes, striped.stripes[i].bytes);
  }
}

TEST(StripedJpegMessage, RefusesWhatIsNotOne) {
  const std::vector<uint8_t> rgb = testFrame(64, 160);
  const std::string message = packStripedJpeg(StripedJpegEncoder(2).encode(rgb.data(), 64, 160, 75));
  EXPECT_THROW(unpackStripedJpeg(message.substr(0, 11)), std::invalid_argument);
  EXPECT_THROW(unpackStripedJpeg(message.substr(0, message.size() - 1)), std::invalid_argument);
  EXPECT_THROW(unpackStripedJpeg(message + "x"), std::invalid_argument);
  std::string unordered = message;
  unordered[20] = char(200);  // the second stripe's first row past the height
  EXPECT_THROW(unpackStripedJpeg(unordered), std::invalid_argument);
  std::string none = message;
  none[8] = 0;  // no stripes
  EXPECT_THROW(unpackStripedJpeg(none), std::invalid_argument);
}

}  // namespace
}  // namespace candela
