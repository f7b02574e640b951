// Image decoding: PNG through libpng, JPEG through libjpeg-turbo, OpenEXR data windows, and the texture limits
// that decode oversized textures smaller.
#include <gtest/gtest.h>

#include <OpenEXR/ImfRgbaFile.h>
#include <png.h>
#include <stb/stb_image_write.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <jpeglib.h>
#include <cstdio>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <type_traits>

#include "app/scene_loading.h"
#include "io/file_bytes.h"
#include "io/images/area_downscaler.h"
#include "io/images/exr_decoding.h"
#include "io/images/image_decoding.h"
#include "io/load_diagnostics.h"
#include "scene/loaders/obj/obj_loader.h"
#include "scene/loaders/texture_limits.h"
#include "scene_test_files.h"
#include "webp_test_image.h"

namespace candela {
namespace {

using test::TempFolder;

std::vector<uint8_t> readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Texture decodeFile(const std::string& path, bool srgb = false) {
  std::vector<uint8_t> bytes = readAll(path);
  return decodeImage(path, bytes.data(), bytes.size(), srgb);
}

// Writes a PNG through libpng, which can write what stb_image_write cannot: 16-bit, palette, interlaced and
// 1-bit images. `row(y, out)` fills one row of samples as libpng takes them.
void writePngWithLibpng(const std::string& path, uint32_t width, uint32_t height, int bitDepth, int colorType,
                        bool interlaced, const std::function<void(uint32_t, std::vector<uint8_t>&)>& row,
                        const std::function<void(png_structp, png_infop)>& extra = {}) {
  FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, file);
  png_set_compression_level(png, 9);
  png_set_IHDR(png, info, width, height, bitDepth, colorType, interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (extra) extra(png, info);
  png_write_info(png, info);
  std::vector<uint8_t> samples;
  const int passes = png_set_interlace_handling(png);
  for (int pass = 0; pass < passes; ++pass)
    for (uint32_t y = 0; y < height; ++y) {
      row(y, samples);
      png_write_row(png, samples.data());
    }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(file);
}

TEST(PngDecoding, ChannelsAsBefore) {
  TempFolder dir;
  const uint8_t grey[] = {10, 20, 30, 40}, greyAlpha[] = {10, 1, 20, 2, 30, 3, 40, 4};
  const uint8_t rgb[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  ASSERT_TRUE(stbi_write_png(dir.file("g.png").c_str(), 2, 2, 1, grey, 2));
  ASSERT_TRUE(stbi_write_png(dir.file("ga.png").c_str(), 2, 2, 2, greyAlpha, 4));
  ASSERT_TRUE(stbi_write_png(dir.file("rgb.png").c_str(), 2, 2, 3, rgb, 6));
  Texture g = decodeFile(dir.file("g.png"), true);
  EXPECT_EQ(g.channels, 1u);
  EXPECT_EQ(g.bytes, std::vector<uint8_t>(grey, grey + 4));
  EXPECT_TRUE(g.srgb);
  Texture ga = decodeFile(dir.file("ga.png"));
  ASSERT_EQ(ga.channels, 4u);
  EXPECT_EQ(ga.bytes, (std::vector<uint8_t>{10, 10, 10, 1, 20, 20, 20, 2, 30, 30, 30, 3, 40, 40, 40, 4}));
  Texture c = decodeFile(dir.file("rgb.png"));
  ASSERT_EQ(c.channels, 4u);
  EXPECT_EQ(c.bytes, (std::vector<uint8_t>{1, 2, 3, 255, 4, 5, 6, 255, 7, 8, 9, 255, 10, 11, 12, 255}));
}

TEST(PngDecoding, SixteenBitPaletteAndInterlacedImages) {
  TempFolder dir;
  // 16-bit grey keeps the high byte of each sample.
  writePngWithLibpng(dir.file("g16.png"), 3, 1, 16, PNG_COLOR_TYPE_GRAY, false,
                     [](uint32_t, std::vector<uint8_t>& s) { s = {0x12, 0x34, 0xab, 0xcd, 0xff, 0xff}; });
  Texture g16 = decodeFile(dir.file("g16.png"));
  EXPECT_EQ(g16.channels, 1u);
  EXPECT_EQ(g16.bytes, (std::vector<uint8_t>{0x12, 0xab, 0xff}));
  // A palette with transparency becomes RGBA.
  writePngWithLibpng(
      dir.file("p.png"), 2, 1, 8, PNG_COLOR_TYPE_PALETTE, false,
      [](uint32_t, std::vector<uint8_t>& s) {
        s = {1, 0};
      },
      [](png_structp png, png_infop info) {
        png_color palette[2] = {{10, 20, 30}, {40, 50, 60}};
        png_set_PLTE(png, info, palette, 2);
        png_byte alpha[1] = {128};
        png_set_tRNS(png, info, alpha, 1, nullptr);
      });
  Texture p = decodeFile(dir.file("p.png"));
  ASSERT_EQ(p.channels, 4u);
  EXPECT_EQ(p.bytes, (std::vector<uint8_t>{40, 50, 60, 255, 10, 20, 30, 128}));
  // Interlaced RGB: every pass lands where it belongs.
  writePngWithLibpng(dir.file("i.png"), 9, 9, 8, PNG_COLOR_TYPE_RGB, true, [](uint32_t y, std::vector<uint8_t>& s) {
    s.resize(27);
    for (uint32_t x = 0; x < 9; ++x) s[3 * x] = s[3 * x + 1] = s[3 * x + 2] = uint8_t(10 * y + x);
  });
  Texture i = decodeFile(dir.file("i.png"));
  ASSERT_EQ(i.channels, 4u);
  for (uint32_t y = 0; y < 9; ++y)
    for (uint32_t x = 0; x < 9; ++x) EXPECT_EQ(i.bytes[(y * 9 + x) * 4], 10 * y + x);
}

TEST(PngDecoding, DamagedFilesAreLoadErrorsNamingTheFile) {
  TempFolder dir;
  const uint8_t rgb[3 * 64 * 64] = {};
  ASSERT_TRUE(stbi_write_png(dir.file("ok.png").c_str(), 64, 64, 3, rgb, 64 * 3));
  std::vector<uint8_t> bytes = readAll(dir.file("ok.png"));
  for (size_t cut : {size_t(8), size_t(20), bytes.size() / 2, bytes.size() - 13}) {
    try {
      decodeImage("cut.png", bytes.data(), cut, false);
      ADD_FAILURE() << "a PNG cut at " << cut << " decoded";
    } catch (const LoadError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("cut.png: not a readable PNG image (", 0), 0u) << e.what();
    }
  }
}

// The growth of the peak memory of a child process that calls `work`, in MB.
long peakMemoryGrowthMb(const std::function<void()>& work) {
  const pid_t child = fork();
  if (child == 0) {
    rusage before{}, after{};
    getrusage(RUSAGE_SELF, &before);
    work();
    getrusage(RUSAGE_SELF, &after);
    _exit(int(std::min<long>((after.ru_maxrss - before.ru_maxrss) / 1024, 255)));
  }
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 255;
}

TEST(PngDecoding, ChunksClaimingMoreThanTheFileHoldsAreNotAllocated) {
  TempFolder dir;
  const uint8_t rgb[3 * 4 * 4] = {};
  ASSERT_TRUE(stbi_write_png(dir.file("ok.png").c_str(), 4, 4, 3, rgb, 4 * 3));
  std::vector<uint8_t> bytes = readAll(dir.file("ok.png"));
  // After the signature and IHDR (33 bytes): an iTXt chunk that claims 0x6b6b6b6b bytes (1.8 GB), which libpng
  // allocated and cleared before it found the file too short (found by the png fuzz target).
  const uint8_t claim[] = {0x6b, 0x6b, 0x6b, 0x6b, 'i', 'T', 'X', 't', 'k', 'k', 'k', 'k'};
  bytes.insert(bytes.begin() + 33, std::begin(claim), std::end(claim));
  const long growth = peakMemoryGrowthMb([&] {
    try {
      decodeImage("claim.png", bytes.data(), bytes.size(), false);
    } catch (const LoadError&) {
    }
  });
  EXPECT_LT(growth, 64);
  try {
    decodeImage("claim.png", bytes.data(), bytes.size(), false);
    ADD_FAILURE() << "a PNG with a chunk longer than the file decoded";
  } catch (const LoadError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("claim.png: not a readable PNG image (", 0), 0u) << e.what();
  }
}

TEST(PngDecoding, CompressedTextLargerThanTheFileDoesNotStopTheImage) {
  TempFolder dir;
  const std::string text(1 << 20, 'a');  // some 1 KB compressed
  writePngWithLibpng(
      dir.file("z.png"), 2, 1, 8, PNG_COLOR_TYPE_GRAY, false,
      [](uint32_t, std::vector<uint8_t>& s) {
        s = {7, 9};
      },
      [&](png_structp png, png_infop info) {
        png_text entry{};
        entry.compression = PNG_TEXT_COMPRESSION_zTXt;
        entry.key = const_cast<char*>("Comment");
        entry.text = const_cast<char*>(text.c_str());
        entry.text_length = text.size();
        png_set_text(png, info, &entry, 1);
      });
  ASSERT_LT(readAll(dir.file("z.png")).size(), size_t(1) << 16);
  Texture z = decodeFile(dir.file("z.png"));
  EXPECT_EQ(z.bytes, (std::vector<uint8_t>{7, 9}));
}

// Writes a JPEG through libjpeg: grey when `components` is 1, else RGB.
void writeJpeg(const std::string& path, uint32_t width, uint32_t height, int components, uint8_t value) {
  FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  jpeg_compress_struct c{};
  jpeg_error_mgr errors{};
  c.err = jpeg_std_error(&errors);
  jpeg_create_compress(&c);
  jpeg_stdio_dest(&c, file);
  c.image_width = width;
  c.image_height = height;
  c.input_components = components;
  c.in_color_space = components == 1 ? JCS_GRAYSCALE : JCS_RGB;
  jpeg_set_defaults(&c);
  jpeg_set_quality(&c, 95, TRUE);
  jpeg_start_compress(&c, TRUE);
  std::vector<uint8_t> row(size_t(width) * components, value);
  while (c.next_scanline < c.image_height) {
    JSAMPROW rows[1] = {row.data()};
    jpeg_write_scanlines(&c, rows, 1);
  }
  jpeg_finish_compress(&c);
  jpeg_destroy_compress(&c);
  std::fclose(file);
}

TEST(JpegDecoding, GreyAndColourAsBefore) {
  TempFolder dir;
  writeJpeg(dir.file("g.jpg"), 16, 8, 1, 100);
  writeJpeg(dir.file("c.jpg"), 16, 8, 3, 200);
  Texture g = decodeFile(dir.file("g.jpg"), true);
  EXPECT_EQ(g.width, 16u);
  EXPECT_EQ(g.height, 8u);
  ASSERT_EQ(g.channels, 1u);
  for (uint8_t v : g.bytes) EXPECT_NEAR(v, 100, 1);
  Texture c = decodeFile(dir.file("c.jpg"));
  ASSERT_EQ(c.channels, 4u);
  for (size_t i = 0; i < c.bytes.size(); ++i) EXPECT_NEAR(c.bytes[i], i % 4 == 3 ? 255 : 200, 1);
}

TEST(JpegDecoding, DamagedFilesAreLibjpegErrors) {
  TempFolder dir;
  writeJpeg(dir.file("c.jpg"), 16, 8, 3, 200);
  std::vector<uint8_t> bytes = readAll(dir.file("c.jpg"));
  // Destroy the Huffman tables (DHT segments): the message is libjpeg's, never stb_image's.
  for (size_t i = 0; i + 1 < bytes.size(); ++i)
    if (bytes[i] == 0xff && bytes[i + 1] == 0xc4)
      for (size_t k = i + 4; k < std::min(bytes.size(), i + 40); ++k) bytes[k] = 0xff;
  try {
    decodeImage("bad.jpg", bytes.data(), bytes.size(), false);
    ADD_FAILURE() << "a JPEG with broken Huffman tables decoded";
  } catch (const LoadError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("bad.jpg: not a readable JPEG image (", 0), 0u) << e.what();
  }
  // The 20 bytes that made stb_image write out of bounds in stbi__build_huffman.
  const uint8_t huff[] = {0xff, 0xff, 0xff, 0xff, 0xff, 0xd8, 0xff, 0xff, 0xff, 0xc4,
                          0xda, 0xff, 0x00, 0x18, 0x2c, 0xdf, 0xff, 0x21, 0x66, 0x81};
  EXPECT_THROW(decodeImage("huff.jpg", huff, sizeof huff, false), LoadError);
}

