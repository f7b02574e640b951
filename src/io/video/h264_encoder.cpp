#include "io/video/h264_encoder.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

extern "C" {
#include <x264.h>
}

namespace candela {

namespace {

// BT.709 luma weights; limited range: luma 16..235, chroma 16..240 (H.273).
constexpr float kR = 0.2126f, kG = 0.7152f, kB = 0.0722f;

uint8_t toByte(float v) { return uint8_t(std::clamp(std::lround(v), 0L, 255L)); }

float luma(float r, float g, float b) { return 16.0f + (219.0f / 255.0f) * (kR * r + kG * g + kB * b); }

// Fills the picture's planes (codedWidth x codedHeight, each the frame's size rounded up to even) from the frame of
// width x height pixels, two rows at a time in parallel; the padding repeats the last column and row. Each chroma
// sample is of the mean of its 2 x 2 pixels.
void convertToI420(const uint8_t* rgb, uint32_t width, uint32_t height, x264_image_t& image) {
  const uint32_t codedWidth = (width + 1) & ~1u, codedHeight = (height + 1) & ~1u;
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, codedHeight / 2), [&](const tbb::blocked_range<uint32_t>& rows) {
    for (uint32_t cy = rows.begin(); cy != rows.end(); ++cy) {
      const uint8_t* source[2] = {rgb + size_t(2 * cy) * width * 3,
                                  rgb + size_t(std::min(2 * cy + 1, height - 1)) * width * 3};
      uint8_t* luma0 = image.plane[0] + size_t(2 * cy) * size_t(image.i_stride[0]);
      uint8_t* lumaRows[2] = {luma0, luma0 + image.i_stride[0]};
      uint8_t* cb = image.plane[1] + size_t(cy) * size_t(image.i_stride[1]);
      uint8_t* cr = image.plane[2] + size_t(cy) * size_t(image.i_stride[2]);
      for (uint32_t cx = 0; cx < codedWidth / 2; ++cx) {
        float r = 0.0f, g = 0.0f, b = 0.0f;
        for (uint32_t dy = 0; dy < 2; ++dy)
          for (uint32_t dx = 0; dx < 2; ++dx) {
            const uint8_t* p = source[dy] + 3 * size_t(std::min(2 * cx + dx, width - 1));
            lumaRows[dy][2 * cx + dx] = toByte(luma(p[0], p[1], p[2]));
            r += float(p[0]);
            g += float(p[1]);
            b += float(p[2]);
          }
        r *= 0.25f;
        g *= 0.25f;
        b *= 0.25f;
        const float y = kR * r + kG * g + kB * b;
        cb[cx] = toByte(128.0f + (224.0f / 255.0f) * (b - y) / (2.0f * (1.0f - kB)));
        cr[cx] = toByte(128.0f + (224.0f / 255.0f) * (r - y) / (2.0f * (1.0f - kR)));
      }
    }
  });
}

// The WebCodecs codec string of an SPS NAL unit's first bytes (profile_idc, constraint flags, level_idc).
std::string codecString(const uint8_t* sps) {
  char text[16];
  std::snprintf(text, sizeof text, "avc1.%02X%02X%02X", sps[1], sps[2], sps[3]);
  return text;
}

}  // namespace

struct H264Encoder::State {
  x264_param_t param{};
  x264_t* encoder = nullptr;
  x264_picture_t picture{};
  bool pictureAllocated = false;
  uint32_t frameWidth = 0, frameHeight = 0;
  H264Settings settings;
  std::string codec;
  int64_t pts = 0;

  ~State() { close(); }

  void close() {
    if (encoder) x264_encoder_close(encoder);
    if (pictureAllocated) x264_picture_clean(&picture);
    encoder = nullptr;
    pictureAllocated = false;
  }

  // The settings x264_encoder_reconfig takes from one frame to the next: the deblocking filter and the rate. The
  // rate control counts time in frames of the opened frame rate: at `s.framesPerSecond` frames a second, a
  // frame's share of the rate is maxKilobitsPerSecond / s.framesPerSecond, which a limit scaled by the ratio of
  // the two rates gives it.
  void applySettings(const H264Settings& s) {
    param.b_deblocking_filter = s.deblocking ? 1 : 0;
    const uint64_t measured = std::max(1u, s.framesPerSecond);
    param.rc.i_rc_method = X264_RC_CRF;
    param.rc.f_rf_constant = s.rateFactor;
    param.rc.i_vbv_max_bitrate =
        int(std::max<uint64_t>(1, uint64_t(s.maxKilobitsPerSecond) * param.i_fps_num / measured));
    // A buffer of two frames at the rate: no frame much larger than its share, which would arrive late.
    param.rc.i_vbv_buffer_size = int(std::max<uint64_t>(1, 2 * uint64_t(s.maxKilobitsPerSecond) / measured));
    settings = s;
  }

