#include "app/serve/outgoing_queue.h"

namespace candela {

bool OutgoingQueue::push(std::shared_ptr<const std::string> message, bool binary) {
  if (binary) {
    for (Message& queued : messages_)
      if (queued.binary) {
        queued.bytes = std::move(message);
        binaryQueued_ = queued.bytes.get();
        return true;
      }
    binaryQueued_ = message.get();
  } else {
    if (textMessages_ >= kMaxTextMessages || textBytes_ + message->size() > kMaxTextBytes) return false;
    textBytes_ += message->size();
    ++textMessages_;
  }
  messages_.push_back({std::move(message), binary});
  return true;
}

std::optional<OutgoingQueue::Message> OutgoingQueue::pop() {
  if (messages_.empty()) return std::nullopt;
  Message message = std::move(messages_.front());
  messages_.pop_front();
  if (message.binary) {
    binaryQueued_ = nullptr;
  } else {
    textBytes_ -= message.bytes->size();
    --textMessages_;
  }
  return message;
}

}  // namespace candela
