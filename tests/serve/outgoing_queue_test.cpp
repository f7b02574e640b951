#include <gtest/gtest.h>

#include "app/serve/outgoing_queue.h"

namespace candela {
namespace {

std::shared_ptr<const std::string> bytes(size_t n, char c = 'x') { return std::make_shared<const std::string>(n, c); }

// A browser that asks for a screenshot again and again and reads nothing: the queue holds one, the latest.
TEST(OutgoingQueue, AScreenshotFloodHoldsOneScreenshot) {
  OutgoingQueue queue;
  constexpr size_t kScreenshotBytes = 1 << 20;
  for (int i = 0; i < 1000; ++i) {
    queue.push(bytes(kScreenshotBytes, char('a' + i % 26)), /*binary=*/true);
    ASSERT_LE(queue.bytes(), kScreenshotBytes) << "after " << i + 1 << " screenshots";
  }
  std::optional<OutgoingQueue::Message> first = queue.pop();
  ASSERT_TRUE(first);
  EXPECT_TRUE(first->binary);
  EXPECT_EQ(first->bytes->front(), char('a' + 999 % 26)) << "the latest screenshot is the one kept";
  EXPECT_FALSE(queue.pop());
  EXPECT_EQ(queue.bytes(), 0u);
}

TEST(OutgoingQueue, TextMessagesAreBoundedInBytesAndCount) {
  OutgoingQueue queue;
  size_t accepted = 0;
  for (int i = 0; i < 10000; ++i) accepted += queue.push(bytes(100 * 1024), false);
  EXPECT_LE(queue.bytes(), OutgoingQueue::kMaxTextBytes);
  EXPECT_EQ(accepted, OutgoingQueue::kMaxTextBytes / (100 * 1024));
  OutgoingQueue small;
  for (int i = 0; i < 10000; ++i) small.push(bytes(10), false);
  size_t count = 0;
  while (small.pop()) ++count;
  EXPECT_EQ(count, OutgoingQueue::kMaxTextMessages);
}

TEST(OutgoingQueue, KeepsTheOrderOfTextAroundTheScreenshot) {
  OutgoingQueue queue;
  queue.push(bytes(1, 'a'), false);
  queue.push(bytes(1, 'S'), true);
  queue.push(bytes(1, 'b'), false);
  queue.push(bytes(1, 'T'), true);  // takes the first screenshot's place, before 'b'
  std::string order;
  while (std::optional<OutgoingQueue::Message> m = queue.pop()) order += *m->bytes;
  EXPECT_EQ(order, "aTb");
  queue.push(bytes(1, 'U'), true);  // none waits now: queued anew
  EXPECT_EQ(*queue.pop()->bytes, "U");
}

}  // namespace
}  // namespace candela
