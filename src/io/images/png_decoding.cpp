#include "io/images/png_decoding.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

#include "io/images/downscaled_texture.h"
#include "io/load_budget.h"
#include "io/load_diagnostics.h"

namespace candela {

namespace {

// libpng reports errors by longjmp to the setjmp of the function that called it. Every function below that
// calls libpng sets its own, and holds only trivially destructible locals, so that the jump skips no destructor;
// it then throws from its own frame, never through libpng's.
struct PngReader {
  const uint8_t* data;
  size_t size;
  size_t position = 0;
  char error[200] = "";
  png_structp png = nullptr;
  png_infop info = nullptr;
  int passes = 1;  // 7 for an interlaced image

  PngReader(const uint8_t* d, size_t s) : data(d), size(s) {}
  PngReader(const PngReader&) = delete;
  PngReader& operator=(const PngReader&) = delete;
  ~PngReader() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

void onError(png_structp png, png_const_charp message) {
  auto* reader = static_cast<PngReader*>(png_get_error_ptr(png));
  std::snprintf(reader->error, sizeof reader->error, "%s", message);
  png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}

void readBytes(png_structp png, png_bytep out, size_t count) {
  auto* reader = static_cast<PngReader*>(png_get_io_ptr(png));
  if (reader->size - reader->position < count) png_error(png, "file is truncated");
  std::memcpy(out, reader->data + reader->position, count);
  reader->position += count;
}

[[noreturn]] void failPng(const std::string& name, const PngReader& reader) {
  failLoad(name, std::string("not a readable PNG image (") + (reader.error[0] ? reader.error : "libpng failed") + ")");
}

// Reads the header and sets up the conversions; returns false when libpng fails.
bool readHeader(PngReader& r) {
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r, &onError, &onWarning);
  if (!r.png) return false;
  r.info = png_create_info_struct(r.png);
  if (!r.info) return false;
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_set_read_fn(r.png, &r, &readBytes);
  // Only IHDR, PLTE, tRNS, IDAT and IEND are read; every other chunk is skipped unread. libpng allocates and
  // clears what a text (or iCCP, sPLT, eXIf, pCAL, sCAL) chunk declares before reading it, and its check of the
  // length only warns: a 59-byte file whose iTXt chunk claimed 1.8 GB took 2 GB of memory and 18 s.
  png_set_keep_unknown_chunks(r.png, PNG_HANDLE_CHUNK_NEVER, nullptr, -1);
  // The checksum of the compressed stream costs a tenth of the decoding of a large image and protects nothing a
  // decoder needs: corrupt data still fails (or decodes to wrong pixels) without it.
  png_set_option(r.png, PNG_IGNORE_ADLER32, PNG_OPTION_ON);
  png_read_info(r.png, r.info);
  const png_byte colorType = png_get_color_type(r.png, r.info);
  png_set_strip_16(r.png);
  png_set_packing(r.png);
  if (colorType == PNG_COLOR_TYPE_GRAY) {
    png_set_expand_gray_1_2_4_to_8(r.png);
  } else {
    png_set_palette_to_rgb(r.png);
    if (colorType != PNG_COLOR_TYPE_GRAY_ALPHA && png_get_valid(r.png, r.info, PNG_INFO_tRNS))
      png_set_tRNS_to_alpha(r.png);
    png_set_gray_to_rgb(r.png);
    png_set_filler(r.png, 0xff, PNG_FILLER_AFTER);
  }
  r.passes = png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  return true;
}

bool readRows(PngReader& r, uint8_t* rows, uint32_t count, size_t rowBytes) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  for (uint32_t y = 0; y < count; ++y) png_read_row(r.png, rows + size_t(y) * rowBytes, nullptr);
  return true;
}

uint32_t channelsOf(const PngReader& r) { return png_get_color_type(r.png, r.info) == PNG_COLOR_TYPE_GRAY ? 1 : 4; }

}  // namespace

bool isPng(const uint8_t* data, size_t size) { return size >= 8 && png_sig_cmp(data, 0, 8) == 0; }

ImageInfo pngInfo(const std::string& name, const uint8_t* data, size_t size) {
  PngReader reader(data, size);
  if (!readHeader(reader)) failPng(name, reader);
  return {png_get_image_width(reader.png, reader.info), png_get_image_height(reader.png, reader.info),
          channelsOf(reader), false};
}

Texture decodePng(const std::string& name, const uint8_t* data, size_t size, uint32_t targetWidth,
                  uint32_t targetHeight) {
  PngReader reader(data, size);
  if (!readHeader(reader)) failPng(name, reader);
  const uint32_t width = png_get_image_width(reader.png, reader.info);
  const uint32_t height = png_get_image_height(reader.png, reader.info);
  const uint32_t channels = channelsOf(reader);
  const size_t rowBytes = size_t(width) * channels;
  if (png_get_rowbytes(reader.png, reader.info) != rowBytes) failLoad(name, "unexpected PNG pixel layout");
  AreaDownscaler<uint8_t> target(width, height, targetWidth, targetHeight, channels);
  // An interlaced image is complete only after its last pass, so it is read whole; others a row at a time.
  const bool interlaced = reader.passes > 1;
  if (interlaced) {
    checkDecodedSize(name, width, height, channels);
    chargeLoadMemory(uint64_t(rowBytes) * height, name,
                     "an interlaced PNG of " + std::to_string(width) + "x" + std::to_string(height) +
                         " pixels, decoded whole before it is downscaled,");
  }
  std::vector<uint8_t> rows(interlaced ? rowBytes * height : rowBytes);
  if (interlaced) {
    for (int pass = 0; pass < reader.passes; ++pass)
      if (!readRows(reader, rows.data(), height, rowBytes)) failPng(name, reader);
    for (uint32_t y = 0; y < height; ++y) target.addRow(&rows[size_t(y) * rowBytes]);
    releaseLoadMemory(uint64_t(rowBytes) * height);
  } else {
    for (uint32_t y = 0; y < height; ++y) {
      if (!readRows(reader, rows.data(), 1, rowBytes)) failPng(name, reader);
      target.addRow(rows.data());
      if (y % 256 == 255)
        noteLoadProgress(name, "decoding row " + std::to_string(y + 1) + " of " + std::to_string(height));
    }
  }
  return finishTexture(name, target);
}

}  // namespace candela
