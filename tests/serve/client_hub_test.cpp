#include <gtest/gtest.h>

#include <chrono>
#include <thread>

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

// Each client gets the stream it chose; a client taking video needs a key frame whenever it missed the stream's
// last access unit: when it chose video, and after a frame it was not ready for.
TEST(ClientHub, VideoClientsGetKeyFramesWhereTheyMissedTheStream) {
  ClientHub hub(/*videoOffered=*/true);
  auto a = std::make_shared<RecordingConnection>(), b = std::make_shared<RecordingConnection>();
  const uint64_t ida = hub.attach(a), idb = hub.attach(b);
  hub.receive(idb, StreamMessage{FrameStream::H264});
  FrameNeeds needs = hub.frameNeeds(0);
  EXPECT_TRUE(needs.jpeg && needs.video && needs.videoKey);
  hub.publishFrame(1, {frame("jpeg 1"), frame("key 1")}, false);
  EXPECT_EQ(a->frames.back(), "jpeg 1");
  EXPECT_EQ(b->frames.back(), "key 1");
  hub.receive(ida, FrameAckMessage{1});
  hub.receive(idb, FrameAckMessage{1});
  needs = hub.frameNeeds(1);
  EXPECT_TRUE(needs.video && !needs.videoKey) << "b has the stream's last access unit";
  hub.publishFrame(2, {frame("jpeg 2"), frame("delta 2")}, false);
  hub.receive(ida, FrameAckMessage{2});  // b does not acknowledge: it misses frame 3
  needs = hub.frameNeeds(2);
  EXPECT_TRUE(needs.jpeg && !needs.video);
  hub.publishFrame(3, {frame("jpeg 3"), nullptr}, false);
  hub.receive(idb, FrameAckMessage{2});
  EXPECT_FALSE(hub.frameNeeds(2).videoKey) << "frame 3 had no access unit: the stream is whole for b";
  hub.receive(ida, FrameAckMessage{3});
  hub.publishFrame(4, {frame("jpeg 4"), frame("delta 4")}, false);
  hub.receive(idb, FrameAckMessage{4});
  hub.receive(ida, FrameAckMessage{4});
  hub.publishFrame(5, {frame("jpeg 5"), frame("delta 5")}, false);  // b acknowledges it late
  hub.receive(ida, FrameAckMessage{5});
  hub.publishFrame(6, {frame("jpeg 6"), frame("delta 6")}, false);  // not to b
  hub.receive(idb, FrameAckMessage{5});
  EXPECT_TRUE(hub.frameNeeds(6).videoKey) << "b missed access unit 6";
  EXPECT_EQ(b->frames, (std::vector<std::string>{"key 1", "delta 2", "delta 4", "delta 5"}));
  // Choosing video again (the page's decoder failed) asks for a key frame too.
  hub.publishFrame(7, {frame("jpeg 7"), frame("key 7")}, false);
  hub.receive(idb, FrameAckMessage{7});
  EXPECT_FALSE(hub.frameNeeds(7).videoKey);
  hub.receive(idb, StreamMessage{FrameStream::H264});
  EXPECT_TRUE(hub.frameNeeds(7).videoKey);
}

TEST(ClientHub, VideoIsRefusedWhereItIsNotOffered) {
  ClientHub hub;
  auto a = std::make_shared<RecordingConnection>();
  const uint64_t id = hub.attach(a);
  hub.receive(id, StreamMessage{FrameStream::H264});
  const FrameNeeds needs = hub.frameNeeds(0);
  EXPECT_TRUE(needs.jpeg && !needs.video);
}

// A flood of screenshot requests costs one screenshot per batch of messages, not one per request.
TEST(ClientHub, ARequestThatStillWaitsIsNotQueuedAgain) {
  ClientHub hub(false, std::chrono::milliseconds(0));  // no interval between screenshots (tested below)
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

// A client's screenshots are at least the interval apart: one asked for sooner is dropped with a reply to that
// client alone, and other clients are not held back by it.
TEST(ClientHub, AClientsScreenshotsAreAtLeastTheIntervalApart) {
  ClientHub hub;  // one second
  auto a = std::make_shared<RecordingConnection>(), b = std::make_shared<RecordingConnection>();
  const uint64_t ida = hub.attach(a), idb = hub.attach(b);
  const size_t aMessages = a->messages.size(), bMessages = b->messages.size();
  hub.receive(ida, ActionMessage{ActionMessage::Kind::Screenshot});
  EXPECT_EQ(hub.takeMessages().size(), 1u);
  hub.receive(ida, ActionMessage{ActionMessage::Kind::Screenshot});
  EXPECT_TRUE(hub.takeMessages().empty()) << "a second screenshot within the interval was queued";
  ASSERT_EQ(a->messages.size(), aMessages + 1);
  EXPECT_NE(a->messages.back().find("\"type\":\"message\""), std::string::npos) << a->messages.back();
  EXPECT_NE(a->messages.back().find("no screenshot: one every 1 s at most"), std::string::npos) << a->messages.back();
  hub.receive(idb, ActionMessage{ActionMessage::Kind::Screenshot});
  EXPECT_EQ(hub.takeMessages().size(), 1u) << "another client's screenshot waits for nobody";
  EXPECT_EQ(b->messages.size(), bMessages);

  ClientHub quick(false, std::chrono::milliseconds(20));
  const uint64_t id = quick.attach(std::make_shared<RecordingConnection>());
  quick.receive(id, ActionMessage{ActionMessage::Kind::Screenshot});
  EXPECT_EQ(quick.takeMessages().size(), 1u);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  quick.receive(id, ActionMessage{ActionMessage::Kind::Screenshot});
  EXPECT_EQ(quick.takeMessages().size(), 1u) << "a screenshot after the interval was dropped";
}

}  // namespace
}  // namespace candela
