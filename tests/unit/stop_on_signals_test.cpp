// A stop signal handled on another thread than the render's (checkpoint/stop_signals.h). A process's signal may be
// handled on any of its threads that does not block it, a TBB worker as well as the one that renders; the render
// must see it all the same, and without a data race (the ThreadSanitizer stage runs this test:
// scripts/test-thread-sanitized.sh).
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <limits>
#include <thread>

#include "app/checkpoint/stop_signals.h"
#include "app/schedule/sample_dispenser.h"

namespace candela {
namespace {

TEST(StopOnSignals, ASignalHandledOnAnotherThreadEndsTheRenderAtItsNextSample) {
  StopOnSignals stopOnSignals;
  SampleDispenser dispenser(0, std::numeric_limits<uint32_t>::max(), {}, SampleDispenser::Clock::now());
  std::thread other([] { std::raise(SIGUSR1); });  // raise() runs the handler on the thread that calls it
  // The render's loop, a sample at a time, while the other thread takes the signal.
  const auto deadline = SampleDispenser::Clock::now() + std::chrono::seconds(10);
  SampleDispenser::Pause pause = SampleDispenser::Pause::None;
  while (pause == SampleDispenser::Pause::None && SampleDispenser::Clock::now() < deadline) {
    pause = dispenser.pause(0.0);
    if (pause == SampleDispenser::Pause::None) dispenser.take(1);
  }
  other.join();
  EXPECT_EQ(pause, SampleDispenser::Pause::End);
  EXPECT_EQ(dispenser.end(), RenderEnd::Signal);
  EXPECT_EQ(StopOnSignals::requested(), SIGUSR1);
}

TEST(StopOnSignals, AForwardedRequestDoesNotReplaceTheSignalThatCameHere) {
  StopOnSignals stopOnSignals;
  std::raise(SIGTERM);
  StopOnSignals::forward(SIGUSR1);  // a stop request that came to another process of the render
  EXPECT_EQ(StopOnSignals::requested(), SIGTERM);
}

}  // namespace
}  // namespace candela
