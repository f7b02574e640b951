#pragma once
// Frames of 8-bit RGB pixels as an H.264 stream for a browser's WebCodecs VideoDecoder (x264): Annex B byte
// stream, SPS and PPS before every key frame, no B-frames and no look-ahead, so that each frame comes out as soon
// as it goes in (one frame in, one access unit out), the way a remote desktop streams.
//
// The pixels are converted to 4:2:0 YCbCr with the BT.709 matrix in limited range, which the stream's VUI states
// (with the sRGB transfer), so that a decoder shows the same colours. H.264 4:2:0 needs an even size (and cannot
// crop one column or row off): a frame of odd width or height is coded with its last column or row repeated, which
// the page leaves out when it draws the decoded picture (its top-left width x height pixels are the frame's).
#include <cstdint>
#include <memory>
#include <string>

namespace candela {

struct H264Settings {
  // The rate the stream may use on average, and the quality it aims for within it (x264's constant rate factor:
  // lower is better; 18 is close to transparent).
  uint32_t maxKilobitsPerSecond = 20000;
  float rateFactor = 20.0f;
  // The rate the frames come at, as measured: the rate cap holds at it. x264 keeps the frame rate the stream was
  // opened with (x264_encoder_reconfig cannot change it), so a later rate scales the rate control's limits instead.
  uint32_t framesPerSecond = 60;
  // H.264's in-loop filter over the edges of the coded blocks (ultrafast leaves it off). It took 8-30% more of the
  // encoder's CPU time on 1080p frames and gave 0.3 dB at the same rate on rendered frames at rest, where the
  // picture matters more than the time; it can be switched from one frame to the next.
  bool deblocking = false;

  bool operator==(const H264Settings&) const = default;
};

struct H264Frame {
  uint32_t width = 0, height = 0;  // the frame's; the coded pictures are these rounded up to even
  bool key = false;                // an IDR frame: a decoder may start here
  std::string bytes;               // the access unit, Annex B
  // The WebCodecs codec string of the stream ("avc1.PPCCLL" from the SPS: profile, constraints, level).
  std::string codec;
  double milliseconds = 0.0;  // converting and encoding, wall clock
};

class H264Encoder {
 public:
  // `threads`: 0 for x264's choice from the hardware's threads.
  explicit H264Encoder(unsigned threads = 0);
  ~H264Encoder();
  H264Encoder(const H264Encoder&) = delete;
  H264Encoder& operator=(const H264Encoder&) = delete;

  // Encodes one frame (three bytes a pixel, row-major, top row first). The first frame, a frame of another size,
  // and one asked for with `key` are IDR frames. Settings that change take effect from this frame. Throws
  // std::invalid_argument for a frame smaller than 2 x 2 and std::runtime_error where x264 fails.
  H264Frame encode(const uint8_t* rgb, uint32_t width, uint32_t height, const H264Settings& settings, bool key);

 private:
  struct State;
  std::unique_ptr<State> state_;
  unsigned threads_;
};

}  // namespace candela
