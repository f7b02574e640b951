#include <gtest/gtest.h>

#include "app/serve/client_hub.h"

namespace candela {
namespace {

struct RecordingConnection : ClientConnection {
  std::vector<std::string> messages;
  std::vector<std::string> frames;
  void sendMessage(std::shared_ptr<const std::string> m, bool) override { messages.push_back(*m); }
  void sendFrame(std::shared_ptr<const std::string> f) override { frames.push_back(*f); }
};

auto frame(const char* text) { return std::make_shared<const std::string>(text); }

TEST(ClientHub, TheFirstClientHoldsControlAndItPassesOnWhenItLeaves) {
  ClientHub hub;
  auto a = std::make_shared<RecordingConnection>(), b = std::make_shared<RecordingConnection>();
  const uint64_t ida = hub.attach(a), idb = hub.attach(b);
  EXPECT_EQ(hub.controller(), ida);
  EXPECT_NE(b->messages.back().find("\"control\":false"), std::string::npos);
  hub.detach(ida);
  EXPECT_EQ(hub.controller(), idb);
  EXPECT_NE(b->messages.back().find("\"control\":true"), std::string::npos);
}

TEST(ClientHub, WatchersInputIsDroppedButTheyMayTakeControl) {
  ClientHub hub;
  const uint64_t ida = hub.attach(std::make_shared<RecordingConnection>());
  const uint64_t idb = hub.attach(std::make_shared<RecordingConnection>());
  hub.receive(idb, WheelMessage{1.0});
  EXPECT_TRUE(hub.takeMessages().empty());
  hub.receive(ida, WheelMessage{1.0});
  EXPECT_EQ(hub.takeMessages().size(), 1u);
  hub.receive(idb, ActionMessage{ActionMessage::Kind::TakeControl});
  auto taken = hub.takeMessages();
  ASSERT_EQ(taken.size(), 1u);
  hub.giveControl(taken[0].client);
  EXPECT_EQ(hub.controller(), idb);
}

TEST(ClientHub, AClientGetsNoNewFrameUntilItAcknowledgesTheLast) {
  ClientHub hub;
  auto a = std::make_shared<RecordingConnection>();
  const uint64_t id = hub.attach(a);
  EXPECT_TRUE(hub.anyReady());
  hub.publishFrame(1, frame("one"), false);
  EXPECT_FALSE(hub.anyReady());
  hub.publishFrame(2, frame("two"), false);
  EXPECT_EQ(a->frames, std::vector<std::string>{"one"});
  hub.receive(id, FrameAckMessage{2});  // not the frame it was sent
  EXPECT_FALSE(hub.anyReady());
  hub.receive(id, FrameAckMessage{1});
  EXPECT_TRUE(hub.anyReady());
  hub.publishFrame(3, frame("three"), true);
  EXPECT_EQ(a->frames.back(), "three");
  ASSERT_EQ(hub.takeDeliveries().size(), 1u);
}

TEST(ClientHub, RefusesClientsPastTheLimit) {
  ClientHub hub;
  for (size_t i = 0; i < ClientHub::kMaxClients; ++i)
    EXPECT_NE(hub.attach(std::make_shared<RecordingConnection>()), 0u);
  EXPECT_EQ(hub.attach(std::make_shared<RecordingConnection>()), 0u);
}

// A flood of screenshot requests costs one screenshot per batch of messages, not one per request.
TEST(ClientHub, ARequestThatStillWaitsIsNotQueuedAgain) {
  ClientHub hub;
  const uint64_t ida = hub.attach(std::make_shared<RecordingConnection>());
  const uint64_t idb = hub.attach(std::make_shared<RecordingConnection>());
  for (int i = 0; i < 100; ++i) {
    hub.receive(ida, ActionMessage{ActionMessage::Kind::Screenshot});
    hub.receive(idb, ActionMessage{ActionMessage::Kind::Screenshot});
    hub.receive(idb, ActionMessage{ActionMessage::Kind::SaveView});
  }
  EXPECT_EQ(hub.takeMessages().size(), 3u);
  hub.receive(ida, ActionMessage{ActionMessage::Kind::Screenshot});
  EXPECT_EQ(hub.takeMessages().size(), 1u) << "once taken, a request is queued again";
}

}  // namespace
}  // namespace candela