// glTF's EXT_texture_webp: lossless pixels come back exactly, as RGBA; a smaller decode averages them.
TEST(WebpDecoding, LosslessPixelsAndAreaAverage) {
  const std::vector<uint8_t> rgba = {10, 20,  30,  255, 50,  60,  70,  128,  // row 0
                                     90, 100, 110, 255, 130, 140, 150, 0};
  const std::vector<uint8_t> webp = test::losslessWebp(rgba, 2, 2);
  Texture t = decodeImage("t.webp", webp.data(), webp.size(), true);
  EXPECT_EQ(t.width, 2u);
  EXPECT_EQ(t.height, 2u);
  ASSERT_EQ(t.channels, 4u);
  EXPECT_TRUE(t.srgb);
  // libwebp may change the colour of fully transparent pixels; the others are exact.
  for (size_t i = 0; i < 12; ++i) EXPECT_EQ(t.bytes[i], rgba[i]) << i;
  EXPECT_EQ(t.bytes[15], 0);
  Texture small = decodeImage("t.webp", webp.data(), webp.size(), false, 1, 1);
  ASSERT_EQ(small.bytes.size(), 4u);
  EXPECT_NEAR(small.bytes[3], (255 + 128 + 255 + 0) / 4.0, 1.0);
}

TEST(WebpDecoding, DamagedFilesAreLoadErrorsNamingTheFile) {
  const std::vector<uint8_t> rgba(64 * 64 * 4, 77);
  std::vector<uint8_t> webp = test::losslessWebp(rgba, 64, 64);
  for (size_t cut : {size_t(12), size_t(20), webp.size() / 2}) {
    try {
      decodeImage("cut.webp", webp.data(), cut, false);
      ADD_FAILURE() << "a WebP cut to " << cut << " bytes decoded";
    } catch (const LoadError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("cut.webp: ", 0), 0u) << e.what();
    }
  }
}

