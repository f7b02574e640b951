#include "app/serve/client_hub.h"

#include <nlohmann/json.hpp>

#include <cstdio>

#include "io/load_diagnostics.h"

namespace candela {

namespace {

constexpr size_t kMaxLoggedProblems = 64;

}  // namespace

uint64_t ClientHub::attach(std::shared_ptr<ClientConnection> connection) {
  std::lock_guard lock(mutex_);
  if (clients_.size() >= kMaxClients) return 0;
  const uint64_t id = nextId_++;
  clients_[id].connection = std::move(connection);
  joined_.push_back(id);
  if (controller_ == 0)
    setControllerLocked(id);
  else
    tellRolesLocked();
  work_.notify_all();
  return id;
}

void ClientHub::detach(uint64_t client) {
  std::lock_guard lock(mutex_);
  if (clients_.erase(client) == 0) return;
  if (controller_ == client)
    setControllerLocked(clients_.empty() ? 0 : clients_.begin()->first);
  else
    tellRolesLocked();
}

void ClientHub::detachAll() {
  std::lock_guard lock(mutex_);
  clients_.clear();
  controller_ = 0;
}

void ClientHub::receive(uint64_t client, ClientMessage message) {
  std::lock_guard lock(mutex_);
  auto it = clients_.find(client);
  if (it == clients_.end()) return;
  if (const auto* ack = std::get_if<FrameAckMessage>(&message)) {
    Client& c = it->second;
    if (c.awaitingAck && ack->frame == c.frameSent) {
      c.awaitingAck = false;
      if (client == controller_) {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - c.sentAt).count();
        deliveries_.push_back({c.bytesSent, seconds, c.movingSent});
      }
      work_.notify_all();
    }
    return;
  }
  if (const auto* stream = std::get_if<StreamMessage>(&message)) {
    if (stream->stream == FrameStream::H264 && !videoOffered_) {
      droppedLocked(client, "a video stream, which this server does not offer");
      return;
    }
    it->second.video = stream->stream == FrameStream::H264;
    it->second.videoFrameSent = 0;
    return;
  }
  const auto* action = std::get_if<ActionMessage>(&message);
  const bool anyoneMay =
      action && (action->kind == ActionMessage::Kind::TakeControl || action->kind == ActionMessage::Kind::Screenshot ||
                 action->kind == ActionMessage::Kind::SaveView);
  if (client != controller_ && !anyoneMay) return;  // watchers look; they do not steer
  if (messages_.size() >= kMaxQueuedMessages) return;
  if (action && action->kind != ActionMessage::Kind::TakeControl)
    for (const IncomingMessage& waiting : messages_)
      if (const auto* same = std::get_if<ActionMessage>(&waiting.message);
          waiting.client == client && same && same->kind == action->kind)
        return;
  if (action && action->kind == ActionMessage::Kind::Screenshot) {
    Client& c = it->second;
    const auto now = std::chrono::steady_clock::now();
    if (c.screenshotAt && now - *c.screenshotAt < screenshotInterval_) {
      char text[96];
      std::snprintf(text, sizeof text, "no screenshot: one every %g s at most, and the last was asked for sooner",
                    std::chrono::duration<double>(screenshotInterval_).count());
      const nlohmann::json reply = {{"type", "message"}, {"text", text}, {"error", false}};
      c.connection->sendMessage(std::make_shared<const std::string>(reply.dump()), false);
      return;
    }
    c.screenshotAt = now;
  }
  messages_.push_back({client, std::move(message)});
  work_.notify_all();
}

void ClientHub::dropped(uint64_t client, const std::string& problem) {
  std::lock_guard lock(mutex_);
  droppedLocked(client, problem);
}

void ClientHub::droppedLocked(uint64_t client, const std::string& problem) {
  const std::string kind = problem.substr(0, problem.find('\''));
  if (loggedProblems_.size() >= kMaxLoggedProblems || !loggedProblems_.insert(kind).second) return;
  std::fprintf(stderr,
               "candela serve: dropped a message from client %llu: %s (such messages are dropped "
               "silently from now on)\n",
               static_cast<unsigned long long>(client), printableText(problem).c_str());
}

