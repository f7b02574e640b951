#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

#include "app/checkpoint/duration.h"
#include "app/schedule/sample_dispenser.h"

using namespace candela;

TEST(Duration, SecondsMinutesHours) {
  EXPECT_DOUBLE_EQ(parseDuration("90"), 90.0);
  EXPECT_DOUBLE_EQ(parseDuration("90s"), 90.0);
  EXPECT_DOUBLE_EQ(parseDuration("1.5m"), 90.0);
  EXPECT_DOUBLE_EQ(parseDuration("2h"), 7200.0);
  EXPECT_DOUBLE_EQ(parseDuration("0.2s"), 0.2);
}

TEST(Duration, RefusesWhatIsNoPositiveDuration) {
  for (const char* text : {"", "s", "0", "-5s", "10 m", "10d", "1e400", "nan", "inf", "5ss"})
    EXPECT_THROW(parseDuration(text), std::invalid_argument) << text;
}

TEST(SampleDispenser, HandsOutEveryIndexOnceInOrder) {
  SampleDispenser d(3, 10, {}, SampleDispenser::Clock::now());
  EXPECT_EQ(d.pause(0.0), SampleDispenser::Pause::None);
  EXPECT_EQ(d.take(4), 3u);
  EXPECT_EQ(d.take(4), 7u);
  EXPECT_EQ(d.remaining(), 0u);  // the second batch was cut to the 3 indices left
  EXPECT_EQ(d.next(), 10u);
  EXPECT_EQ(d.pause(0.0), SampleDispenser::Pause::End);
  EXPECT_EQ(d.end(), RenderEnd::Complete);
}

TEST(SampleDispenser, ResumedPastTheEndHasNothingToDo) {
  SampleDispenser d(12, 8, {}, SampleDispenser::Clock::now());
  EXPECT_EQ(d.remaining(), 0u);
  EXPECT_EQ(d.pause(0.0), SampleDispenser::Pause::End);
}

TEST(SampleDispenser, EndsBeforeABatchThatWouldPassTheTimeLimit) {
  RenderControl control;
  control.timeLimitSeconds = 10.0;
  SampleDispenser d(0, 100, control, SampleDispenser::Clock::now());
  EXPECT_EQ(d.pause(5.0), SampleDispenser::Pause::None);
  EXPECT_EQ(d.pause(11.0), SampleDispenser::Pause::End);
  EXPECT_EQ(d.end(), RenderEnd::TimeLimit);
}

TEST(SampleDispenser, PausesForCheckpointsOnlyWithACheckpointFile) {
  RenderControl control;
  control.checkpointEverySeconds = 0.01;
  SampleDispenser without(0, 100, control, SampleDispenser::Clock::now());
  control.checkpointPath = "render.ckpt.exr";
  SampleDispenser with(0, 100, control, SampleDispenser::Clock::now());
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(without.pause(0.0), SampleDispenser::Pause::None);
  EXPECT_EQ(with.pause(0.0), SampleDispenser::Pause::Checkpoint);
  with.checkpointWritten();
  EXPECT_EQ(with.pause(0.0), SampleDispenser::Pause::None);
}
