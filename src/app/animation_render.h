#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "app/render_job.h"
#include "io/images/image_io.h"

namespace candela {

// Frames `first` to `last` of a sequence, both included.
struct FrameRange {
  int64_t first = 0;
  int64_t last = 0;
};

// What `candela render` was asked to animate: one moment (--time) or a sequence of frames (--frames, --fps).
struct AnimationRequest {
  std::optional<double> time;  // seconds
  std::optional<FrameRange> frames;
  double framesPerSecond = 24.0;
  std::string clip;  // the animation to play, by name or index; empty: the first

  bool requested() const { return time.has_value() || frames.has_value(); }
};

constexpr int64_t kMaxFrameNumber = 9'999'999;

// "A:B" with 0 <= A <= B <= kMaxFrameNumber. Throws std::invalid_argument saying what is wrong.
FrameRange parseFrameRange(const std::string& text);

// The file name of frame `frame` of a sequence written to `output`: the last run of '#' in its file name is
// replaced by the frame number, padded with zeros to the run's length (out_####.png: out_0007.png); a name
// without '#' gets "_####" before its extension (out.png: out_0007.png).
std::string frameFileName(const std::string& output, int64_t frame);

// Renders the job's scene posed by its animation at request.time into `output`, or every frame of
// request.frames (frame f at f / request.framesPerSecond seconds) into frameFileName(output, f). The scene is
// loaded and handed to the backend once; each frame only poses the animated instances, cameras and lights again
// (Backend::setInstanceTransforms) and deforms skinned and morphed meshes (Backend::setDeformedMeshes). Every file is
// written atomically, and the paths written are printed on stdout as they are done. A scene without an animation
// renders the same image at every time, with a warning. With `job.team`, every process of the team calls it: each
// frame's sample indices are shared among them, and the writer writes the frames. Throws std::runtime_error on
// failure.
int runAnimatedRender(const RenderJob& job, const AnimationRequest& request, const std::string& output,
                      const DisplaySettings& display);

}  // namespace candela
