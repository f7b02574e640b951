#include "scene/loaders/pbrt/pbrt_film.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "io/load_diagnostics.h"

namespace candela {

PbrtFilm readPbrtFilm(const PbrtParameters* film, const PbrtParameters* camera, PbrtContext& context) {
  PbrtFilm result;
  float iso = 100.0f;
  if (film) {
    // The same ranges as a JSON scene file's render settings (scene_file.cpp).
    result.fullWidth = result.width = uint32_t(std::clamp(film->getInt("xresolution", 1280), 1, 16384));
    result.fullHeight = result.height = uint32_t(std::clamp(film->getInt("yresolution", 720), 1, 16384));
    if (film->find("cropwindow")) {
      const std::vector<double> crop = film->getNumbers("cropwindow");
      if (crop.size() != 4) film->fail("'cropwindow' needs 4 numbers: x0 x1 y0 y1");
      for (double bound : crop)
        if (!std::isfinite(bound)) film->fail("the film's 'cropwindow' is not finite");
      // As pbrt-v4: each pair in either order, clamped to [0, 1]; the pixels kept run from ceil(min * resolution)
      // to ceil(max * resolution).
      auto pixel = [](double bound, uint32_t resolution) {
        return uint32_t(std::ceil(std::clamp(bound, 0.0, 1.0) * double(resolution)));
      };
      const uint32_t x0 = pixel(std::min(crop[0], crop[1]), result.fullWidth);
      const uint32_t x1 = pixel(std::max(crop[0], crop[1]), result.fullWidth);
      const uint32_t y0 = pixel(std::min(crop[2], crop[3]), result.fullHeight);
      const uint32_t y1 = pixel(std::max(crop[2], crop[3]), result.fullHeight);
      if (x1 <= x0 || y1 <= y0) film->fail("the film's 'cropwindow' holds no pixel");
      result.cropX = x0;
      result.cropY = y0;
      result.width = x1 - x0;
      result.height = y1 - y0;
    }
    iso = film->getFloat("iso", 100.0f);
    film->getString("filename", "");  // the output is named on the command line
    if (!(iso > 0.0f) || !std::isfinite(iso)) film->fail("'iso' must be positive");
  }
  float exposureTime = 1.0f;
  if (camera) {
    float open = camera->getFloat("shutteropen", 0.0f), close = camera->getFloat("shutterclose", 1.0f);
    exposureTime = std::abs(close - open);  // pbrt-v4 swaps the two when they are in the wrong order
    if (!(exposureTime > 0.0f) || !std::isfinite(exposureTime))
      camera->fail("the camera's shutter times leave the shutter closed ('shutteropen' equals 'shutterclose')");
  }
  result.imagingRatio = exposureTime * iso / 100.0f;
  if (!std::isfinite(result.imagingRatio)) (film ? film : camera)->fail("the film's imaging ratio is not finite");
  if (film) context.warnUnused("film", *film);
  return result;
}

void scaleSceneLights(Scene& scene, float ratio) {
  if (ratio == 1.0f) return;
  for (Material& m : scene.materials) m.emission = m.emission * ratio;
  scene.environment.intensity *= ratio;
  for (PunctualLight& light : scene.punctualLights) light.intensity = light.intensity * ratio;
}

}  // namespace candela
