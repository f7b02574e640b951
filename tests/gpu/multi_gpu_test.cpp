// The OptiX backend on several devices of one process (optix/multi_gpu_backend.h) against one device: the same
// sample indices, split between the devices and combined, give the same film up to the order of the float
// additions. The devices are CANDELA_TEST_DEVICES (default 0,0: two contexts on the first GPU, which exercises
// the split, the combine and the rebalancing on a machine of one GPU; 0,1 on a machine of two).
#include <cuda_runtime.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <set>
#include <type_traits>

#include "app/device_list.h"
#include "backends/film_display.h"
#include "backends/optix/cuda_devices.h"
#include "backends/optix/multi_gpu_backend.h"
#include "gpu_render.h"
#include "support/scene_edits.h"

namespace candela {
namespace {

// The MPI test's tolerance (tests/distributed): float sums in another order.
constexpr double kRelative = 1e-5;

std::vector<int> testDevices() {
  const char* listed = std::getenv("CANDELA_TEST_DEVICES");
  return resolveDevices(parseDeviceRequest(listed ? listed : "0,0"), optix::gpuNames());
}

std::unique_ptr<MultiGpuBackend> makeGroup() { return std::make_unique<MultiGpuBackend>(testDevices()); }
std::unique_ptr<OptixBackend> makeOne() { return std::make_unique<OptixBackend>(testDevices()[0]); }

RenderSettings settings(uint32_t width, uint32_t height, uint32_t seed) {
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.seed = seed;
  return s;
}

void start(Backend& backend, const Scene& scene, const RenderSettings& s, bool aovs = false) {
  backend.setScene(scene);
  backend.setSettings(s);
  backend.setAovsEnabled(aovs);
  backend.setCamera(scene.camera.toCamera(float(s.width) / float(s.height)));
}

// The group and one device, created in that order and started on the same scene and settings.
struct GroupAndOne {
  std::unique_ptr<MultiGpuBackend> group;
  std::unique_ptr<OptixBackend> one;
};

GroupAndOne startGroupAndOne(const Scene& scene, const RenderSettings& s, bool aovs = false) {
  GroupAndOne backends{makeGroup(), makeOne()};
  start(*backends.group, scene, s, aovs);
  start(*backends.one, scene, s, aovs);
  return backends;
}

// Equal counts; sums within kRelative of the larger magnitude (or of the pixel's sample count, for sums such as
// the normals' that can cancel to near zero).
template <class T>
void expectSumsAgree(const char* what, const std::vector<T>& a, const std::vector<T>& b,
                     const std::vector<uint32_t>& samples, size_t& failures) {
  ASSERT_EQ(a.size(), b.size()) << what;
  const size_t components = sizeof(T) / sizeof(float);
  for (size_t i = 0; i < a.size(); ++i) {
    const float* x = reinterpret_cast<const float*>(&a[i]);
    const float* y = reinterpret_cast<const float*>(&b[i]);
    for (size_t c = 0; c < components; ++c) {
      const double scale = std::max({std::fabs(double(x[c])), std::fabs(double(y[c])), 1e-3 * samples[i]});
      if (std::fabs(double(x[c]) - double(y[c])) > kRelative * scale && failures++ < 5)
        ADD_FAILURE() << what << " differ at pixel " << i << ": " << x[c] << " vs " << y[c];
    }
  }
}

// Every channel of the film (kernel/film_channels.h): equal counts, sums that agree.
void expectFilmsAgree(const FilmSums& group, const FilmSums& one) {
  ASSERT_TRUE(group.sameShape(one));
  ASSERT_EQ(group.samples, one.samples) << "every pixel must hold the same number of samples";
  size_t failures = 0;
  forEachFilmChannel(group, one, [&](auto channel, const auto& a, const auto& b) {
    if constexpr (std::is_same_v<typename decltype(channel)::Type, uint32_t>)
      EXPECT_EQ(a, b) << channel.description;
    else
      expectSumsAgree(channel.description, a, b, one.samples, failures);
  });
  EXPECT_EQ(failures, 0u);
}

// A check that cannot tell films apart proves nothing: `other` must differ from `film` clearly somewhere.
void expectFilmsDiffer(const FilmSums& film, const FilmSums& other) {
  double largest = 0.0;
  for (size_t i = 0; i < film.radiance.size(); ++i)
    for (int c = 0; c < 3; ++c)
      largest = std::max(largest, std::fabs(double(film.radiance[i][c] - other.radiance[i][c])));
  EXPECT_GT(largest, 0.01);
}

// `calls` render() calls of `samplesPerCall` on the group and on one device.
void expectProgressiveRenderEqualsOneDevice(bool aovs) {
  const Scene scene = makeCornellBox();
  const RenderSettings s = settings(96, 64, 11);
  auto [group, one] = startGroupAndOne(scene, s, aovs);
  FrameStats groupStats, oneStats;
  for (int call = 0; call < 3; ++call) {
    const uint32_t samples = 8 + uint32_t(call);  // uneven counts: the split moves the later devices' first index
    const FrameStats g = group->render(samples), o = one->render(samples);
    groupStats.rays += g.rays;
    oneStats.rays += o.rays;
    ASSERT_EQ(g.perDeviceMilliseconds.size(), group->deviceCount());
    for (const DeviceShare& share : group->lastShares()) {
      EXPECT_EQ(share.rows, s.height) << "a call of several samples per device splits the sample indices";
      EXPECT_GT(share.samples, 0u);
    }
  }
  EXPECT_EQ(group->accumulatedSamples(), one->accumulatedSamples());
  EXPECT_EQ(groupStats.rays, oneStats.rays) << "the same paths trace the same rays";
  expectFilmsAgree(group->readFilm(), one->readFilm());
}

TEST(MultiGpu, ProgressiveRenderSplitsTheSampleIndicesAndEqualsOneDevice) {
  expectProgressiveRenderEqualsOneDevice(false);
}

TEST(MultiGpu, ProgressiveRenderWithAovsEqualsOneDeviceInEverySum) { expectProgressiveRenderEqualsOneDevice(true); }

// Frames of one sample as the viewer renders them: bands of rows, moved every frame by the devices' times, the
// image read after every frame. A tall image, so that any difference of the devices' times moves a band.
TEST(MultiGpu, InteractiveFramesSplitRowsFollowTheTimesAndEqualOneDevice) {
  const Scene scene = makeCornellBox();
  const RenderSettings s = settings(32, 1080, 12);
  auto [group, one] = startGroupAndOne(scene, s);
  std::set<std::vector<uint32_t>> splits;
  for (int frame = 0; frame < 24; ++frame) {
    group->render(1);
    one->render(1);
    std::vector<uint32_t> rows;
    uint32_t next = 0;
    for (const DeviceShare& share : group->lastShares()) {
      EXPECT_EQ(share.firstRow, next) << "bands are contiguous, top to bottom";
      EXPECT_GT(share.rows, 0u) << "every device keeps a band, so that its speed is measured";
      EXPECT_EQ(share.samples, 1u);
      next += share.rows;
      rows.push_back(share.rows);
    }
    EXPECT_EQ(next, s.height);
    splits.insert(rows);
    // The viewer reads every frame: each read moves the other devices' rows into the first one's film.
    const Image image = group->readImage();
    ASSERT_EQ(image.pixels.size(), size_t(s.width) * s.height);
  }
  EXPECT_GT(splits.size(), 1u) << "the bands never moved: the rebalancing was not exercised";
  EXPECT_GE(group->lastCombineMilliseconds(), 0.0);
  expectFilmsAgree(group->readFilm(), one->readFilm());
}

// The viewer's interop path: the image written to device memory on the display device is the combined one.
TEST(MultiGpu, DeviceImageIsTheCombinedImage) {
  const Scene scene = makeCornellBox();
  const RenderSettings s = settings(64, 48, 13);
  auto [group, one] = startGroupAndOne(scene, s);
  for (int frame = 0; frame < 6; ++frame) {
    group->render(1);
    one->render(1);
  }
  const size_t pixels = size_t(s.width) * s.height;
  optix::CurrentDevice display(testDevices()[0]);
  Vec3* device = nullptr;
  ASSERT_EQ(cudaMalloc(&device, pixels * sizeof(Vec3)), cudaSuccess);
  group->deviceImage()->writeImageToDevice(device);
  std::vector<Vec3> image(pixels);
  ASSERT_EQ(cudaMemcpy(image.data(), device, pixels * sizeof(Vec3), cudaMemcpyDeviceToHost), cudaSuccess);
  cudaFree(device);
  EXPECT_EQ(group->deviceImage()->deviceUuid(), one->deviceUuid());
  const Image expected = one->readImage();
  for (size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(image[i][c], expected.pixels[i][c], kRelative * std::max(1.0f, std::fabs(expected.pixels[i][c])))
          << "pixel " << i;
}

// The display frames (Backend::display) are the first device's, of the combined film: the bytes the CPU display
// gives of the combined image, with the temporal filter too (whose frames combine the films themselves).
TEST(MultiGpu, DisplayFramesShowTheCombinedFilm) {
  const Scene scene = makeCornellBox();
  const RenderSettings s = settings(64, 48, 15);
  auto group = makeGroup();
  start(*group, scene, s, /*aovs=*/true);
  const Camera camera = scene.camera.toCamera(float(s.width) / float(s.height));
  const std::unique_ptr<TemporalDenoiser> shown = group->filters().temporal(TemporalParams{});
  const std::unique_ptr<TemporalDenoiser> read = group->filters().temporal(TemporalParams{});
  auto cpuBytes = [](const Image& image) {
    std::vector<uint8_t> bytes(image.pixels.size() * 3);
    writeDisplayPixels({image.pixels.data(), nullptr, image.width, image.height}, DisplaySettings{}, 1, bytes.data());
    return bytes;
  };
  for (int frame = 0; frame < 4; ++frame) {
    group->render(1);  // rows on every device: the display must combine them first
    DisplayRequest request;
    const DisplayFrame plain = group->display().read(request);
    EXPECT_EQ(std::vector<uint8_t>(plain.rgb, plain.rgb + s.width * s.height * 3), cpuBytes(group->readImage()));
    group->render(1);
    request.source = TemporalFiltered{shown.get(), camera, frame > 0};
    const DisplayFrame temporal = group->display().read(request);
    EXPECT_EQ(std::vector<uint8_t>(temporal.rgb, temporal.rgb + s.width * s.height * 3),
              cpuBytes(read->denoise(camera, frame > 0)));
  }
}

// A resumed render: the loaded film replaces every device's samples, and later samples add to it.
TEST(MultiGpu, LoadedFilmReplacesEveryDevicesSamples) {
  const Scene scene = makeCornellBox();
  const RenderSettings s = settings(64, 48, 14);
  auto one = makeOne();
  start(*one, scene, s);
  one->render(4);
  const FilmSums checkpoint = one->readFilm();
  one->render(4);

  auto group = makeGroup();
  start(*group, scene, s);
  group->render(1);  // samples the loaded film must replace, on the other devices too
  group->render(3);
  group->loadFilm(checkpoint);
  group->setNextSampleIndex(4);
  group->render(4);
  expectFilmsAgree(group->readFilm(), one->readFilm());
}

// Renders `original` on the group, edits it there, renders again: the film must equal one device's render of the
// edited scene (so the edit reached every device, whose samples are all in it) and differ from the unedited one.
void expectEditReachesEveryDevice(const Scene& original, const Scene& edited, const std::function<void(Backend&)>& edit,
                                  const std::function<void(Backend&)>& startEdited) {
  const RenderSettings s = settings(48, 48, 17);
  auto group = makeGroup();
  start(*group, original, s);
  group->render(4);
  edit(*group);
  EXPECT_EQ(group->accumulatedSamples(), 0u);
  group->render(4);
  group->render(1);
  const FilmSums afterEdit = group->readFilm();

  auto one = makeOne();
  start(*one, edited, s);
  startEdited(*one);
  one->render(5);
  expectFilmsAgree(afterEdit, one->readFilm());

  auto unedited = makeOne();
  start(*unedited, original, s);
  unedited->render(5);
  expectFilmsDiffer(afterEdit, unedited->readFilm());
}

const auto kNothing = [](Backend&) {};

TEST(MultiGpu, MaterialEditReachesEveryDevice) {
  const Scene original = makeMaterialGallery();
  const Scene edited = test::withMaterialEdit(original);
  expectEditReachesEveryDevice(
      original, edited, [&](Backend& b) { EXPECT_TRUE(b.setMaterials(edited.materials)); }, kNothing);
}

TEST(MultiGpu, EnvironmentEditReachesEveryDevice) {
  const Scene original = makeMaterialGallery();
  Scene edited = original;
  edited.environment.intensity *= 3.0f;
  edited.environment.rotationDegrees = 30.0f;
  expectEditReachesEveryDevice(
      original, edited, [&](Backend& b) { b.setEnvironment(edited.environment); }, kNothing);
}

TEST(MultiGpu, CameraEditReachesEveryDevice) {
  const Scene scene = makeCornellBox();
  CameraDescription moved = scene.camera;
  moved.eye = moved.eye + Vec3{0.3f, 0.2f, 0.0f};
  moved.verticalFovDegrees *= 0.8f;
  const Camera camera = moved.toCamera(1.0f);
  auto setCamera = [&](Backend& b) { b.setCamera(camera); };
  expectEditReachesEveryDevice(scene, scene, setCamera, setCamera);
}

TEST(MultiGpu, GeometryEditReachesEveryDevice) {
  const Scene original = makeCornellBox();
  Scene edited = original;
  for (Instance& instance : edited.instances) instance.objectToWorld.m[3] += 0.05f;
  expectEditReachesEveryDevice(
      original, edited, [&](Backend& b) { b.setInstanceTransforms(edited); }, kNothing);
}

TEST(MultiGpu, NamesEveryDeviceAndTheCombinePath) {
  auto group = makeGroup();
  EXPECT_EQ(group->name(), "optix");
  const std::string name = group->deviceName();
  EXPECT_NE(name.find(std::to_string(testDevices().size()) + " x "), std::string::npos) << name;
  EXPECT_NE(name.find("combined "), std::string::npos) << name;
}

}  // namespace
}  // namespace candela
