#pragma once
#include <vector>

#include "image/aov_images.h"
#include "image/filters/atrous.h"
#include "image/image.h"
#include "kernel/camera.h"

namespace candela {

// Temporal accumulation with reprojection in front of the a-trous filter, as SVGF does (Schied et al. 2017), for
// images that change with the camera: the viewer while the camera moves, `candela render --camera-path`.
// Each frame, the previous frame's history is reprojected to the current pixels (the current first-hit point,
// from the depth AOV along the pixel's centre ray, projected by the previous camera), kept only where the
// previous pixels show the same surface (depth and normal agree, both emit or neither does) and mixed with the
// current film by sample counts (a history counts as at most maxHistory samples). The accumulated reflected light
// (demodulated) then goes through the a-trous passes, whose first level becomes the next frame's history; the
// accumulated emission goes through passes of its own, as in atrousDenoise. Where the history is long, the first
// pass's colour width comes from the variance of the frames' luminance (their moments) instead of the pixel's
// neighbourhood. No mix with the raw pixels: the history is what makes the image steady.
struct TemporalParams {
  AtrousParams atrous;
  float maxHistory = 16.0f;
  float depthTolerance = 0.05f;
  float normalTolerance = 0.9f;
};

// Throws std::invalid_argument for bad a-trous params, a maxHistory below 1 or tolerances out of range.
void validateTemporalParams(const TemporalParams& params);

// The frames in the temporal filter's terms.
struct TemporalFrame {
  const Image& color;     // the film's mean radiance
  const AovImages& aovs;  // its AOVs (emission included)
  Camera camera;          // that saw it
  uint32_t samples;       // per pixel in the film
  // Whether the film continues the previous frame's (same camera and scene: samples were added to it), so that
  // the history it started from is not to be reprojected again.
  bool filmContinues;
};

// The history of one sequence of frames, in host memory.
class TemporalFilter {
 public:
  explicit TemporalFilter(TemporalParams params = {});
  // The frame filtered; the history moves on to it. A frame of another size than the history's starts afresh.
  Image filter(const TemporalFrame& frame);
  // Forgets the history (a new scene).
  void reset();
  const TemporalParams& params() const { return params_; }

 private:
  struct History {
    std::vector<Vec3> reflected, emission, normal;
    std::vector<float> length, moment1, moment2, depth;
    std::vector<uint8_t> emissive;
    void resize(size_t pixels);
  };
  TemporalParams params_;
  uint32_t width_ = 0, height_ = 0;
  bool haveHistory_ = false;
  Camera camera_;
  History base_;  // the history the current film started from, reprojected to its camera
  History last_;  // the last frame's, for the next film to start from
  // Scratch kept from frame to frame rather than allocated per frame: a 1080p frame's planes take 124 MB, and memory
  // new to the process is faulted in page by page.
  AtrousWorkspace workspace_;
  std::vector<float> variance_;  // the first pass's variance of each pixel's luminance
};

}  // namespace candela
