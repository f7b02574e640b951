// candela serve's H.264 stream at rest, over the network as a browser takes it: the frames come
// StreamQuality::kRestFrameRate a second at most, the samples rendered between them are not lost, and input that
// comes at rest gets its frame at once, not at the next turn of the rest rate.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "app/serve/stream_quality.h"
#include "network_clients.h"
#include "serve_process.h"

namespace candela::test {
namespace {

using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

double secondsBetween(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

struct VideoFrame {
  Clock::time_point arrived;
  uint64_t samples = 0;
  double exposure = 0.0;
};

// A browser that chose the video stream and acknowledges each frame as it comes, as the page does once drawn.
class VideoBrowser {
 public:
  explicit VideoBrowser(const ServeProcess& server) : ws_(server.port(), server.token()) {}

  // Whether the server offers the video stream (a build without x264 does not); reads up to its greeting.
  bool chooseVideo() {
    for (;;) {
      const WebSocketClient::Message m = ws_.read();
      if (m.binary) {
        acknowledge(Json::parse(m.text));
        continue;
      }
      const Json message = Json::parse(m.text);
      if (message.value("type", "") != "hello") continue;
      const Json streams = message.value("streams", Json::array());
      if (std::find(streams.begin(), streams.end(), "h264") == streams.end()) return false;
      ws_.send(R"({"type":"stream","codec":"h264"})");
      return true;
    }
  }

  // The next H.264 frame (JPEG frames sent before the choice took effect are acknowledged and passed over).
  VideoFrame next() {
    for (;;) {
      const WebSocketClient::Message m = ws_.read();
      if (!m.binary) continue;
      const Json header = Json::parse(m.text);
      if (header.value("kind", "") != "frame") continue;
      const Clock::time_point arrived = Clock::now();
      acknowledge(header);
      if (header.value("format", "") == "h264")
        return {arrived, header.at("samples").get<uint64_t>(), header.at("controls").at("exposure").get<double>()};
    }
  }

  void send(const std::string& json) { ws_.send(json); }

 private:
  void acknowledge(const Json& header) {
    if (header.value("kind", "") == "frame")
      ws_.send(R"({"type":"frame_ack","frame":)" + std::to_string(header.at("frame").get<uint64_t>()) + "}");
  }

  WebSocketClient ws_;
};

TEST(ServeVideoAtRest, FewerFramesEachWithTheSamplesRenderedSinceTheLast) {
  // A frame this small renders and encodes in well under the rest rate's interval: without the hold at rest the
  // frames would come as fast as the browser acknowledges them, one sample apart.
  ServeProcess server(
      CANDELA_EXECUTABLE,
      {"cornell-box", "--backend", "cpu", "--port", "0", "--width", "64", "--height", "64", "--max-depth", "2"}, 120.0);
  VideoBrowser browser(server);
  if (!browser.chooseVideo()) GTEST_SKIP() << "this build's serve offers no H.264 stream";
  browser.next();  // the key frame

  constexpr double kWatchSeconds = 1.5;
  const VideoFrame first = browser.next();
  VideoFrame last = first;
  int frames = 0;
  while (secondsBetween(first.arrived, last.arrived) < kWatchSeconds) {
    last = browser.next();
    ++frames;
  }
  const double perSecond = frames / secondsBetween(first.arrived, last.arrived);
  EXPECT_LE(perSecond, 1.2 * StreamQuality::kRestFrameRate) << frames << " frames";
  EXPECT_GT(last.samples - first.samples, uint64_t(frames))
      << "the frames held back at rest add their samples to the next one sent";

  // A change of the exposure at rest, sent as soon as a frame came: its frame goes at once. At the rest rate it
  // would come an interval after the last one (47 ms measured with the rule taken out, against 50); the quickest of
  // ten tries must come well before that, with room for a loaded machine (33 ms seen under ASan beside two busy
  // processes, against a few without load).
  double quickest = 1e9;
  for (int trial = 0; trial < 10; ++trial) {
    const VideoFrame before = browser.next();
    const double exposure = 0.25 * (trial + 1);
    browser.send(R"({"type":"settings","exposure":)" + std::to_string(exposure) + "}");
    VideoFrame after = browser.next();
    while (after.exposure != exposure) after = browser.next();
    quickest = std::min(quickest, secondsBetween(before.arrived, after.arrived));
  }
  EXPECT_LT(quickest, 0.75 / StreamQuality::kRestFrameRate) << "input at rest waited for the rest rate's interval";
  EXPECT_EQ(server.stop(30.0), 0) << server.stderrText();
}

}  // namespace
}  // namespace candela::test
