#include "backends/optix/multi_gpu_backend.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <stdexcept>
#include <variant>

#include "backends/film_display.h"
#include "backends/film_filters.h"
#include "backends/optix/cuda_devices.h"
#include "backends/optix/optix_error.h"

namespace candela {

using optix::CurrentDevice;

namespace {

// Lets the first device read the others' memory directly where the GPUs allow it (NVLink or PCIe peer to
// peer); cudaMemcpyPeerAsync goes through host memory otherwise. Returns whether every pair allows it.
bool enablePeerAccess(const std::vector<int>& ordinals) {
  bool all = true;
  CurrentDevice first(ordinals[0]);
  for (size_t i = 1; i < ordinals.size(); ++i) {
    if (ordinals[i] == ordinals[0]) continue;  // the same GPU: an ordinary device-to-device copy
    int possible = 0;
    optix::checkCuda(cudaDeviceCanAccessPeer(&possible, ordinals[0], ordinals[i]), "asking for peer-to-peer access");
    if (!possible) {
      all = false;
      continue;
    }
    const cudaError_t result = cudaDeviceEnablePeerAccess(ordinals[i], 0);
    if (result == cudaErrorPeerAccessAlreadyEnabled)
      cudaGetLastError();
    else
      optix::checkCuda(result, "enabling peer-to-peer access");
  }
  return all;
}

// A temporal filter of the first device whose every frame starts by adding the other devices' films to its own.
class CombiningTemporalDenoiser : public TemporalDenoiser {
 public:
  CombiningTemporalDenoiser(std::unique_ptr<TemporalDenoiser> first, std::function<void()> combine, int ordinal)
      : first_(std::move(first)), combine_(std::move(combine)), ordinal_(ordinal) {}
  Image denoise(const Camera& camera, bool filmContinues) override {
    combine_();
    CurrentDevice device(ordinal_);
    return first_->denoise(camera, filmContinues);
  }
  void reset() override { first_->reset(); }
  const TemporalParams& params() const override { return first_->params(); }
  // The first device's filter, which the display frames run once they combined the films themselves.
  TemporalDenoiser* first() const { return first_.get(); }

 private:
  std::unique_ptr<TemporalDenoiser> first_;
  std::function<void()> combine_;
  int ordinal_;
};

}  // namespace

// What reads the film, filters it or writes from it runs on the first device, once the other devices' films are
// added to its own, with that device current.
template <typename Task>
auto MultiGpuBackend::onMergedFilm(Task&& task) const {
  mergeFilms();
  CurrentDevice device(ordinals_[0]);
  return task(*devices_[0]);
}

// The first device's filters, each run once the other devices' films are added to its own.
class MultiGpuBackend::CombinedFilmFilters final : public FilmFilters {
 public:
  explicit CombinedFilmFilters(const MultiGpuBackend& backend) : backend_(backend) {}

  Image atrous(const AtrousParams& params) const override {
    return backend_.onMergedFilm([&](const OptixBackend& first) { return first.filters().atrous(params); });
  }
  Image bilateral(const BilateralParams& params) const override {
    return backend_.onMergedFilm([&](const OptixBackend& first) { return first.filters().bilateral(params); });
  }
  std::unique_ptr<TemporalDenoiser> temporal(const TemporalParams& params) const override {
    CurrentDevice device(backend_.ordinals_[0]);
    return std::make_unique<CombiningTemporalDenoiser>(
        backend_.devices_[0]->filters().temporal(params), [this] { backend_.mergeFilms(); }, backend_.ordinals_[0]);
  }

 private:
  const MultiGpuBackend& backend_;
};

// The first device's display frames, each made once the other devices' films are added to its own.
class MultiGpuBackend::CombinedFilmDisplay final : public FilmDisplay {
 public:
  explicit CombinedFilmDisplay(const MultiGpuBackend& backend) : backend_(backend) {}

  DisplayFrame read(const DisplayRequest& request) const override {
    const auto start = std::chrono::steady_clock::now();
    DisplayRequest onFirst = request;
    if (auto* temporal = std::get_if<TemporalFiltered>(&onFirst.source)) {
      auto* combining = dynamic_cast<CombiningTemporalDenoiser*>(temporal->denoiser);
      if (!combining) throw std::invalid_argument("a display frame through a temporal filter of another backend");
      temporal->denoiser = combining->first();
    }
    DisplayFrame frame =
        backend_.onMergedFilm([&](const OptixBackend& first) { return first.display().read(onFirst); });
    frame.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return frame;
  }

