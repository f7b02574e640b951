// One host thread per device (backends/multi/device_threads.h).
#include "backends/multi/device_threads.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>

namespace candela {
namespace {

TEST(DeviceThreads, RunsEveryDeviceOnceConcurrentlyTheFirstOnTheCallingThread) {
  DeviceThreads threads(4);
  EXPECT_EQ(threads.size(), 4u);
  for (int round = 0; round < 100; ++round) {
    std::atomic<int> arrived{0};
    std::vector<int> calls(4, 0);
    std::vector<std::thread::id> ids(4);
    threads.run([&](size_t i) {
      ++calls[i];
      ids[i] = std::this_thread::get_id();
      // Every task waits for all four: this returns only if they run at the same time.
      ++arrived;
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
      while (arrived.load() < 4 && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
    });
    ASSERT_EQ(arrived.load(), 4);
    EXPECT_EQ(calls, (std::vector<int>{1, 1, 1, 1}));
    EXPECT_EQ(ids[0], std::this_thread::get_id());
    for (size_t i = 1; i < 4; ++i) EXPECT_NE(ids[i], ids[0]);
  }
}

TEST(DeviceThreads, EachDeviceKeepsItsThread) {
  DeviceThreads threads(3);
  std::vector<std::thread::id> first(3), second(3);
  threads.run([&](size_t i) { first[i] = std::this_thread::get_id(); });
  threads.run([&](size_t i) { second[i] = std::this_thread::get_id(); });
  EXPECT_EQ(first, second);
}

TEST(DeviceThreads, RethrowsTheLowestDevicesExceptionAfterAllReturned) {
  DeviceThreads threads(3);
  std::atomic<int> returned{0};
  try {
    threads.run([&](size_t i) {
      ++returned;
      if (i > 0) throw std::runtime_error("device " + std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "device 1");
  }
  EXPECT_EQ(returned.load(), 3);
  // The threads serve the next run as before.
  std::atomic<int> calls{0};
  threads.run([&](size_t) { ++calls; });
  EXPECT_EQ(calls.load(), 3);
}

// As the backends use it: plain memory written before run() is seen by every device's task, and what the tasks
// write is seen by the caller after it (under ThreadSanitizer, a missing ordering is reported here).
TEST(DeviceThreads, TasksSeeTheCallersDataAndTheCallerSeesTheirs) {
  DeviceThreads threads(4);
  std::vector<uint64_t> input(4), output(4);
  for (uint64_t round = 1; round <= 50; ++round) {
    for (size_t i = 0; i < 4; ++i) input[i] = round * 10 + i;
    threads.run([&](size_t i) { output[i] = input[i] * 2; });
    for (size_t i = 0; i < 4; ++i) ASSERT_EQ(output[i], (round * 10 + i) * 2);
  }
}

TEST(DeviceThreads, StopsCleanlyWhetherItRanOrNot) {
  for (int i = 0; i < 50; ++i) {
    DeviceThreads threads(4);  // destroyed at once, maybe before its workers wait for work
    if (i % 2 == 0) continue;
    std::atomic<int> calls{0};
    threads.run([&](size_t) { ++calls; });
    EXPECT_EQ(calls.load(), 4);
  }
}

TEST(DeviceThreads, OneDeviceRunsOnTheCallingThreadAlone) {
  DeviceThreads threads(1);
  std::thread::id id;
  threads.run([&](size_t i) {
    EXPECT_EQ(i, 0u);
    id = std::this_thread::get_id();
  });
  EXPECT_EQ(id, std::this_thread::get_id());
}

}  // namespace
}  // namespace candela
