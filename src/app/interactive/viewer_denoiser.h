#pragma once
#include <memory>
#include <string>

#include "app/denoising/optix_ai_denoiser.h"
#include "app/interactive/post_settings.h"
#include "app/interactive/render_session.h"
#include "backends/film_display.h"
#include "backends/film_filters.h"

namespace candela {

// The viewer's denoisers applied to the session's accumulated image. The OptiX AI denoiser is made when first
// asked for and kept for the frames after, so that its model and memory are not made again every frame.
class ViewerDenoiser {
 public:
  // Makes the OptiX AI denoiser unless it is made already. Throws std::runtime_error with one sentence where it
  // cannot run: not in this build, no usable GPU, or no denoiser weights in the driver (OptiX error 7990).
  void prepareOptix();
  // For a window or page: prepares the OptiX AI denoiser where `choice` asks for it; where it cannot run, turns
  // `choice` to None and returns the sentence to show (empty when nothing went wrong).
  std::string prepareOrTurnOff(DenoiserChoice& choice);

  // The accumulated image through `choice` (None: as it is). The AOVs must be enabled for the others, and
  // prepareOptix must have succeeded for Optix. A-trous, called once per frame: once the accumulation restarted
  // (the camera or scene changed) the temporal filter (image/filters/temporal.h) runs, with the history of the frames
  // before, until the film holds kTemporalSamples samples; then the spatial filter, which mixes in the raw pixels as
  // they converge, so the image sharpens when the camera stops.
  Image apply(const RenderSession& session, DenoiserChoice choice, const AtrousParams& atrousParams);

  // What the a-trous choice shows of the film this frame, for Backend::display (backends/film_display.h): the
  // temporal or the spatial filter, by the rule of apply(), whose history and state it advances as apply() does.
  DisplaySource atrousSource(const RenderSession& session, const AtrousParams& params);

  // Samples after which a film that stands still is filtered spatially again: the temporal history counts as at most
  // this many (TemporalParams::maxHistory).
  static constexpr uint32_t kTemporalSamples = 16;
  bool temporalActive() const { return temporalActive_; }

 private:
  OptixAiDenoise optix_;
  std::unique_ptr<TemporalDenoiser> temporal_;
  const Backend* temporalBackend_ = nullptr;  // the one temporal_ reads
  bool haveFrame_ = false, temporalActive_ = false;
  uint64_t lastRestarts_ = 0;
};

}  // namespace candela
