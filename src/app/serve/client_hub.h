#pragma once
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app/serve/client_messages.h"

namespace candela {

// One connected browser as the render loop sees it; the WebSocket session implements it. Both calls may come from
// any thread and return at once.
class ClientConnection {
 public:
  virtual ~ClientConnection() = default;
  // Queued behind earlier messages, bounded in bytes (outgoing_queue.h): past the bound text messages are
  // dropped, and a binary message (a screenshot) takes the place of one still waiting.
  virtual void sendMessage(std::shared_ptr<const std::string> message, bool binary) = 0;
  // Takes the place of a frame not yet sent: a slow connection gets the latest frame, never a queue of old ones.
  virtual void sendFrame(std::shared_ptr<const std::string> frame) = 0;
};

struct IncomingMessage {
  uint64_t client = 0;
  ClientMessage message;
};

// A frame's trip to the browser that holds control and back (its acknowledgement).
struct FrameDelivery {
  size_t bytes = 0;
  double seconds = 0.0;
  bool moving = false;
};

// A frame as the render loop publishes it: as JPEG stripes for the browsers that take those, as the H.264 stream's
// next access unit for those that take video; either may be null where no client ready for a frame takes it.
struct PublishedFrame {
  PublishedFrame(std::shared_ptr<const std::string> jpegFrame, std::shared_ptr<const std::string> videoFrame = {})
      : jpeg(std::move(jpegFrame)), video(std::move(videoFrame)) {}
  std::shared_ptr<const std::string> jpeg, video;
};

// What the clients ready for a frame need of the next one (ClientHub::frameNeeds).
struct FrameNeeds {
  bool jpeg = false, video = false;
  // A client taking video did not get the stream's last access unit (it joined, chose video, was not ready for
  // one, or lost its decoder): the next one must be a key frame, where a decoder can start.
  bool videoKey = false;
};

// The browsers watching, which of them holds control, and the messages between them and the render loop. The
// network thread attaches, detaches and receives; the render loop takes messages and publishes frames. A client
// gets a new frame only once it has acknowledged the last one, so the render loop renders no faster than the
// quickest browser draws, and every browser gets the latest frame when it is ready for one.
class ClientHub {
 public:
  static constexpr size_t kMaxClients = 16;
  static constexpr size_t kMaxQueuedMessages = 1024;
  // A frame not acknowledged in this time is taken as lost, so a browser that never acknowledges still gets
  // a frame now and then and cannot stall anyone.
  static constexpr std::chrono::seconds kAckTimeout{5};

  // A client's screenshots are at least this far apart: each is a lossless image of the whole view, encoded on
  // the render loop's thread, so a client asking for them without pause would slow every client's frames. A
  // request sooner than that after the client's last one is dropped, with a message telling it so.
  static constexpr std::chrono::milliseconds kScreenshotInterval{1000};

  // `videoOffered`: clients may choose the H.264 stream (StreamMessage); where not, such a choice is dropped.
  explicit ClientHub(bool videoOffered = false, std::chrono::milliseconds screenshotInterval = kScreenshotInterval)
      : videoOffered_(videoOffered), screenshotInterval_(screenshotInterval) {}
  ClientHub(const ClientHub&) = delete;
  ClientHub& operator=(const ClientHub&) = delete;

  // Returns the client's id, or 0 when kMaxClients are connected already. The first client, and the oldest one
  // left when the controller leaves, holds control.
  uint64_t attach(std::shared_ptr<ClientConnection> connection);
  void detach(uint64_t client);
  // Lets every connection go (the network thread has stopped).
  void detachAll();
  // A valid message from `client`. Input from a client without control is dropped, and so is a request for a
  // screenshot or a view file while the same request of the same client still waits, and a screenshot asked for
  // within the screenshot interval of the client's last one (with a reply).
  void receive(uint64_t client, ClientMessage message);
  // An invalid or unwelcome message: logged once per kind of problem, then dropped silently.
  void dropped(uint64_t client, const std::string& problem);

  // Render loop: waits until a message waits, a client is ready for a frame, or `timeout` passes.
  void waitForWork(std::chrono::milliseconds timeout);
  std::vector<IncomingMessage> takeMessages();
  std::vector<uint64_t> takeJoined();  // clients attached since the last call
  std::vector<FrameDelivery> takeDeliveries();
  bool anyReady();
  size_t clientCount();
  uint64_t controller();
  uint64_t controlChanges();  // how often control passed to another client (or to none)
  void giveControl(uint64_t client);
  bool videoOffered();
  // Takes every client off the video stream and offers it no more (the encoder failed): JPEG frames from now on.
  void stopVideo();

  // What the next frame is needed as; `lastVideoFrame` is the number of the stream's last access unit (0: none).
  FrameNeeds frameNeeds(uint64_t lastVideoFrame);
  // Sends the frame to every client ready for one, as the stream it takes (a client whose kind is null gets none).
  void publishFrame(uint64_t frameNumber, const PublishedFrame& frame, bool moving);
  void send(uint64_t client, std::shared_ptr<const std::string> message, bool binary);
  void broadcast(const std::string& text);

 private:
  struct Client {
    std::shared_ptr<ClientConnection> connection;
    bool awaitingAck = false;
    uint64_t frameSent = 0;
    size_t bytesSent = 0;
    bool movingSent = false;
    bool video = false;           // takes the H.264 stream
    uint64_t videoFrameSent = 0;  // the last access unit it was sent
    std::chrono::steady_clock::time_point sentAt;
    std::optional<std::chrono::steady_clock::time_point> screenshotAt;  // its last screenshot request queued
  };
  bool readyLocked(const Client& client, std::chrono::steady_clock::time_point now) const;
  void droppedLocked(uint64_t client, const std::string& problem);
  void tellRolesLocked();
  void setControllerLocked(uint64_t client);

  std::mutex mutex_;
  bool videoOffered_;
  std::chrono::milliseconds screenshotInterval_;
  std::condition_variable work_;
  std::map<uint64_t, Client> clients_;  // ordered by id: the oldest first
  uint64_t nextId_ = 1;
  uint64_t controller_ = 0;
  uint64_t controlChanges_ = 0;
  std::vector<IncomingMessage> messages_;
  std::vector<uint64_t> joined_;
  std::vector<FrameDelivery> deliveries_;
  std::set<std::string> loggedProblems_;
};

}  // namespace candela