 private:
  const MultiGpuBackend& backend_;
};

MultiGpuBackend::MultiGpuBackend(const std::vector<int>& deviceIndices, ProgramCompileListener compileProgress)
    : ordinals_(deviceIndices),
      threads_(deviceIndices.size()),
      devices_(deviceIndices.size()),
      balance_(deviceIndices.size()),
      unmerged_(deviceIndices.size()),
      filters_(std::make_unique<CombinedFilmFilters>(*this)),
      display_(std::make_unique<CombinedFilmDisplay>(*this)) {
  if (deviceIndices.size() < 2) throw std::logic_error("MultiGpuBackend needs two devices at least");
  try {
    // Each context is made on its own thread, which keeps that device current.
    threads_.run([&](size_t i) {
      devices_[i] =
          std::make_unique<OptixBackend>(deviceIndices[i], i == 0 ? compileProgress : ProgramCompileListener());
    });
    for (size_t i = 0; i < devices_.size(); ++i) ordinals_[i] = devices_[i]->deviceOrdinal();
    peerToPeer_ = enablePeerAccess(ordinals_);
  } catch (...) {
    threads_.run([&](size_t i) { devices_[i].reset(); });
    throw;
  }
  settings_ = RenderSettings{};
}

// Each device's memory is freed with that device current.
MultiGpuBackend::~MultiGpuBackend() {
  threads_.run([&](size_t i) {
    CurrentDevice device(ordinals_[i]);
    devices_[i].reset();
  });
}

std::string MultiGpuBackend::deviceName() const {
  std::string name = devices_[0]->deviceName();
  bool alike = true;
  std::string gpus;
  for (size_t i = 0; i < devices_.size(); ++i) {
    alike = alike && devices_[i]->deviceName() == name;
    gpus += (i ? ", " : "") + std::to_string(ordinals_[i]);
  }
  if (!alike) {
    name.clear();
    for (size_t i = 0; i < devices_.size(); ++i) name += (i ? " + " : "") + devices_[i]->deviceName();
  } else {
    name = std::to_string(devices_.size()) + " x " + name;
  }
  return name + " (GPUs " + gpus + "; combined " + (peerToPeer_ ? "peer to peer" : "through host memory") + ")";
}

void MultiGpuBackend::onEveryDevice(const std::function<void(OptixBackend&)>& task) {
  threads_.run([&](size_t i) {
    CurrentDevice device(ordinals_[i]);
    task(*devices_[i]);
  });
}

double MultiGpuBackend::preparePrograms(ProgramWait wait) {
  const auto start = std::chrono::steady_clock::now();
  onEveryDevice([wait](OptixBackend& device) { device.preparePrograms(wait); });
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void MultiGpuBackend::restart() {
  accumulated_ = 0;
  nextSample_ = 0;
  std::fill(unmerged_.begin(), unmerged_.end(), RowRange{});
}

void MultiGpuBackend::setScene(const Scene& scene) {
  onEveryDevice([&](OptixBackend& d) { d.setScene(scene); });
  restart();
}

void MultiGpuBackend::setInstanceTransforms(const Scene& scene) {
  onEveryDevice([&](OptixBackend& d) { d.setInstanceTransforms(scene); });
  restart();
}

bool MultiGpuBackend::setMaterials(const std::vector<Material>& materials) {
  std::vector<char> taken(devices_.size());
  threads_.run([&](size_t i) {
    CurrentDevice device(ordinals_[i]);
    taken[i] = devices_[i]->setMaterials(materials);
  });
  // Every device holds the same scene, so they all decide alike.
  if (std::count(taken.begin(), taken.end(), taken[0]) != std::ptrdiff_t(taken.size()))
    throw std::logic_error("MultiGpuBackend::setMaterials: the devices decided differently");
  if (taken[0]) restart();
  return taken[0];
}

void MultiGpuBackend::setEnvironment(const Environment& environment) {
  onEveryDevice([&](OptixBackend& d) { d.setEnvironment(environment); });
  restart();
}

void MultiGpuBackend::setCamera(const Camera& camera) {
  onEveryDevice([&](OptixBackend& d) { d.setCamera(camera); });
  restart();
}

void MultiGpuBackend::setSettings(const RenderSettings& settings) {
  // ReSTIR's spatial reuse reads the whole image's reservoirs of the same sample, which a split into bands of rows
  // scatters over the devices.
  if (settings.restir != RestirMode::Off && devices_.size() > 1)
    throw std::invalid_argument("--restir runs on one GPU: pick one with --devices");
  onEveryDevice([&](OptixBackend& d) { d.setSettings(settings); });
  settings_ = settings;
  restart();
}

void MultiGpuBackend::setAovsEnabled(bool enabled) {
  onEveryDevice([&](OptixBackend& d) { d.setAovsEnabled(enabled); });
  restart();
}

bool MultiGpuBackend::aovsEnabled() const { return devices_[0]->aovsEnabled(); }

FrameStats MultiGpuBackend::render(uint32_t samplesPerPixel) {
  const std::vector<DeviceShare> shares = planShares(samplesPerPixel, settings_.height, balance_.weights());
  std::vector<FrameStats> stats(devices_.size());
  threads_.run([&](size_t i) {
    const DeviceShare& share = shares[i];
    if (share.empty()) return;
    CurrentDevice device(ordinals_[i]);
    devices_[i]->setNextSampleIndex(nextSample_ + share.firstSample);
    stats[i] = devices_[i]->renderRows(share.samples, share.firstRow, share.rows);
  });
  FrameStats total;
  for (size_t i = 0; i < devices_.size(); ++i) {
    total.rays += stats[i].rays;
    total.invalidSamples += stats[i].invalidSamples;
    total.deviceMilliseconds = std::max(total.deviceMilliseconds, stats[i].deviceMilliseconds);
    total.perDeviceMilliseconds.push_back(stats[i].deviceMilliseconds);
    if (i == 0 || shares[i].empty()) continue;
    RowRange& rows = unmerged_[i];
    const uint32_t end = shares[i].firstRow + shares[i].rows;
    rows = rows.first == rows.end ? RowRange{shares[i].firstRow, end}
                                  : RowRange{std::min(rows.first, shares[i].firstRow), std::max(rows.end, end)};
  }
  balance_.record(shares, settings_.width, total.perDeviceMilliseconds);
  lastShares_ = shares;
  accumulated_ += samplesPerPixel;
  nextSample_ += samplesPerPixel;
  return total;
}

void MultiGpuBackend::mergeFilms() const {
  const auto start = std::chrono::steady_clock::now();
  bool merged = false;
  for (size_t i = 1; i < devices_.size(); ++i) {
    RowRange& rows = unmerged_[i];
    if (rows.first == rows.end) continue;
    devices_[0]->moveFilmRows(*devices_[i], rows.first, rows.end - rows.first);
    rows = {};
    merged = true;
  }
  if (merged)
    combineMilliseconds_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

FilmSums MultiGpuBackend::readFilm() const {
  return onMergedFilm([](const OptixBackend& first) { return first.readFilm(); });
}

// After the merge the other devices' films are clear, so the loaded sums are all there is.
void MultiGpuBackend::loadFilm(const FilmSums& film) {
  onMergedFilm([&](OptixBackend& first) { first.loadFilm(film); });
}

Image MultiGpuBackend::readImage() const {
  return onMergedFilm([](const OptixBackend& first) { return first.readImage(); });
}

Image MultiGpuBackend::readEmission() const {
  return onMergedFilm([](const OptixBackend& first) { return first.readEmission(); });
}

AovImages MultiGpuBackend::readAovs() const {
  return onMergedFilm([](const OptixBackend& first) { return first.readAovs(); });
}

const FilmFilters& MultiGpuBackend::filters() const { return *filters_; }

const FilmDisplay& MultiGpuBackend::display() const { return *display_; }

std::array<unsigned char, 16> MultiGpuBackend::deviceUuid() const { return devices_[0]->deviceUuid(); }

void MultiGpuBackend::writeImageToDevice(Vec3* destination) const {
  onMergedFilm([&](const OptixBackend& first) { first.writeImageToDevice(destination); });
}

RawTraceTiming MultiGpuBackend::timeRawTrace(uint32_t warmup, uint32_t frames) {
  CurrentDevice device(ordinals_[0]);
  devices_[0]->setNextSampleIndex(nextSample_);
  return devices_[0]->timeRawTrace(warmup, frames);
}

}  // namespace candela
