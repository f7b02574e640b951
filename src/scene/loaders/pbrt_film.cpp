#include "scene/loaders/pbrt_film.h"

#include <algorithm>
#include <cmath>

#include "scene/loaders/load_diagnostics.h"

namespace candela {

PbrtFilm readPbrtFilm(const PbrtParameters* film, const PbrtParameters* camera, PbrtContext& context) {
  PbrtFilm result;
  float iso = 100.0f;
  if (film) {
    // The same ranges as a JSON scene file's render settings (scene_file.cpp).
    result.width = uint32_t(std::clamp(film->getInt("xresolution", 1280), 1, 16384));
    result.height = uint32_t(std::clamp(film->getInt("yresolution", 720), 1, 16384));
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
