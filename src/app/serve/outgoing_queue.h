#pragma once
#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <string>

namespace candela {

// The messages waiting to go to one browser, bounded in bytes whatever the browser does: a browser that asks for
// screenshots and reads nothing holds the server to one screenshot waiting (a newer one takes the place of one not
// yet being written) and kMaxTextBytes of text messages (more are dropped). Frames are not queued here: a session
// keeps only the latest one (ClientConnection::sendFrame).
class OutgoingQueue {
 public:
  static constexpr size_t kMaxTextBytes = 4 * 1024 * 1024;
  static constexpr size_t kMaxTextMessages = 64;

  struct Message {
    std::shared_ptr<const std::string> bytes;
    bool binary = false;
  };

  // Returns false when the message was dropped.
  bool push(std::shared_ptr<const std::string> message, bool binary);
  std::optional<Message> pop();  // the oldest message, or nullopt

  bool empty() const { return messages_.empty(); }
  size_t bytes() const { return textBytes_ + (binaryQueued_ ? binaryQueued_->size() : 0); }

 private:
  std::deque<Message> messages_;
  size_t textBytes_ = 0, textMessages_ = 0;
  const std::string* binaryQueued_ = nullptr;  // the one binary message in messages_, if any
};

}  // namespace candela
