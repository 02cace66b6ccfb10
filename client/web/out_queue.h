// A browser's bounded queue of messages waiting to be written: past its byte budget the browser
// is too slow and is dropped, so it never holds back the others or grows the gateway's memory.
#pragma once

#include <cstddef>
#include <deque>
#include <memory>
#include <string>

namespace pool::web {

/// One shared, immutable message: every browser of a match queues the same bytes.
using Message = std::shared_ptr<const std::string>;

/// Messages queued for one browser, oldest first, holding at most `max_bytes` (the message being
/// written included: it stays at the front until popped).
class OutQueue {
 public:
  explicit OutQueue(std::size_t max_bytes) : max_bytes_(max_bytes) {}

  /// Queues `message`; false (and nothing queued) when it would pass the budget: the browser has
  /// fallen too far behind and must be dropped.
  bool push(Message message) {
    if (!message) return true;
    if (bytes_ + message->size() > max_bytes_) return false;
    bytes_ += message->size();
    queue_.push_back(std::move(message));
    return true;
  }
  const Message& front() const { return queue_.front(); }
  void pop() {
    bytes_ -= queue_.front()->size();
    queue_.pop_front();
  }
  bool empty() const { return queue_.empty(); }
  std::size_t size() const { return queue_.size(); }
  std::size_t bytes() const { return bytes_; }

 private:
  std::size_t max_bytes_;
  std::size_t bytes_ = 0;
  std::deque<Message> queue_;
};

}  // namespace pool::web
