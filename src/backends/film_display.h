#pragma once
// A backend's display frames (Backend::display): the accumulated image, or the film through one of its filters, as
// the 8-bit sRGB pixels a screen or a browser shows (image/display_pixels.h). Where the film lives on a GPU the
// filter, the tone mapping and the downscaling run there and only the bytes come back; on the host they run on
// the film's means, in parallel.
#include <array>
#include <cstdint>
#include <optional>
#include <variant>
#include <vector>

#include "backends/film_filters.h"
#include "backends/film_sums.h"
#include "image/display_pixels.h"
#include "kernel/camera.h"

namespace candela {

class Backend;

// What a display frame shows of the film: the accumulated image as it is (Backend::readImage), or through one of
// the backend's filters (backends/film_filters.h), each as that filter gives it.
struct AccumulatedImage {};
struct AtrousFiltered {
  AtrousParams params;
};
struct BilateralFiltered {
  BilateralParams params;
};
// Through a temporal filter made by this backend's FilmFilters::temporal, as TemporalDenoiser::denoise(camera,
// filmContinues) gives it; the filter keeps its history as there.
struct TemporalFiltered {
  TemporalDenoiser* denoiser = nullptr;
  Camera camera;
  bool filmContinues = false;
};
using DisplaySource = std::variant<AccumulatedImage, AtrousFiltered, BilateralFiltered, TemporalFiltered>;

// The linear image `source` gives on the host, through the backend's readImage() or filters(): what a display
// frame of it shows before tone mapping.
Image displaySourceImage(const Backend& backend, const DisplaySource& source);

struct DisplayRequest {
  DisplaySource source;
  // The front ends' bilateral display pass (PostSettings::bilateral) on the source's image, before tone mapping:
  // the bilateral filter (image/filters/bilateral.h) with the emission the camera sees kept apart, where the backend
  // records it (its AOVs are on), else on the whole image.
  std::optional<BilateralParams> smoothing;
  DisplaySettings display;
  uint32_t divisor = 1;  // see displaySize
};

// A frame's pixels and how long it took to make them (wall clock), for the timings a frame's header reports.
struct DisplayFrame {
  uint32_t width = 0, height = 0;
  // width * height pixels of three bytes, row-major, top row first. They stay valid until the second read() after
  // the one that gave them (a display alternates between two buffers), so that one frame can be encoded while the
  // next one is read.
  const uint8_t* rgb = nullptr;
  double filterMilliseconds = 0.0;  // the filter and the smoothing, where the request has them: part of the next
  double milliseconds = 0.0;        // the whole read: filters, tone mapping, downscaling and the read-back
};

class FilmDisplay {
 public:
  virtual ~FilmDisplay() = default;
  // The frame of `request`, from the backend's film as it is now. Throws std::invalid_argument for a divisor that
  // displaySize refuses or a temporal filter that is not this backend's, and std::logic_error where a filter needs
  // the AOVs and they are off. One read at a time.
  virtual DisplayFrame read(const DisplayRequest& request) const = 0;
};

// The display on the host, through the backend's readImage() and filters(): right for any backend, the natural
// one for a backend whose film is in host memory. Given that film's sums, it reads the accumulated image from them
// directly, without making an image of the means first.
class HostFilmDisplay final : public FilmDisplay {
 public:
  explicit HostFilmDisplay(const Backend& backend, const FilmSums* film = nullptr) : backend_(backend), film_(film) {}
  DisplayFrame read(const DisplayRequest& request) const override;

 private:
  const Backend& backend_;
  const FilmSums* film_;
  mutable std::array<std::vector<uint8_t>, 2> pixels_;
  mutable size_t next_ = 0;
};

}  // namespace candela
