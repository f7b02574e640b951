#include "scene/loaders/pbrt/pbrt_grid_media.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "io/load_budget.h"
#include "scene/loaders/pbrt/pbrt_nanovdb_medium.h"
#include "scene/loaders/pbrt/pbrt_temperature_emission.h"
#include "scene/medium_grids.h"
#include "scene/transform.h"

namespace candela {

namespace {

// The largest optical depth (sigma_t x length) along a grid medium's box diagonal that is tracked.
constexpr double kMaxOpticalDepth = 1e6;

// sigma_a or sigma_s (pbrt's default 1) or another colour, finite and not negative.
Vec3 colour(const PbrtParameters& params, const char* name, Vec3 fallback) {
  std::optional<PbrtColor> c = params.getColor(name);
  Vec3 v = c ? c->rgb : fallback;
  if (!isFinite(v) || v.x < 0.0f || v.y < 0.0f || v.z < 0.0f)
    params.fail(std::string("medium: '") + name + "' must be finite and not negative");
  return v;
}

float nonNegative(const PbrtParameters& params, const char* name, float fallback) {
  const float v = params.getFloat(name, fallback);
  if (!(v >= 0.0f) || !std::isfinite(v))
    params.fail(std::string("medium: '") + name + "' must be finite and not negative");
  return v;
}

// The box the grid fills in the medium's own space, pbrt's p0 and p1.
void readBox(const PbrtParameters& params, MediumGrid& grid) {
  auto point = [&](const char* name, Vec3 fallback) {
    std::vector<Vec3> p = params.getVec3s(name);
    if (p.size() > 1) params.fail(std::string("medium: '") + name + "' needs one point");
    return p.empty() ? fallback : p[0];
  };
  grid.p0 = point("p0", {0, 0, 0});
  grid.p1 = point("p1", {1, 1, 1});
}

// Where the grid sits: its box must be finite and not empty, and the transform from world space into the box's
// space must exist.
void placeGrid(const PbrtParameters& params, const glm::mat4& worldFromGrid, MediumGrid& grid) {
  const Vec3 extent = grid.p1 - grid.p0;
  if (!isFinite(grid.p0) || !isFinite(grid.p1) || !(extent.x > 0.0f && extent.y > 0.0f && extent.z > 0.0f))
    params.fail("medium: its box from 'p0' to 'p1' must be finite and not empty");
  const float det = glm::determinant(worldFromGrid);
  if (!(std::fabs(det) > 0.0f) || !std::isfinite(det)) params.fail("medium: its transform cannot be inverted");
  grid.mediumFromWorld = toAffine(glm::inverse(worldFromGrid));
  for (float v : grid.mediumFromWorld.m)
    if (!std::isfinite(v)) params.fail("medium: its transform cannot be inverted");
}

// nx, ny, nz (pbrt's default 1 each), which must describe `count` samples of `channels` numbers each.
uint64_t readResolution(const PbrtParameters& params, const std::string& what, size_t count, uint32_t channels,
                        MediumGrid& grid) {
  const int64_t n[3] = {params.getInt("nx", 1), params.getInt("ny", 1), params.getInt("nz", 1)};
  for (int64_t v : n)
    if (v < 1 || v > (int64_t(1) << 20)) params.fail("medium: 'nx', 'ny' and 'nz' must lie between 1 and 2^20");
  const uint64_t samples = uint64_t(n[0]) * uint64_t(n[1]) * uint64_t(n[2]);
  if (count % channels != 0 || count / channels != samples)
    params.fail("medium: " + what + " has " + std::to_string(count / channels) +
                " values where nx*ny*nz = " + std::to_string(samples));
  grid.nx = uint32_t(n[0]);
  grid.ny = uint32_t(n[1]);
  grid.nz = uint32_t(n[2]);
  return samples;
}

}  // namespace

void checkGridValuesRoom(const PbrtParameters& params, const std::string& name, uint64_t values) {
  const uint64_t majorantRoom = uint64_t(kMajorantGridResolution) * kMajorantGridResolution * kMajorantGridResolution;
  if (values + majorantRoom >= uint64_t(kNoGridValues))
    params.fail("medium '" + name + "': the scene's grids hold more than 2^32 samples");
}

namespace {

// Appends `count` samples, value(i) each, to the scene's grid samples, charged to the load's budget; returns
// their offset. `parameter` names them in messages. Samples below `lowest` are refused (only temperatures may be
// negative).
template <typename Value>
uint32_t appendSamples(const PbrtParameters& params, const std::string& mediumName, const char* parameter, size_t count,
                       Value value, Scene& scene, double lowest = 0.0) {
  checkGridValuesRoom(params, mediumName, scene.mediumGridValues.size() + count);
  chargeLoadMemory(count * sizeof(float), params.file + ":" + std::to_string(params.line),
                   "medium '" + mediumName + "' " + parameter);
  const uint32_t offset = uint32_t(scene.mediumGridValues.size());
  for (size_t i = 0; i < count; ++i) {
    const double v = value(i);
    if (!std::isfinite(v) || v < lowest || std::fabs(v) > double(std::numeric_limits<float>::max()))
      params.fail("medium '" + mediumName + "': '" + parameter + "' has a " +
                  (lowest < 0.0 ? "non-finite" : "negative or non-finite") + " value");
    scene.mediumGridValues.push_back(float(v));
  }
  return offset;
}

// Appends a parameter's numbers to the scene's grid samples.
uint32_t appendSamples(const PbrtParameters& params, const std::string& mediumName, const char* parameter,
                       const std::vector<double>& numbers, Scene& scene) {
  return appendSamples(
      params, mediumName, parameter, numbers.size(), [&](size_t i) { return numbers[i]; }, scene);
}

// pbrt-v4's GridMedium with a `temperature` grid (as many values as `density`): Le is `Lescale` (a grid, or 1) x
// the blackbody of the temperature at each point (pbrt_temperature_emission.h: `temperatureoffset` or
// `temperaturecutoff`, `temperaturescale`). A grid whose temperatures cannot exceed the cutoff keeps its density
// alone and does not emit.
void readTemperatureGrid(const PbrtParameters& params, const std::string& name, const std::vector<double>& density,
                         const std::vector<double>& temperature, const std::vector<double>& leScale, Medium& m,
                         MediumGrid& grid, Scene& scene) {
  if (params.find("Le")) params.fail("uniformgrid medium '" + name + "': 'Le' and 'temperature' are both given");
  if (temperature.size() != density.size())
    params.fail("uniformgrid medium: 'temperature' has " + std::to_string(temperature.size()) +
                " values where nx*ny*nz = " + std::to_string(density.size()));
  grid.density = appendSamples(params, name, "density", density, scene);
  const uint32_t temperatures = appendSamples(
      params, name, "temperature", temperature.size(), [&](size_t i) { return temperature[i]; }, scene,
      -double(std::numeric_limits<float>::max()));
  if (!emitFromTemperature(params, name, temperatures, readTemperatureToKelvin(params), grid, scene)) return;
  if (!leScale.empty()) grid.emission = appendSamples(params, name, "Lescale", leScale, scene);
  m.emission = Vec3{1, 1, 1};
}

// An rgb array parameter's numbers (3 per sample), or none where absent.
std::vector<double> rgbNumbers(const PbrtParameters& params, const char* name) {
  const PbrtParameter* p = params.find(name);
  if (!p) return {};
  if (p->type != "rgb") params.fail(std::string("rgbgrid medium: '") + name + "' must be given as rgb values");
  p->used = true;
  if (p->numbers.empty() || p->numbers.size() % 3 != 0)
    params.fail(std::string("rgbgrid medium: '") + name + "' needs 3 numbers per sample");
  return p->numbers;
}

}  // namespace

bool isPbrtGridMedium(const std::string& type) {
  return type == "uniformgrid" || type == "rgbgrid" || type == "cloud" || type == "nanovdb";
}

Medium readPbrtGridMedium(const std::string& type, const std::string& name, const PbrtParameters& params,
                          const glm::mat4& worldFromMedium, PbrtContext& context) {
  Scene& scene = context.scene;
  Medium m;
  m.g = params.getFloat("g", 0.0f);
  if (!(std::fabs(m.g) < 1.0f)) params.fail("medium: 'g' must lie between -1 and 1");
  MediumGrid grid;
  // A nanovdb grid's box is in its file's index space, the others' in the medium's space.
  glm::mat4 worldFromGrid = worldFromMedium;
  if (type == "nanovdb") {
    const float scale = nonNegative(params, "scale", 1.0f);
    m.sigmaA = colour(params, "sigma_a", {1, 1, 1}) * scale;
    m.sigmaS = colour(params, "sigma_s", {1, 1, 1}) * scale;
    worldFromGrid = worldFromMedium * readPbrtNanoVdbGrids(name, params, context, m, grid);
  } else {
    readBox(params, grid);
  }
  placeGrid(params, worldFromGrid, grid);
  if (type == "cloud") {
    // pbrt's CloudMedium takes no `scale`.
    grid.kind = MediumGridKind::Cloud;
    m.sigmaA = colour(params, "sigma_a", {1, 1, 1});
    m.sigmaS = colour(params, "sigma_s", {1, 1, 1});
    grid.cloudDensity = nonNegative(params, "density", 1.0f);
    grid.wispiness = nonNegative(params, "wispiness", 1.0f);
    grid.frequency = nonNegative(params, "frequency", 5.0f);
  } else if (type == "uniformgrid") {
    grid.kind = MediumGridKind::Density;
    const float scale = nonNegative(params, "scale", 1.0f);
    m.sigmaA = colour(params, "sigma_a", {1, 1, 1}) * scale;
    m.sigmaS = colour(params, "sigma_s", {1, 1, 1}) * scale;
    const std::vector<double> density = params.getNumbers("density");
    if (density.empty()) params.fail("uniformgrid medium '" + name + "' needs \"density\" values");
    readResolution(params, "'density'", density.size(), 1, grid);
    const std::vector<double> leScale = params.getNumbers("Lescale");
    if (!leScale.empty() && leScale.size() != density.size())
      params.fail("uniformgrid medium: 'Lescale' has " + std::to_string(leScale.size()) +
                  " values where nx*ny*nz = " + std::to_string(density.size()));
    const std::vector<double> temperature = params.getNumbers("temperature");
    if (!temperature.empty()) {
      readTemperatureGrid(params, name, density, temperature, leScale, m, grid, scene);
    } else {
      grid.density = appendSamples(params, name, "density", density, scene);
      m.emission = colour(params, "Le", {0, 0, 0});
      if (!leScale.empty()) grid.emission = appendSamples(params, name, "Lescale", leScale, scene);
    }
  } else if (type == "rgbgrid") {
    grid.kind = MediumGridKind::Rgb;
    const float scale = nonNegative(params, "scale", 1.0f);
    m.sigmaA = m.sigmaS = Vec3{scale, scale, scale};
    const float leScale = nonNegative(params, "Lescale", 1.0f);
    m.emission = Vec3{leScale, leScale, leScale};
    const std::vector<double> sigmaA = rgbNumbers(params, "sigma_a"), sigmaS = rgbNumbers(params, "sigma_s");
    const std::vector<double> le = rgbNumbers(params, "Le");
    if (sigmaA.empty() && sigmaS.empty()) params.fail("rgbgrid medium '" + name + "' needs 'sigma_a' or 'sigma_s'");
    if (!le.empty() && sigmaA.empty()) params.fail("rgbgrid medium '" + name + "': 'Le' needs 'sigma_a'");
    const std::vector<double>& first = sigmaA.empty() ? sigmaS : sigmaA;
    readResolution(params, sigmaA.empty() ? "'sigma_s'" : "'sigma_a'", first.size(), 3, grid);
    for (const std::vector<double>* other : {&sigmaS, &le})
      if (!other->empty() && other->size() != first.size())
        params.fail("rgbgrid medium '" + name + "': 'sigma_a', 'sigma_s' and 'Le' need as many values each");
    if (!sigmaA.empty()) grid.sigmaA = appendSamples(params, name, "sigma_a", sigmaA, scene);
    if (!sigmaS.empty()) grid.sigmaS = appendSamples(params, name, "sigma_s", sigmaS, scene);
    if (!le.empty()) grid.emission = appendSamples(params, name, "Le", le, scene);
  }
  if (!isFinite(m.sigmaA) || !isFinite(m.sigmaS) || !isFinite(m.emission))
    params.fail("medium: its coefficients or emission overflow");
  buildMajorantGrid(m, grid, scene.mediumGridValues);
  // Tracking takes about (majorant x length) steps along a ray: bound it, so that a file cannot make one ray
  // endless. No medium that transmits anything comes near the limit (exp(-1e6)).
  float majorant = 0.0f;
  for (uint32_t i = 0; i < grid.mx * grid.my * grid.mz; ++i)
    majorant = std::max(majorant, scene.mediumGridValues[grid.majorants + i]);
  const glm::vec4 diagonal =
      worldFromGrid * glm::vec4(grid.p1.x - grid.p0.x, grid.p1.y - grid.p0.y, grid.p1.z - grid.p0.z, 0.0f);
  const double depth = double(majorant) * double(glm::length(glm::vec3(diagonal)));
  if (!(depth <= kMaxOpticalDepth))
    params.fail("medium '" + name + "' is too dense to track: its largest sigma_t times its size is " +
                std::to_string(depth) + ", above " + std::to_string(int(kMaxOpticalDepth)));
  m.grid = uint32_t(scene.mediumGrids.size());
  scene.mediumGrids.push_back(grid);
  return m;
}

}  // namespace candela
