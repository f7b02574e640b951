// A serve frame's post-processing and encoding, timed on the Cornell box at 1280x720 and 1920x1080: the display
// frame (Backend::display: on the CPU backend tone mapping in parallel from the film's sums, on the OptiX backend a
// CUDA kernel and the read-back of the bytes), of the image as it is or through the a-trous filter, and the
// striped JPEG with its message, each the median of --repeats runs after 3 untimed ones, in wall-clock time (_ms) and
// in the CPU time of all the process's threads (_cpu_ms), which says more on a machine busy with other work. Where the
// build has candela serve, also its frames as they were made before these (the screenshot's displayImage on
// readImage(), one JPEG on one thread): the before_ columns.
// One JSON line per size.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "app/backend_factory.h"
#include "backends/film_display.h"
#include "io/images/striped_jpeg.h"
#include "scene/builtin_scenes.h"
#if CANDELA_HAS_SERVE
#include "app/serve/frame_encoding.h"
#include "app/serve/stream_quality.h"
#include "io/video/h264_encoder.h"
#endif

using namespace candela;

namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double processCpuMilliseconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

struct Timing {
  double wallMs = 0.0, cpuMs = 0.0;
};

Timing medianTiming(int repeats, const std::function<void()>& run) {
  for (int i = 0; i < 3; ++i) run();
  std::vector<double> wall, cpu;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = processCpuMilliseconds();
    run();
    cpu.push_back(processCpuMilliseconds() - cpuStart);
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return {median(wall), median(cpu)};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Times a serve frame's post-processing and encoding");
  std::string backendName = "cpu";
  bool atrous = false;
  uint32_t spp = 4;
  int repeats = 30, quality = 80;
  unsigned threads = 0;
  app.add_option("--backend", backendName, "cpu or optix");
  app.add_flag("--atrous", atrous, "the film through the backend's a-trous filter rather than as it is");
  app.add_option("--spp", spp, "samples per pixel rendered before timing");
  app.add_option("--repeats", repeats, "timed runs per measurement")->check(CLI::PositiveNumber);
  app.add_option("--quality", quality, "JPEG quality")->check(CLI::Range(1, 100));
  app.add_option("--jpeg-threads", threads, "threads of the striped JPEG encoder (0: the hardware's)");
  CLI11_PARSE(app, argc, argv);

  try {
    const Scene scene = makeCornellBox();
    std::string why;
    const std::unique_ptr<Backend> backend = createBackend(backendName, why);
    StripedJpegEncoder encoder(threads);
    for (const auto& [width, height] : {std::pair{1280u, 720u}, std::pair{1920u, 1080u}}) {
      RenderSettings settings;
      settings.width = width;
      settings.height = height;
      backend->setScene(scene);
      backend->setSettings(settings);
      backend->setAovsEnabled(atrous);
      backend->setCamera(scene.camera.toCamera(float(width) / float(height)));
      backend->render(spp);

      DisplayRequest request;
      if (atrous) request.source = AtrousFiltered{AtrousParams{}};
      DisplayFrame frame;
      const Timing post = medianTiming(repeats, [&] { frame = backend->display().read(request); });
      size_t messageBytes = 0, stripes = 0;
      const Timing encode = medianTiming(repeats, [&] {
        const StripedJpeg jpeg = encoder.encode(frame.rgb, frame.width, frame.height, quality);
        stripes = jpeg.stripes.size();
        messageBytes = packStripedJpeg(jpeg).size();
      });
      std::printf(
          "{\"backend\": \"%s\", \"device\": \"%s\", \"source\": \"%s\", \"width\": %u, \"height\": %u, "
          "\"spp\": %u, \"quality\": %d, \"hardware_threads\": %u, \"jpeg_threads\": %u, \"stripes\": %zu, "
          "\"message_bytes\": %zu, \"post_ms\": %.3f, \"post_cpu_ms\": %.3f, \"encode_ms\": %.3f, "
          "\"encode_cpu_ms\": %.3f",
          backend->name().c_str(), backend->deviceName().c_str(), atrous ? "atrous" : "accumulated", width, height, spp,
          quality, std::thread::hardware_concurrency(), encoder.threads(), stripes, messageBytes, post.wallMs,
          post.cpuMs, encode.wallMs, encode.cpuMs);
#if CANDELA_HAS_SERVE
      DisplayImage image;
      const Timing servePost = medianTiming(repeats, [&] {
        image =
            displayImage(atrous ? backend->filters().atrous(AtrousParams{}) : backend->readImage(), DisplaySettings());
      });
      size_t jpegBytes = 0;
      StripedJpegEncoder oneThread(1);  // one stripe: a single JPEG
      const Timing serveEncode = medianTiming(repeats, [&] {
        jpegBytes = oneThread.encode(image.rgb.data(), image.width, image.height, quality).stripes[0].bytes.size();
      });
      std::printf(
          ", \"before_post_ms\": %.3f, \"before_post_cpu_ms\": %.3f, \"before_encode_ms\": %.3f, "
          "\"before_encode_cpu_ms\": %.3f, \"before_jpeg_bytes\": %zu",
          servePost.wallMs, servePost.cpuMs, serveEncode.wallMs, serveEncode.cpuMs, jpegBytes);
#endif
#if CANDELA_HAS_SERVE
      // The H.264 stream at the stream's settings at rest (the film refining, one sample a frame) and moving (a
      // new film of one sample each frame, the camera turning): the access units' median encode time and their
      // mean size as a rate at the stream's frame rate (60 frames a second moving, fewer at rest).
      for (bool moving : {false, true}) {
        H264Encoder video;
        const H264Settings videoSettings = StreamQuality().videoSettings(moving, 60.0);
        std::vector<double> milliseconds;
        double bytes = 0.0;
        const int frames = repeats + 3;
        for (int i = 0; i < frames; ++i) {
          if (moving) {
            Camera camera = scene.camera.toCamera(float(width) / float(height));
            camera.position = camera.position + Vec3(0.002f * float(i), 0.0f, 0.0f);
            backend->setCamera(camera);
          }
          backend->render(1);
          const DisplayFrame pixels = backend->display().read(request);
          const H264Frame encoded = video.encode(pixels.rgb, pixels.width, pixels.height, videoSettings, false);
          if (i < 3) continue;  // the key frame and the encoder's warm-up
          milliseconds.push_back(encoded.milliseconds);
          bytes += double(encoded.bytes.size());
        }
        const char* name = moving ? "video_moving" : "video_rest";
        std::printf(
            ", \"%s_encode_ms\": %.3f, \"%s_frames_per_s\": %u, \"%s_mbit_per_s\": %.2f, \"%s_rate_factor\": %.0f",
            name, median(milliseconds), name, videoSettings.framesPerSecond, name,
            bytes / double(repeats) * 8.0 * double(videoSettings.framesPerSecond) / 1e6, name,
            videoSettings.rateFactor);
      }
      backend->setCamera(scene.camera.toCamera(float(width) / float(height)));
#endif
      std::printf("}\n");
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "display_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
