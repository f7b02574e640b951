#include "backends/backend.h"
#include "backends/film_filters.h"

namespace candela {

namespace {

class HostTemporalDenoiser final : public TemporalDenoiser {
 public:
  HostTemporalDenoiser(const Backend& backend, const TemporalParams& params) : backend_(backend), filter_(params) {}
  Image denoise(const Camera& camera, bool filmContinues) override {
    const Image color = backend_.readImage();
    const AovImages aovs = backend_.readAovs();
    return filter_.filter({color, aovs, camera, backend_.accumulatedSamples(), filmContinues});
  }
  void reset() override { filter_.reset(); }
  const TemporalParams& params() const override { return filter_.params(); }

 private:
  const Backend& backend_;
  TemporalFilter filter_;
};

}  // namespace

Image HostFilmFilters::atrous(const AtrousParams& params) const {
  return atrousDenoise(backend_.readImage(), backend_.readAovs(), params);
}

Image HostFilmFilters::bilateral(const BilateralParams& params) const {
  return bilateralFilter(backend_.readImage(), backend_.readEmission(), params);
}

std::unique_ptr<TemporalDenoiser> HostFilmFilters::temporal(const TemporalParams& params) const {
  return std::make_unique<HostTemporalDenoiser>(backend_, params);
}

}  // namespace candela
