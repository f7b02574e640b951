#include "app/interactive/viewer_denoiser.h"

#include <stdexcept>

namespace candela {

void ViewerDenoiser::prepareOptix() {
  if (!optix_) optix_ = makeOptixAiDenoiser();
}

std::string ViewerDenoiser::prepareOrTurnOff(DenoiserChoice& choice) {
  if (choice != DenoiserChoice::Optix) return {};
  try {
    prepareOptix();
  } catch (const std::runtime_error& e) {
    choice = DenoiserChoice::None;
    return std::string("no OptiX AI denoiser: ") + e.what() + "; denoising is off";
  }
  return {};
}

Image ViewerDenoiser::apply(const RenderSession& session, DenoiserChoice choice, const AtrousParams& atrousParams) {
  switch (choice) {
    case DenoiserChoice::None: return session.image();
    case DenoiserChoice::Atrous: return displaySourceImage(session.backend(), atrousSource(session, atrousParams));
    case DenoiserChoice::Optix:
      if (!optix_) throw std::logic_error("the OptiX AI denoiser was not prepared");
      return optix_(session.image(), session.backend().readAovs());
    case DenoiserChoice::Bilateral:
    case DenoiserChoice::Temporal: break;  // not among kViewerDenoiserChoices
  }
  throw std::logic_error("unknown denoiser");
}

DisplaySource ViewerDenoiser::atrousSource(const RenderSession& session, const AtrousParams& params) {
  const bool restarted = haveFrame_ && session.restarts() != lastRestarts_;
  haveFrame_ = true;
  lastRestarts_ = session.restarts();
  temporalActive_ = restarted || (temporalActive_ && session.accumulatedSamples() < kTemporalSamples);
  if (!temporalActive_) return AtrousFiltered{params};
  TemporalParams temporalParams;
  temporalParams.atrous = params;
  temporalParams.maxHistory = float(kTemporalSamples);
  if (!temporal_ || temporalBackend_ != &session.backend() || temporal_->params().atrous.passes != params.passes) {
    temporal_ = session.backend().filters().temporal(temporalParams);
    temporalBackend_ = &session.backend();
  }
  return TemporalFiltered{temporal_.get(), session.camera(), /*filmContinues=*/!restarted};
}

}  // namespace candela
