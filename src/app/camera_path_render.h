#pragma once
// `candela render --camera-path FILE` / `--camera-orbit FRAMES`: an image sequence along a camera path.
#include <cstdint>
#include <string>

#include "app/render_job.h"
#include "image/filters/temporal.h"
#include "io/images/image_io.h"

namespace candela {

// Where the cameras come from: a camera-path file (app/camera_path.h), or an orbit of `orbitFrames` frames over
// `orbitDegrees` around the scene camera's target.
struct CameraPathSource {
  std::string file;
  uint32_t orbitFrames = 0;
  float orbitDegrees = 360.0f;
  bool given() const { return !file.empty() || orbitFrames > 0; }
};

// Renders the job's scene once per camera of the path, job.samplesPerPixel samples per frame on a fresh film, and
// writes frame i to frameFileName(output, i, count) (each file replaced atomically), printing each file's path.
// job.denoiser "temporal" runs the temporal filter (image/filters/temporal.h) over the sequence; "atrous",
// "bilateral" and "optix" filter each frame alone, as for one image. Throws std::runtime_error on failure.
void runCameraPathRender(const RenderJob& job, const TemporalParams& temporal, const CameraPathSource& source,
                         const std::string& output, const DisplaySettings& display);

}  // namespace candela