  // The stream's pictures are the frame's size rounded up to even: 4:2:0 H.264 cannot crop a single column or row.
  void open(uint32_t width, uint32_t height, const H264Settings& s, unsigned threads) {
    const uint32_t codedWidth = (width + 1) & ~1u, codedHeight = (height + 1) & ~1u;
    close();
    // ultrafast: the encoder keeps up with the GPU's frames at 1080p; zerolatency: no B-frames, no look-ahead,
    // slice threads, so that a frame's access unit comes out of the call that took it.
    if (x264_param_default_preset(&param, "ultrafast", "zerolatency") < 0)
      throw std::runtime_error("x264: no ultrafast/zerolatency preset");
    param.i_width = int(codedWidth);
    param.i_height = int(codedHeight);
    param.i_csp = X264_CSP_I420;
    param.i_threads = threads ? int(threads) : X264_THREADS_AUTO;
    param.i_log_level = X264_LOG_NONE;
    param.i_keyint_max = X264_KEYINT_MAX_INFINITE;  // key frames where the stream needs them (encode's `key`)
    param.b_annexb = 1;
    param.b_repeat_headers = 1;
    param.vui.i_colorprim = 2;
    param.vui.i_transfer = 2;
    param.vui.i_colmatrix = 1;  // BT.709
    param.vui.b_fullrange = 0;
    param.i_fps_num = std::max(1u, s.framesPerSecond);
    param.i_fps_den = 1;
    applySettings(s);
    if (x264_param_apply_profile(&param, "high") < 0) throw std::runtime_error("x264: the high profile is refused");
    encoder = x264_encoder_open(&param);
    if (!encoder)
      throw std::runtime_error("x264 could not open an encoder for " + std::to_string(width) + " x " +
                               std::to_string(height) + " frames");
    frameWidth = width;
    frameHeight = height;
    if (x264_picture_alloc(&picture, X264_CSP_I420, int(codedWidth), int(codedHeight)) < 0)
      throw std::runtime_error("x264 could not allocate a picture");
    pictureAllocated = true;
    codec.clear();
  }
};

H264Encoder::H264Encoder(unsigned threads) : state_(std::make_unique<State>()), threads_(threads) {}

H264Encoder::~H264Encoder() = default;

H264Frame H264Encoder::encode(const uint8_t* rgb, uint32_t width, uint32_t height, const H264Settings& settings,
                              bool key) {
  const auto start = std::chrono::steady_clock::now();
  if (width < 2 || height < 2) throw std::invalid_argument("an H.264 frame needs at least 2 x 2 pixels");
  State& s = *state_;
  const bool reopen = !s.encoder || s.frameWidth != width || s.frameHeight != height;
  if (reopen) {
    s.open(width, height, settings, threads_);
  } else if (settings != s.settings) {
    s.applySettings(settings);
    if (x264_encoder_reconfig(s.encoder, &s.param) < 0) throw std::runtime_error("x264 refused the new settings");
  }
  convertToI420(rgb, width, height, s.picture.img);
  s.picture.i_type = key || reopen ? X264_TYPE_IDR : X264_TYPE_AUTO;
  s.picture.i_pts = s.pts++;
  x264_nal_t* nals = nullptr;
  int count = 0;
  x264_picture_t out;
  const int bytes = x264_encoder_encode(s.encoder, &nals, &count, &s.picture, &out);
  if (bytes < 0) throw std::runtime_error("x264 failed to encode a frame");
  if (bytes == 0 || count == 0) throw std::runtime_error("x264 held a frame back (it should not, at zero latency)");
  H264Frame frame;
  frame.width = width;
  frame.height = height;
  frame.key = out.b_keyframe != 0;
  // x264 writes a frame's NAL units one after the other in one buffer.
  frame.bytes.assign(reinterpret_cast<const char*>(nals[0].p_payload), size_t(bytes));
  for (int i = 0; i < count; ++i)
    if (nals[i].i_type == NAL_SPS && nals[i].i_payload >= 8) s.codec = codecString(nals[i].p_payload + 4);
  frame.codec = s.codec;
  frame.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return frame;
}

}  // namespace candela
