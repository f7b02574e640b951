#include "io/images/jpeg_decoding.h"

#include <cstdio>
// jpeglib.h needs FILE and size_t declared before it.
#include <jpeglib.h>

#include <csetjmp>
#include <vector>

#include "io/images/downscaled_texture.h"
#include "io/load_diagnostics.h"

namespace candela {

namespace {

// A progressive JPEG may hold any number of scans, each a pass over the whole image: thousands of tiny scans make
// a small file decode for minutes. Real encoders write about ten.
constexpr int kMaxScans = 500;

// libjpeg's default error handler calls exit(); this one longjmps to the setjmp of the function that called
// libjpeg. Those functions hold only trivially destructible locals, so the jump skips no destructor, and they
// throw from their own frame, never through libjpeg's.
struct JpegReader {
  jpeg_decompress_struct cinfo{};
  jpeg_error_mgr errors{};
  jpeg_progress_mgr progress{};
  std::jmp_buf jump;
  char error[JMSG_LENGTH_MAX] = "";
  bool created = false;

  JpegReader() = default;
  JpegReader(const JpegReader&) = delete;
  JpegReader& operator=(const JpegReader&) = delete;
  ~JpegReader() {
    if (created) jpeg_destroy_decompress(&cinfo);
  }
};

void onError(j_common_ptr cinfo) {
  auto* reader = static_cast<JpegReader*>(cinfo->client_data);
  cinfo->err->format_message(cinfo, reader->error);
  std::longjmp(reader->jump, 1);
}

// Warnings (a truncated file, corrupt data that libjpeg conceals) are not printed: the image decodes.
void onMessage(j_common_ptr) {}

void onProgress(j_common_ptr cinfo) {
  auto* d = reinterpret_cast<j_decompress_ptr>(cinfo);
  if (d->input_scan_number > kMaxScans) {
    auto* reader = static_cast<JpegReader*>(cinfo->client_data);
    std::snprintf(reader->error, sizeof reader->error, "more than %d scans", kMaxScans);
    std::longjmp(reader->jump, 1);
  }
}

[[noreturn]] void failJpeg(const std::string& name, const JpegReader& reader) {
  failLoad(name,
           std::string("not a readable JPEG image (") + (reader.error[0] ? reader.error : "libjpeg failed") + ")");
}

bool readHeader(JpegReader& r, const uint8_t* data, size_t size) {
  r.cinfo.err = jpeg_std_error(&r.errors);
  r.errors.error_exit = &onError;
  r.errors.output_message = &onMessage;
  r.cinfo.client_data = &r;
  if (setjmp(r.jump)) return false;
  jpeg_create_decompress(&r.cinfo);
  r.created = true;
  // Without a backing store, libjpeg fails rather than allocate more than this for its own buffers.
  r.cinfo.mem->max_memory_to_use = long(kMaxDecodedImageBytes);
  r.progress.progress_monitor = &onProgress;
  r.cinfo.progress = &r.progress;
  jpeg_mem_src(&r.cinfo, data, (unsigned long)size);
  jpeg_read_header(&r.cinfo, TRUE);
  return true;
}

uint32_t channelsOf(const JpegReader& r) { return r.cinfo.jpeg_color_space == JCS_GRAYSCALE ? 1 : 4; }

bool startDecompress(JpegReader& r, uint32_t targetWidth, uint32_t targetHeight) {
  if (setjmp(r.jump)) return false;
  const J_COLOR_SPACE in = r.cinfo.jpeg_color_space;
  r.cinfo.out_color_space = in == JCS_GRAYSCALE                  ? JCS_GRAYSCALE
                            : (in == JCS_CMYK || in == JCS_YCCK) ? JCS_CMYK
                                                                 : JCS_EXT_RGBA;
  // The DCT scales by 1/2, 1/4 or 1/8 nearly for free; the area average does the rest.
  r.cinfo.scale_num = 1;
  for (unsigned denom = 8; denom > 1; denom /= 2)
    if (r.cinfo.image_width / denom >= targetWidth && r.cinfo.image_height / denom >= targetHeight) {
      r.cinfo.scale_denom = denom;
      break;
    }
  jpeg_start_decompress(&r.cinfo);
  return true;
}

bool readRow(JpegReader& r, uint8_t* row) {
  if (setjmp(r.jump)) return false;
  JSAMPROW rows[1] = {row};
  // A source in memory never suspends, so every call gives a row.
  if (jpeg_read_scanlines(&r.cinfo, rows, 1) == 1) return true;
  std::snprintf(r.error, sizeof r.error, "scanline missing");
  return false;
}

// Adobe's CMYK JPEGs store the inks inverted (255 = none); what libjpeg gives is then 255 - ink.
void cmykToRgba(uint8_t* row, uint32_t width, bool inverted) {
  for (uint32_t x = 0; x < width; ++x) {
    uint8_t* p = row + size_t(x) * 4;
    int c = p[0], m = p[1], y = p[2], k = p[3];
    if (!inverted) c = 255 - c, m = 255 - m, y = 255 - y, k = 255 - k;
    p[0] = uint8_t((c * k + 127) / 255);
    p[1] = uint8_t((m * k + 127) / 255);
    p[2] = uint8_t((y * k + 127) / 255);
    p[3] = 255;
  }
}

}  // namespace

bool isJpeg(const uint8_t* data, size_t size) {
  return size >= 3 && data[0] == 0xff && data[1] == 0xd8 && data[2] == 0xff;
}

ImageInfo jpegInfo(const std::string& name, const uint8_t* data, size_t size) {
  JpegReader reader;
  if (!readHeader(reader, data, size)) failJpeg(name, reader);
  return {reader.cinfo.image_width, reader.cinfo.image_height, channelsOf(reader), false};
}

Texture decodeJpeg(const std::string& name, const uint8_t* data, size_t size, uint32_t targetWidth,
                   uint32_t targetHeight) {
  JpegReader reader;
  if (!readHeader(reader, data, size)) failJpeg(name, reader);
  if (!startDecompress(reader, targetWidth, targetHeight)) failJpeg(name, reader);
  const jpeg_decompress_struct& c = reader.cinfo;
  const uint32_t channels = channelsOf(reader);
  if (uint32_t(c.output_components) != channels) failLoad(name, "unexpected JPEG pixel layout");
  AreaDownscaler<uint8_t> target(c.output_width, c.output_height, targetWidth, targetHeight, channels);
  std::vector<uint8_t> row(size_t(c.output_width) * channels);
  for (uint32_t y = 0; y < c.output_height; ++y) {
    if (!readRow(reader, row.data())) failJpeg(name, reader);
    if (c.out_color_space == JCS_CMYK) cmykToRgba(row.data(), c.output_width, c.saw_Adobe_marker);
    target.addRow(row.data());
  }
  return finishTexture(name, target);
}

}  // namespace candela