// An OpenEXR image of 100x10 pixels whose data window lies far from the origin; pixel (x, y) of the window
// holds red x, green y.
void writeOffsetExr(const std::string& path, int minX, int minY) {
  const int width = 100, height = 10;
  Imath::Box2i window({minX, minY}, {minX + width - 1, minY + height - 1});
  Imath::Box2i display({0, 0}, {width - 1, height - 1});
  Imf::RgbaOutputFile file(path.c_str(), Imf::Header(display, window), Imf::WRITE_RGBA);
  std::vector<Imf::Rgba> pixels(size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) pixels[size_t(y) * width + x] = Imf::Rgba(float(x), float(y), 1.0f, 1.0f);
  const int64_t origin = int64_t(minX) + int64_t(minY) * width;
  file.setFrameBuffer(reinterpret_cast<Imf::Rgba*>(reinterpret_cast<uintptr_t>(pixels.data()) -
                                                   uintptr_t(origin) * sizeof(Imf::Rgba)),
                      1, width);
  file.writePixels(height);
}

TEST(ExrDecoding, DataWindowFarFromTheOrigin) {
  TempFolder dir;
  for (auto [minX, minY] : {std::pair{0, 100000000}, std::pair{-1000000000, 5}, std::pair{1000000000, -1000000000}}) {
    const std::string path = dir.file("off.exr");
    writeOffsetExr(path, minX, minY);
    Texture t = loadEnvironmentImage(path);
    ASSERT_EQ(t.width, 100u);
    ASSERT_EQ(t.height, 10u);
    EXPECT_EQ(t.floats[(5 * 100 + 7) * 3 + 0], 7.0f);
    EXPECT_EQ(t.floats[(5 * 100 + 7) * 3 + 1], 5.0f);
    EXPECT_EQ(t.floats[(9 * 100 + 99) * 3 + 2], 1.0f);
  }
}

