// candela serve over the network from several clients at once: browsers' WebSockets that steer, acknowledge
// frames, ask for screenshots and leave (politely or not), plain HTTP requests and malformed ones, while the
// render loop renders and publishes; then SIGTERM ends the server, which must exit with status 0. Under
// ThreadSanitizer (scripts/test-thread-sanitized.sh) a race in the server makes it exit with TSan's status
// instead, and its report is printed.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "io/images/striped_jpeg.h"
#include "network_clients.h"
#include "serve_process.h"

namespace candela::test {
namespace {

using Json = nlohmann::json;

constexpr int kBrowsers = 4;
constexpr int kVisitsPerBrowser = 3;
constexpr int kFramesPerVisit = 3;
constexpr int kRequesters = 3;
constexpr int kRequestsPerRequester = 6;

// Kills the server when the clients are not done in time, so that a client waiting for it fails instead of
// hanging the test.
class Watchdog {
 public:
  Watchdog(std::chrono::seconds limit, ServeProcess& server)
      : thread_([this, limit, &server] {
          std::unique_lock lock(mutex_);
          if (!cancelled_.wait_for(lock, limit, [&] { return done_; })) {
            fired_ = true;
            server.kill();
          }
        }) {}
  ~Watchdog() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    cancelled_.notify_one();
    thread_.join();
  }
  bool fired() {
    std::lock_guard lock(mutex_);
    return fired_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable cancelled_;
  bool done_ = false, fired_ = false;
  std::thread thread_;  // last: it starts once the members above are made
};

// What a browser says after its n-th frame (1, 2, 3, ...): the page's messages, each kind at least once.
void steer(WebSocketClient& ws, int frame) {
  switch (frame) {
    case 1:
      ws.send(R"({"type":"resize","width":48,"height":32})");
      ws.send(R"({"type":"action","name":"take_control"})");
      break;
    case 2:
      ws.send(R"({"type":"pointer","action":"down","button":"left","x":10,"y":10})");
      ws.send(R"({"type":"pointer","action":"move","x":14,"y":12})");
      ws.send(R"({"type":"pointer","action":"up","button":"left","x":14,"y":12})");
      ws.send(R"({"type":"wheel","steps":1.5})");
      ws.send(R"({"type":"keys","forward":true})");
      ws.send(R"({"type":"keys"})");
      break;
    default:
      ws.send(R"({"type":"settings","exposure":0.5,"max_depth":3})");
      ws.send(R"({"type":"action","name":"screenshot"})");
      ws.send(R"({"type":"action","name":"save_view"})");
      ws.send("not json");
      ws.send(R"({"type":"\u001b[31m)" + std::string(3000, 'A') + R"("})");
      break;
  }
}

// A frame's payload: JPEG stripes (io/images/striped_jpeg.h) of the size its header gives.
bool isStripedJpeg(const std::string& payload, const nlohmann::json& header) {
  try {
    const StripedJpeg frame = unpackStripedJpeg(payload);
    for (const JpegStripe& stripe : frame.stripes)
      if (stripe.bytes.size() < 2 || uint8_t(stripe.bytes[0]) != 0xff || uint8_t(stripe.bytes[1]) != 0xd8) return false;
    return frame.width == header.at("width").get<uint32_t>() && frame.height == header.at("height").get<uint32_t>() &&
           frame.stripes.size() == header.at("stripes").get<size_t>();
  } catch (const std::exception&) {
    return false;
  }
}

// One browser's visits, one after the other; returns what went wrong.
std::vector<std::string> browse(uint16_t port, const std::string& token, int browser) {
  std::vector<std::string> problems;
  for (int visit = 0; visit < kVisitsPerBrowser; ++visit) {
    const std::string who = "browser " + std::to_string(browser) + ", visit " + std::to_string(visit) + ": ";
    try {
      WebSocketClient ws(port, token);
      bool role = false, hello = false;
      uint64_t last = 0;
      for (int frames = 0; frames < kFramesPerVisit;) {
        const WebSocketClient::Message m = ws.read();
        const Json header = Json::parse(m.text);
        if (!m.binary) {
          const std::string type = header.value("type", "");
          role = role || type == "role";
          hello = hello || type == "hello";
          continue;
        }
        if (header.value("kind", "") != "frame") continue;  // a screenshot
        const uint64_t number = header.at("frame").get<uint64_t>();
        if (number <= last)
          problems.push_back(who + "frame " + std::to_string(number) + " after " + std::to_string(last));
        if (!isStripedJpeg(m.payload, header)) problems.push_back(who + "a frame that is no striped JPEG of its size");
        last = number;
        steer(ws, ++frames);
        ws.send(R"({"type":"frame_ack","frame":)" + std::to_string(number) + "}");
      }
      // The role comes on attaching, the greeting before the render loop's next frame.
      if (!role) problems.push_back(who + "no role message");
      if (!hello) problems.push_back(who + "no hello message");
      if ((browser + visit) % 2 == 0)
        ws.close();
      else
        ws.drop();
    } catch (const std::exception& e) {
      problems.push_back(who + e.what());
    }
  }
  return problems;
}

// The page's files, refusals and a request that is no HTTP, over and over; returns what went wrong.
std::vector<std::string> request(uint16_t port, const std::string& token) {
  std::vector<std::string> problems;
  const auto expect = [&](const std::string& what, unsigned got, unsigned wanted) {
    if (got != wanted)
      problems.push_back(what + ": status " + std::to_string(got) + " instead of " + std::to_string(wanted));
  };
  for (int i = 0; i < kRequestsPerRequester; ++i) {
    try {
      const std::string withToken = "?token=" + token;
      const HttpAnswer page = httpGet(port, "/" + withToken);
      expect("GET /", page.status, 200);
      if (page.contentType.rfind("text/html", 0) != 0) problems.push_back("GET /: " + page.contentType);
      expect("GET /app.js", httpGet(port, "/app.js" + withToken).status, 200);
      expect("GET /no-such-file", httpGet(port, "/no-such-file" + withToken).status, 404);
      expect("GET / without the token", httpGet(port, "/").status, 403);
      expect("no HTTP", rawRequestStatus(port, "NOT HTTP AT ALL\r\n\r\n"), 400);
    } catch (const std::exception& e) {
      problems.push_back(std::string("request: ") + e.what());
    }
  }
  return problems;
}

TEST(ServeNetwork, ManyClientsAtOnceThenSigtermEndsTheServerCleanly) {
  ServeProcess server(
      CANDELA_EXECUTABLE,
      {"cornell-box", "--backend", "cpu", "--port", "0", "--width", "64", "--height", "64", "--max-depth", "4"}, 120.0);
  std::vector<std::vector<std::string>> problems(kBrowsers + kRequesters);
  bool timedOut = false;
  {
    Watchdog watchdog(std::chrono::seconds(120), server);
    std::vector<std::thread> clients;
    for (int b = 0; b < kBrowsers; ++b)
      clients.emplace_back([&, b] { problems[size_t(b)] = browse(server.port(), server.token(), b); });
    for (int r = 0; r < kRequesters; ++r)
      clients.emplace_back([&, r] { problems[size_t(kBrowsers + r)] = request(server.port(), server.token()); });
    for (std::thread& c : clients) c.join();
    timedOut = watchdog.fired();
  }
  // The server's end first: a sanitizer's report there explains what the clients saw.
  EXPECT_FALSE(timedOut) << "the clients were not done within 120 s; the server was killed";
  EXPECT_EQ(server.stop(60.0), 0) << server.stderrText();
  EXPECT_NE(server.stderrText().find("candela serve: stopped"), std::string::npos) << server.stderrText();
  // What clients sent reaches the terminal only as printable text, on short lines.
  const std::string log = server.stderrText();
  EXPECT_NE(log.find("unknown type"), std::string::npos) << log;
  EXPECT_EQ(log.find('\x1b'), std::string::npos) << "an escape sequence from a client reached the terminal";
  for (size_t start = 0, end; start < log.size(); start = end + 1) {
    end = std::min(log.find('\n', start), log.size());
    EXPECT_LT(end - start, 300u) << log.substr(start, 300);
  }
  for (const std::vector<std::string>& p : problems)
    for (const std::string& problem : p) ADD_FAILURE() << problem;
}

}  // namespace
}  // namespace candela::test
