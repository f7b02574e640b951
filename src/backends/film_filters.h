#pragma once
// The filters that run on a backend's film (Backend::filters): where the film lives on a GPU they run there and
// only the result is read back; on the host they run on the film's means.
#include <memory>

#include "image/filters/atrous.h"
#include "image/filters/bilateral.h"
#include "image/filters/temporal.h"
#include "image/image.h"
#include "kernel/camera.h"

namespace candela {

class Backend;

// The temporal filter (image/filters/temporal.h) applied to a backend's film frame after frame; it keeps the
// history. Made by FilmFilters::temporal, used while that backend lives.
class TemporalDenoiser {
 public:
  virtual ~TemporalDenoiser() = default;
  // The backend's accumulated image through the filter (the AOVs must be enabled). `camera` is the one that saw
  // the film; `filmContinues` says that the film is the one the previous call filtered, with samples added since
  // (the camera and scene did not change).
  virtual Image denoise(const Camera& camera, bool filmContinues) = 0;
  // Forgets the history (a new scene).
  virtual void reset() = 0;
  virtual const TemporalParams& params() const = 0;
};

class FilmFilters {
 public:
  virtual ~FilmFilters() = default;
  // The accumulated image through the a-trous filter guided by the AOVs, or through the bilateral filter, which
  // keeps the emission apart. Both need the backend's AOVs enabled (the emission is recorded with them).
  virtual Image atrous(const AtrousParams& params) const = 0;
  virtual Image bilateral(const BilateralParams& params) const = 0;
  // The temporal filter for this film.
  virtual std::unique_ptr<TemporalDenoiser> temporal(const TemporalParams& params) const = 0;
};

// The filters on the host, on the backend's readImage(), readEmission() and readAovs(): right for any backend,
// the natural ones for a backend whose film is in host memory.
class HostFilmFilters final : public FilmFilters {
 public:
  explicit HostFilmFilters(const Backend& backend) : backend_(backend) {}
  Image atrous(const AtrousParams& params) const override;
  Image bilateral(const BilateralParams& params) const override;
  std::unique_ptr<TemporalDenoiser> temporal(const TemporalParams& params) const override;

 private:
  const Backend& backend_;
};

}  // namespace candela
