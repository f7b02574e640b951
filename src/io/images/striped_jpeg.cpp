#include "io/images/striped_jpeg.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <turbojpeg.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace candela {

namespace {

// A libjpeg-turbo compressor with an output buffer large enough for any stripe it has encoded, kept from frame to
// frame: a fresh buffer a frame would cost its allocation and page faults every time.
class StripeCompressor {
 public:
  StripeCompressor() : handle_(tjInitCompress()) {
    if (!handle_) throw std::runtime_error(std::string("libjpeg-turbo: ") + tjGetErrorStr());
  }
  ~StripeCompressor() {
    tjFree(buffer_);
    tjDestroy(handle_);
  }
  StripeCompressor(const StripeCompressor&) = delete;
  StripeCompressor& operator=(const StripeCompressor&) = delete;

  std::string encode(const uint8_t* rgb, uint32_t width, uint32_t rows, int quality) {
    const unsigned long capacity = tjBufSize(int(width), int(rows), TJSAMP_420);
    if (capacity > capacity_) {
      tjFree(buffer_);
      capacity_ = 0;
      buffer_ = tjAlloc(int(capacity));
      if (!buffer_) throw std::runtime_error("libjpeg-turbo: no memory for a stripe's JPEG");
      capacity_ = capacity;
    }
    unsigned long size = capacity_;
    // 4:2:0 chroma halves the bytes of a frame; the eye misses the colour detail in a moving picture.
    if (tjCompress2(handle_, rgb, int(width), 0, int(rows), TJPF_RGB, &buffer_, &size, TJSAMP_420, quality,
                    TJFLAG_FASTDCT | TJFLAG_NOREALLOC) != 0)
      throw std::runtime_error(std::string("libjpeg-turbo: ") + tjGetErrorStr2(handle_));
    return std::string(reinterpret_cast<const char*>(buffer_), size);
  }

 private:
  tjhandle handle_;
  unsigned char* buffer_ = nullptr;
  unsigned long capacity_ = 0;
};

unsigned poolThreads(unsigned requested) {
  const unsigned threads = requested ? requested : std::max(1u, std::thread::hardware_concurrency());
  return std::min(threads, kMaxJpegThreads);
}

void putUint32(std::string& out, uint32_t value) {
  for (int i = 0; i < 4; ++i) out.push_back(char((value >> (8 * i)) & 0xffu));
}

uint32_t getUint32(std::string_view bytes, size_t offset) {
  uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value |= uint32_t(uint8_t(bytes[offset + i])) << (8 * i);
  return value;
}

}  // namespace

uint32_t jpegStripeRows(uint32_t height, unsigned threads) {
  const uint32_t stripes = std::max(1u, std::min(uint32_t(std::max(threads, 1u)), height / kMinStripeRows));
  const uint32_t rows = (height + stripes - 1) / stripes;
  return std::max(16u, (rows + 15) / 16 * 16);
}

// One compressor per stripe: stripe i is always encoded with compressor i, whichever thread runs it. The arena
// takes no more threads than TBB may run (the cores, or what `--threads` allowed), which leaves the stripes as
// they are and keeps TBB from warning about a request it cannot meet.
struct StripedJpegEncoder::Pool {
  explicit Pool(unsigned stripeThreads)
      : threads(stripeThreads),
        arena(int(std::min<size_t>(stripeThreads,
                                   tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)))) {}
  unsigned threads;
  tbb::task_arena arena;
  std::vector<std::unique_ptr<StripeCompressor>> compressors;
};

StripedJpegEncoder::StripedJpegEncoder(unsigned threads) : pool_(std::make_unique<Pool>(poolThreads(threads))) {}

StripedJpegEncoder::~StripedJpegEncoder() = default;

unsigned StripedJpegEncoder::threads() const { return pool_->threads; }

StripedJpeg StripedJpegEncoder::encode(const uint8_t* rgb, uint32_t width, uint32_t height, int quality) {
  if (width == 0 || height == 0) throw std::invalid_argument("a JPEG of no pixels");
  const auto start = std::chrono::steady_clock::now();
  const uint32_t stripeRows = jpegStripeRows(height, threads());
  StripedJpeg jpeg;
  jpeg.width = width;
  jpeg.height = height;
  for (uint32_t first = 0; first < height; first += stripeRows)
    jpeg.stripes.push_back({first, std::min(stripeRows, height - first), {}});
  while (pool_->compressors.size() < jpeg.stripes.size())
    pool_->compressors.push_back(std::make_unique<StripeCompressor>());
  pool_->arena.execute([&] {
    tbb::parallel_for(size_t(0), jpeg.stripes.size(), [&](size_t i) {
      JpegStripe& stripe = jpeg.stripes[i];
      stripe.bytes =
          pool_->compressors[i]->encode(rgb + size_t(stripe.firstRow) * width * 3, width, stripe.rows, quality);
    });
  });
  jpeg.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return jpeg;
}

std::string packStripedJpeg(const StripedJpeg& jpeg) {
  size_t bytes = 12 + 8 * jpeg.stripes.size();
  for (const JpegStripe& stripe : jpeg.stripes) bytes += stripe.bytes.size();
  std::string message;
  message.reserve(bytes);
  putUint32(message, jpeg.width);
  putUint32(message, jpeg.height);
  putUint32(message, uint32_t(jpeg.stripes.size()));
  for (const JpegStripe& stripe : jpeg.stripes) {
    putUint32(message, stripe.firstRow);
    putUint32(message, uint32_t(stripe.bytes.size()));
  }
  for (const JpegStripe& stripe : jpeg.stripes) message += stripe.bytes;
  return message;
}

StripedJpeg unpackStripedJpeg(std::string_view message) {
  auto refuse = [](const char* why) { throw std::invalid_argument(std::string("not a striped JPEG message: ") + why); };
  if (message.size() < 12) refuse("shorter than its header");
  StripedJpeg jpeg;
  jpeg.width = getUint32(message, 0);
  jpeg.height = getUint32(message, 4);
  const uint32_t count = getUint32(message, 8);
  if (count == 0 || count > jpeg.height) refuse("no stripes, or more than rows");
  size_t offset = 12 + 8 * size_t(count);
  if (message.size() < offset) refuse("shorter than its stripe table");
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t first = getUint32(message, 12 + 8 * size_t(i)), length = getUint32(message, 16 + 8 * size_t(i));
    const uint32_t next = i + 1 < count ? getUint32(message, 20 + 8 * size_t(i)) : jpeg.height;
    if ((i == 0 && first != 0) || next <= first || next > jpeg.height) refuse("stripes that do not tile the rows");
    if (message.size() - offset < length) refuse("stripes past its end");
    jpeg.stripes.push_back({first, next - first, std::string(message.substr(offset, length))});
    offset += length;
  }
  if (offset != message.size()) refuse("bytes after its last stripe");
  return jpeg;
}

}  // namespace candela