void ClientHub::waitForWork(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  work_.wait_for(lock, timeout, [&] {
    if (!messages_.empty() || !joined_.empty()) return true;
    const auto now = std::chrono::steady_clock::now();
    for (const auto& [id, c] : clients_)
      if (readyLocked(c, now)) return true;
    return false;
  });
}

std::vector<IncomingMessage> ClientHub::takeMessages() {
  std::lock_guard lock(mutex_);
  return std::exchange(messages_, {});
}

std::vector<uint64_t> ClientHub::takeJoined() {
  std::lock_guard lock(mutex_);
  return std::exchange(joined_, {});
}

std::vector<FrameDelivery> ClientHub::takeDeliveries() {
  std::lock_guard lock(mutex_);
  return std::exchange(deliveries_, {});
}

bool ClientHub::readyLocked(const Client& client, std::chrono::steady_clock::time_point now) const {
  return !client.awaitingAck || now - client.sentAt > kAckTimeout;
}

bool ClientHub::anyReady() {
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  for (const auto& [id, c] : clients_)
    if (readyLocked(c, now)) return true;
  return false;
}

size_t ClientHub::clientCount() {
  std::lock_guard lock(mutex_);
  return clients_.size();
}

uint64_t ClientHub::controller() {
  std::lock_guard lock(mutex_);
  return controller_;
}

uint64_t ClientHub::controlChanges() {
  std::lock_guard lock(mutex_);
  return controlChanges_;
}

void ClientHub::giveControl(uint64_t client) {
  std::lock_guard lock(mutex_);
  if (clients_.count(client) && controller_ != client) setControllerLocked(client);
}

void ClientHub::setControllerLocked(uint64_t client) {
  controller_ = client;
  ++controlChanges_;
  tellRolesLocked();
}

void ClientHub::tellRolesLocked() {
  for (const auto& [id, c] : clients_) {
    const nlohmann::json role = {{"type", "role"}, {"control", id == controller_}, {"clients", clients_.size()}};
    c.connection->sendMessage(std::make_shared<const std::string>(role.dump()), false);
  }
}

bool ClientHub::videoOffered() {
  std::lock_guard lock(mutex_);
  return videoOffered_;
}

void ClientHub::stopVideo() {
  std::lock_guard lock(mutex_);
  videoOffered_ = false;
  for (auto& [id, c] : clients_) c.video = false;
}

FrameNeeds ClientHub::frameNeeds(uint64_t lastVideoFrame) {
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  FrameNeeds needs;
  for (const auto& [id, c] : clients_) {
    if (!readyLocked(c, now)) continue;
    needs.jpeg = needs.jpeg || !c.video;
    needs.video = needs.video || c.video;
    needs.videoKey = needs.videoKey || (c.video && (lastVideoFrame == 0 || c.videoFrameSent != lastVideoFrame));
  }
  return needs;
}

void ClientHub::publishFrame(uint64_t frameNumber, const PublishedFrame& frame, bool moving) {
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  for (auto& [id, c] : clients_) {
    const std::shared_ptr<const std::string>& message = c.video ? frame.video : frame.jpeg;
    if (!message || !readyLocked(c, now)) continue;
    c.awaitingAck = true;
    c.frameSent = frameNumber;
    if (c.video) c.videoFrameSent = frameNumber;
    c.bytesSent = message->size();
    c.movingSent = moving;
    c.sentAt = now;
    c.connection->sendFrame(message);
  }
}

void ClientHub::send(uint64_t client, std::shared_ptr<const std::string> message, bool binary) {
  std::lock_guard lock(mutex_);
  auto it = clients_.find(client);
  if (it != clients_.end()) it->second.connection->sendMessage(std::move(message), binary);
}

void ClientHub::broadcast(const std::string& text) {
  std::lock_guard lock(mutex_);
  auto message = std::make_shared<const std::string>(text);
  for (const auto& [id, c] : clients_) c.connection->sendMessage(message, false);
}

}  // namespace candela
