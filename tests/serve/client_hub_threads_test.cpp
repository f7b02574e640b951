// ClientHub from several threads at once, as candela serve drives it: connections attach, acknowledge frames,
// send input and leave while the render loop takes the messages and publishes frames. The ThreadSanitizer stage
// runs it (scripts/test-thread-sanitized.sh); its assertions hold in every interleaving.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/serve/client_hub.h"

namespace candela {
namespace {

// A connection as the WebSocket session is one: the hub calls it from the render loop's thread and the attaching
// thread, and the browser's side (a client thread here) waits for its frames.
class QueuedConnection : public ClientConnection {
 public:
  void sendMessage(std::shared_ptr<const std::string> message, bool) override {
    std::lock_guard lock(mutex_);
    messages_.push_back(*message);
  }
  void sendFrame(std::shared_ptr<const std::string> frame) override {
    std::lock_guard lock(mutex_);
    frames_.push_back(*frame);
    arrived_.notify_all();
  }
  // The frame after the `taken` first ones, or nullopt when none comes within `timeout`.
  std::optional<std::string> frame(size_t taken, std::chrono::seconds timeout) {
    std::unique_lock lock(mutex_);
    if (!arrived_.wait_for(lock, timeout, [&] { return frames_.size() > taken; })) return std::nullopt;
    return frames_[taken];
  }
  std::vector<std::string> messages() {
    std::lock_guard lock(mutex_);
    return messages_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::vector<std::string> messages_, frames_;
};

constexpr int kClientThreads = 6;
constexpr int kVisitsPerThread = 10;
constexpr size_t kFramesPerVisit = 3;
constexpr int kInputsPerFrame = 16;  // a burst, as a dragged mouse sends them

// One thread's browsers, one after the other: each attaches, takes and acknowledges kFramesPerVisit frames, after
// each a burst of input, a request for control and a message the hub drops, then leaves. Returns what went wrong.
std::vector<std::string> visit(ClientHub& hub) {
  std::vector<std::string> problems;
  for (int v = 0; v < kVisitsPerThread; ++v) {
    auto connection = std::make_shared<QueuedConnection>();
    const uint64_t id = hub.attach(connection);
    if (id == 0) {
      problems.push_back("refused although fewer than kMaxClients were connected");
      continue;
    }
    uint64_t last = 0;
    for (size_t f = 0; f < kFramesPerVisit; ++f) {
      const std::optional<std::string> frame = connection->frame(f, std::chrono::seconds(20));
      if (!frame) {
        problems.push_back("no frame " + std::to_string(f + 1) + " within 20 s");
        break;
      }
      const uint64_t number = std::stoull(*frame);
      if (number <= last) problems.push_back("frame " + *frame + " after frame " + std::to_string(last));
      last = number;
      for (int i = 0; i < kInputsPerFrame; ++i)
        hub.receive(id, PointerMessage{PointerMessage::Action::Move, MouseButton::Left, double(i), double(f)});
      hub.receive(id, WheelMessage{1.0});
      hub.receive(id, ActionMessage{ActionMessage::Kind::TakeControl});
      hub.dropped(id, "a binary message");
      hub.receive(id, FrameAckMessage{number});
    }
    const std::vector<std::string> messages = connection->messages();
    if (messages.empty() || messages.front().find("\"type\":\"role\"") == std::string::npos)
      problems.push_back("the first message was not the client's role");
    hub.detach(id);
  }
  return problems;
}

TEST(ClientHubThreads, BrowsersComeAndGoWhileTheRenderLoopPublishes) {
  ClientHub hub;
  std::atomic<bool> browsersDone{false};
  size_t messagesTaken = 0;
  // The render loop, as ServeLoop::run drives the hub: greet, take the messages, hand over control, publish.
  std::thread renderLoop([&] {
    uint64_t frameNumber = 0;
    while (!browsersDone) {
      hub.waitForWork(std::chrono::milliseconds(5));
      hub.controlChanges();
      for (uint64_t client : hub.takeJoined()) hub.send(client, std::make_shared<const std::string>("hello"), false);
      for (const IncomingMessage& m : hub.takeMessages()) {
        ++messagesTaken;
        const auto* action = std::get_if<ActionMessage>(&m.message);
        if (action && action->kind == ActionMessage::Kind::TakeControl) hub.giveControl(m.client);
      }
      hub.takeDeliveries();
      if (!hub.anyReady()) continue;
      ++frameNumber;
      hub.publishFrame(frameNumber, std::make_shared<const std::string>(std::to_string(frameNumber)),
                       frameNumber % 2 == 0);
      if (frameNumber % 16 == 0) hub.broadcast("{\"type\":\"message\",\"text\":\"still here\"}");
      hub.clientCount();
      hub.controller();
    }
  });
  std::vector<std::vector<std::string>> problems(kClientThreads);
  std::vector<std::thread> browsers;
  for (int t = 0; t < kClientThreads; ++t) browsers.emplace_back([&, t] { problems[size_t(t)] = visit(hub); });
  for (std::thread& b : browsers) b.join();
  browsersDone = true;
  renderLoop.join();

  for (const std::vector<std::string>& p : problems)
    for (const std::string& problem : p) ADD_FAILURE() << problem;
  EXPECT_EQ(hub.clientCount(), 0u);
  EXPECT_EQ(hub.controller(), 0u);
  EXPECT_GT(messagesTaken, 0u);
}

}  // namespace
}  // namespace candela