TEST(ExrDecoding, LargeImagesAreReadInBandsAndDownscaled) {
  TempFolder dir;
  // 1000 x 1100 pixels: more than one band of rows. Pixel (x, y) holds red x % 16, green y % 16.
  const int width = 1000, height = 1100;
  const std::string path = dir.file("large.exr");
  {
    Imath::Box2i window({0, 0}, {width - 1, height - 1});
    Imf::RgbaOutputFile file(path.c_str(), Imf::Header(window, window), Imf::WRITE_RGBA);
    std::vector<Imf::Rgba> pixels(size_t(width) * height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) pixels[size_t(y) * width + x] = Imf::Rgba(float(x % 16), float(y % 16), 1.0f);
    file.setFrameBuffer(pixels.data(), 1, width);
    file.writePixels(height);
  }
  const std::vector<uint8_t> bytes = readFileBytes(path);
  std::pair<uint32_t, uint32_t> fileSize;
  Texture t = decodeExr(path, bytes.data(), bytes.size(), UINT64_MAX, 500, &fileSize);
  EXPECT_EQ(fileSize, std::make_pair(1000u, 1100u));
  ASSERT_EQ(t.width, 454u);  // 1000 * 500 / 1100, rounded down
  ASSERT_EQ(t.height, 500u);
  // Every target pixel is the mean of the source pixels that fall in it, on both sides of a band's edge.
  for (uint32_t ty = 0; ty < t.height; ++ty) {
    double sum = 0;
    uint32_t count = 0;
    for (uint32_t y = 0; y < uint32_t(height); ++y)
      if (y * t.height / height == ty) {
        sum += y % 16;
        ++count;
      }
    EXPECT_NEAR(t.floats[(size_t(ty) * t.width + 3) * 3 + 1], sum / count, 1e-5) << "row " << ty;
  }
  Texture whole = decodeExr(path, bytes.data(), bytes.size());
  EXPECT_EQ(whole.width, 1000u);
  EXPECT_EQ(whole.floats[(size_t(1099) * width + 999) * 3 + 0], float(999 % 16));
  EXPECT_EQ(whole.floats[(size_t(1099) * width + 999) * 3 + 1], float(1099 % 16));
}

