#pragma once
// A frame as horizontal stripes, each an independent JPEG (libjpeg-turbo, 4:2:0), encoded at the same time on a
// small pool of threads, and the one binary message that carries them to a browser.
//
// The message, every number a little-endian uint32:
//   width, height, stripe count n,
//   n times: the stripe's first row, its byte length,
//   the n stripes' JPEG files, one after the other, in the order of the table.
// The stripes cover the rows top to bottom without gaps: stripe i+1 starts where stripe i ends, and each stripe's
// JPEG is width pixels wide and as tall as the rows up to the next stripe's first row (the last: up to height).
// A page draws a stripe with createImageBitmap(new Blob([bytes], {type: "image/jpeg"})) and drawImage at (0, first
// row); the stripes decode independently, in parallel where the browser can.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

struct JpegStripe {
  uint32_t firstRow = 0, rows = 0;
  std::string bytes;  // a whole JPEG file, width x rows pixels
};

struct StripedJpeg {
  uint32_t width = 0, height = 0;
  std::vector<JpegStripe> stripes;
  double milliseconds = 0.0;  // how long the encoding took, wall clock
};

// The rows of each stripe but the last, for an image `height` rows tall encoded by `threads` threads: a multiple
// of 16, so that a stripe boundary falls between the 16-row blocks of 4:2:0 JPEG (the stripes' pixels are encoded
// as the single JPEG's), with as many stripes as threads but none shorter than kMinStripeRows.
uint32_t jpegStripeRows(uint32_t height, unsigned threads);
constexpr uint32_t kMinStripeRows = 64;

// Encodes frames of 8-bit RGB pixels (three bytes a pixel, row-major, top row first) as stripes, on a pool of its
// own threads (a TBB arena; the calling thread works in it too). One encode at a time.
class StripedJpegEncoder {
 public:
  // `threads`: 0 for the hardware's threads, at most kMaxJpegThreads; the stripes are those of jpegStripeRows for
  // this many threads, and at most as many as TBB may run encode them at once.
  explicit StripedJpegEncoder(unsigned threads = 0);
  ~StripedJpegEncoder();
  StripedJpegEncoder(const StripedJpegEncoder&) = delete;
  StripedJpegEncoder& operator=(const StripedJpegEncoder&) = delete;

  unsigned threads() const;
  // `quality` 1 to 100, 4:2:0 chroma, libjpeg-turbo's fast DCT, as the single JPEG of a serve frame. Throws
  // std::invalid_argument for an empty frame, std::runtime_error with libjpeg-turbo's reason where it fails.
  StripedJpeg encode(const uint8_t* rgb, uint32_t width, uint32_t height, int quality);

 private:
  struct Pool;
  std::unique_ptr<Pool> pool_;
};

// More threads than this add stripes (their headers, the browser's decodes) faster than they save time.
constexpr unsigned kMaxJpegThreads = 16;

// The message above, and back; unpackStripedJpeg throws std::invalid_argument for bytes that are not such a
// message (its milliseconds are 0).
std::string packStripedJpeg(const StripedJpeg& jpeg);
StripedJpeg unpackStripedJpeg(std::string_view message);

}  // namespace candela