// The message of the LoadError that `decode` throws, or "(no error)".
std::string decodeError(const std::function<void()>& decode) {
  try {
    decode();
  } catch (const LoadError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ExrDecoding, SizesAreCheckedOnTheHeaderBeforeDecoding) {
  TempFolder dir;
  const std::string path = dir.file("small.exr");
  writeOffsetExr(path, 0, 0);
  std::vector<uint8_t> bytes = readAll(path);
  EXPECT_EQ(decodeExr(path, bytes.data(), bytes.size(), 1000).width, 100u);
  EXPECT_EQ(decodeError([&] { decodeExr("small.exr", bytes.data(), bytes.size(), 999); }),
            "small.exr: OpenEXR image of 100x10 pixels is larger than the limit of 999 pixels");
  // The same file with a data window of 30000x30000 pixels in its header: refused before anything is allocated.
  const std::string key("dataWindow\0box2i\0", 17);
  auto at = std::search(bytes.begin(), bytes.end(), key.begin(), key.end());
  ASSERT_NE(at, bytes.end());
  const int32_t window[4] = {0, 0, 29999, 29999};
  std::memcpy(&*(at + ptrdiff_t(key.size()) + 4), window, sizeof window);
  EXPECT_EQ(decodeError([&] { decodeExr("huge.exr", bytes.data(), bytes.size()); }),
            "huge.exr: image header claims 30000x30000 pixels, more than the file can hold");
}

TEST(ExrDecoding, AttributesLargerThanTheFileAreRefusedBeforeOpenExrAllocatesThem) {
  // OpenEXR allocates an attribute's claimed size before reading it: 32 bytes of a fuzzer's input claiming about
  // 2 GB took hundreds of MB and seconds before it found the file short.
  TempFolder dir;
  const std::string path = dir.file("small.exr");
  writeOffsetExr(path, 0, 0);
  std::vector<uint8_t> bytes = readAll(path);
  const std::string key("channels\0chlist\0", 16);
  auto at = std::search(bytes.begin(), bytes.end(), key.begin(), key.end());
  ASSERT_NE(at, bytes.end());
  const int32_t claimed = 0x7f000000;
  std::memcpy(&*(at + ptrdiff_t(key.size())), &claimed, sizeof claimed);
  EXPECT_EQ(decodeError([&] { decodeExr("claims.exr", bytes.data(), bytes.size()); }),
            "claims.exr: OpenEXR header attribute 'channels' claims 2130706432 bytes, more than the file holds");
  bytes.resize(20);
  EXPECT_EQ(decodeError([&] { decodeExr("short.exr", bytes.data(), bytes.size()); }),
            "short.exr: OpenEXR header is truncated");
}

TEST(ExrDecoding, AttributesReadByTheirContentMustBeOfTheirDeclaredSize) {
  // OpenEXR reads a channel list up to its end and a box2i as 16 bytes whatever size they declare, so a file
  // whose declared sizes disagree would hide the attributes after them from the check above.
  TempFolder dir;
  const std::string path = dir.file("small.exr");
  writeOffsetExr(path, 0, 0);
  std::vector<uint8_t> bytes = readAll(path);
  const std::string key("dataWindow\0box2i\0", 17);
  auto at = std::search(bytes.begin(), bytes.end(), key.begin(), key.end());
  ASSERT_NE(at, bytes.end());
  const int32_t declared = 12;
  std::memcpy(&*(at + ptrdiff_t(key.size())), &declared, sizeof declared);
  EXPECT_EQ(decodeError([&] { decodeExr("window.exr", bytes.data(), bytes.size()); }),
            "window.exr: OpenEXR header attribute 'dataWindow' declares 12 bytes for a value of 16");
  // A preview image of about 2^32 x 2^32 pixels: the fuzzer's input whose size overflowed 64 bits in this check
  // (tests/fuzz/regressions/exr/preview-size-overflowing-64-bits.exr).
  const uint8_t preview[] = {0x76, 0x2f, 0x31, 0x01, 0x02, 0x10, 0x00, 0x00, 0x63, 0x24, 0x24, 0x24, 0x24, 0x24,
                             0x24, 0x87, 0x87, 0x87, 0x87, 0x87, 0x87, 0x87, 0x87, 0x87, 0x87, 0x44, 0x00, 0x70,
                             0x72, 0x65, 0x76, 0x69, 0x65, 0x77, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x87, 0x87,
                             0x87, 0xdb, 0xc8, 0xc8, 0x73, 0x01, 0x80, 0x01, 0x00, 0x7a, 0x00, 0x79, 0x57, 0x69};
  const std::string message = decodeError([&] { decodeExr("preview.exr", preview, sizeof preview); });
  EXPECT_EQ(message.rfind("preview.exr: OpenEXR header attribute 'c$$$$$$", 0), 0u) << message;
  EXPECT_NE(message.find("' runs past the end of the file"), std::string::npos) << message;
}

TEST(AreaDownscaler, MeansOfTheCoveredPixels) {
  // 4x2 to 2x1: each target pixel is the mean of a 2x2 block; 3x1 to 2x1 splits the columns 2 + 1.
  AreaDownscaler<uint8_t> half(4, 2, 2, 1, 1);
  const uint8_t rows[2][4] = {{0, 10, 100, 200}, {20, 30, 50, 50}};
  half.addRow(rows[0]);
  half.addRow(rows[1]);
  EXPECT_EQ(half.finish(), (std::vector<uint8_t>{15, 100}));
  AreaDownscaler<float> uneven(3, 1, 2, 1, 2);
  const float row[6] = {1, 2, 3, 4, 10, 20};
  uneven.addRow(row);
  EXPECT_EQ(uneven.finish(), (std::vector<float>{2, 3, 10, 20}));
}

// Each target pixel against the mean of its source pixels summed here one by one, over sizes whose ratios are
// not whole numbers, every channel count, and 8-bit and float samples.
template <typename Sample>
void expectMeansOfCoveredPixels(uint32_t seed) {
  std::mt19937 engine(seed);
  auto random = [&] { return uint32_t(engine()); };
  for (int trial = 0; trial < 40; ++trial) {
    const uint32_t sw = 1 + random() % 97, sh = 1 + random() % 61, channels = 1 + random() % 4;
    const uint32_t tw = 1 + random() % sw, th = 1 + random() % sh;
    std::vector<Sample> source(size_t(sw) * sh * channels);
    for (Sample& v : source) v = Sample(random() % 256);
    AreaDownscaler<Sample> target(sw, sh, tw, th, channels);
    for (uint32_t y = 0; y < sh; ++y) target.addRow(&source[size_t(y) * sw * channels]);
    const std::vector<Sample> result = target.finish();
    std::vector<double> sums(size_t(tw) * th * channels, 0.0), counts(size_t(tw) * th, 0.0);
    for (uint32_t y = 0; y < sh; ++y)
      for (uint32_t x = 0; x < sw; ++x) {
        const size_t t = size_t(uint64_t(y) * th / sh) * tw + uint64_t(x) * tw / sw;
        counts[t] += 1.0;
        for (uint32_t c = 0; c < channels; ++c)
          sums[t * channels + c] += double(source[(size_t(y) * sw + x) * channels + c]);
      }
    for (size_t i = 0; i < result.size(); ++i) {
      const double mean = sums[i] / counts[i / channels];
      EXPECT_NEAR(double(result[i]), mean, std::is_integral_v<Sample> ? 0.5 : 1e-4 * mean)
          << sw << "x" << sh << " to " << tw << "x" << th << ", " << channels << " channels, value " << i;
    }
  }
}

TEST(AreaDownscaler, EveryTargetPixelIsTheMeanOfItsSourcePixels) {
  expectMeansOfCoveredPixels<uint8_t>(1);
  expectMeansOfCoveredPixels<float>(2);
}

TEST(TextureLimits, FitSizeThenMemory) {
  TextureLimits limits{100, 1u << 20};
  std::vector<TextureExtent> fitted = fitTextureLimits({{400, 200, 4}, {50, 60, 1}}, limits);
  EXPECT_EQ(fitted[0].width, 100u);
  EXPECT_EQ(fitted[0].height, 50u);
  EXPECT_EQ(fitted[1].width, 50u);
  EXPECT_EQ(fitted[1].height, 60u);
  // 2 x 1000x1000 RGBA with their mip levels is 10.67 MB: both shrink by sqrt(2 MiB / 10.67 MB) = 0.443 to fit
  // 2 MiB (8 MB, and 0.512, without the levels).
  limits = {4096, 2u << 20};
  fitted = fitTextureLimits({{1000, 1000, 4}, {1000, 1000, 4}}, limits);
  uint64_t total = 0;
  for (const TextureExtent& e : fitted) total += textureBytesWithMips(e);
  EXPECT_LE(total, limits.maxBytes);
  EXPECT_EQ(fitted[0].width, 443u);
  EXPECT_EQ(fitted[1].height, 443u);
  // Narrow textures: their 1-texel side does not shrink, so the factor from the totals (0.5: 1x8 to 1x4, 28 of
  // 60 bytes) would overshoot.
  std::vector<TextureExtent> many(1000, TextureExtent{1, 8, 4});
  limits = {4096, 15000};
  total = 0;
  for (const TextureExtent& e : fitTextureLimits(many, limits)) total += textureBytesWithMips(e);
  EXPECT_LE(total, limits.maxBytes);
}

// The PNG bomb: 16000x16000 grey pixels, 1 bit each, in a few kilobytes.
TEST(TextureLimits, HugePngTextureIsDecodedSmallerWithOneWarning) {
  TempFolder dir;
  writePngWithLibpng(dir.file("bomb.png"), 16000, 16000, 1, PNG_COLOR_TYPE_GRAY, false,
                     [](uint32_t y, std::vector<uint8_t>& s) { s.assign(2000, y < 8000 ? 0xff : 0x00); });
  dir.write("m.mtl", "newmtl m\nmap_Kd bomb.png\n");
  LoadWarnings warnings;
  Scene s = loadObj(dir.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n"), warnings);
  ASSERT_EQ(s.textures.size(), 1u);
  const Texture& t = s.textures[0];
  EXPECT_EQ(t.width, 8192u);
  EXPECT_EQ(t.height, 8192u);
  EXPECT_EQ(t.channels, 1u);
  EXPECT_EQ(t.bytes[0], 255);                  // top half white,
  EXPECT_EQ(t.bytes[size_t(8191) * 8192], 0);  // bottom half black
  ASSERT_EQ(warnings.messages.size(), 1u);
  EXPECT_NE(warnings.messages[0].find("bomb.png: texture of 16000x16000 pixels downscaled to 8192x8192"),
            std::string::npos)
      << warnings.messages[0];
}

TEST(TextureLimits, LimitsFromTheLoadOptionsApply) {
  TempFolder dir;
  std::vector<uint8_t> pixels(size_t(300) * 200 * 3, 90);
  ASSERT_TRUE(stbi_write_png(dir.file("a.png").c_str(), 300, 200, 3, pixels.data(), 300 * 3));
  ASSERT_TRUE(stbi_write_png(dir.file("b.png").c_str(), 300, 200, 3, pixels.data(), 300 * 3));
  dir.write("m.mtl", "newmtl a\nmap_Kd a.png\nnewmtl b\nmap_Kd b.png\n");
  const std::string obj =
      dir.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\n");
  setTextureLimits({100, 1u << 20});
  LoadWarnings warnings;
  Scene s = loadObj(obj, warnings);
  setTextureLimits({});
  ASSERT_EQ(s.textures.size(), 2u);
  EXPECT_EQ(s.textures[0].width, 100u);
  EXPECT_EQ(s.textures[0].height, 66u);
  EXPECT_EQ(s.textures[0].bytes[0], 90);
  EXPECT_EQ(warnings.messages.size(), 2u);
  // A memory limit below the two textures' 480 000 bytes shrinks both.
  setTextureLimits({8192, 200000});
  LoadWarnings fewer;
  s = loadObj(obj, fewer);
  setTextureLimits({});
  uint64_t total = 0;
  for (const Texture& t : s.textures) total += t.bytes.size();
  EXPECT_LE(total, 200000u);
  ASSERT_EQ(fewer.messages.size(), 2u);
  EXPECT_NE(fewer.messages[0].find("--max-texture-memory"), std::string::npos) << fewer.messages[0];
}

TEST(TextureLimits, SceneCacheHoldsOnlyTexturesDecodedUnderTheDefaults) {
  TempFolder dir;
  std::vector<uint8_t> pixels(size_t(300) * 200 * 3, 90);
  ASSERT_TRUE(stbi_write_png(dir.file("a.png").c_str(), 300, 200, 3, pixels.data(), 300 * 3));
  dir.write("m.mtl", "newmtl a\nmap_Kd a.png\n");
  const std::string obj = dir.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
  const SceneCacheSettings cache{true, dir.file("cache")};
  SceneLoadOptions small, defaults;
  small.cache = defaults.cache = cache;
  small.textureLimits = {100, 1u << 20};
  EXPECT_EQ(loadScene(obj, small).textures.at(0).width, 100u);
  EXPECT_EQ(loadScene(obj, defaults).textures.at(0).width, 300u);
  EXPECT_EQ(loadScene(obj, defaults).textures.at(0).width, 300u);  // now from the cache
  EXPECT_EQ(loadScene(obj, small).textures.at(0).width, 100u);
}

TEST(TextureLimits, SceneOfSeveralModelsIsFittedAsAWhole) {
  Scene scene;
  for (const char* name : {"a.png", "b.hdr"}) {
    Texture t;
    t.name = name;
    t.width = 40;
    t.height = 20;
    t.channels = 1;
    if (name[0] == 'a')
      t.bytes.assign(800, 60);
    else
      t.floats.assign(800, 2.5f);
    scene.textures.push_back(t);
  }
  LoadWarnings warnings;
  fitSceneTextures(scene, {20, 1u << 20}, warnings);
  ASSERT_EQ(warnings.messages.size(), 2u);
  EXPECT_EQ(warnings.messages[1].rfind("b.hdr: texture of 40x20 pixels downscaled to 20x10", 0), 0u)
      << warnings.messages[1];
  EXPECT_EQ(scene.textures[0].bytes, std::vector<uint8_t>(200, 60));
  EXPECT_EQ(scene.textures[1].floats, std::vector<float>(200, 2.5f));
  EXPECT_EQ(scene.textures[1].width, 20u);
}

}  // namespace
}  // namespace candela
