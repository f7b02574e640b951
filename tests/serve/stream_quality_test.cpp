#include <gtest/gtest.h>

#include "app/serve/stream_quality.h"

namespace candela {
namespace {

TEST(StreamQuality, SlowDeliveriesLowerQualityThenResolutionAndQuickOnesRaiseThem) {
  StreamQuality q(0.05);
  const int start = q.jpegQuality(true);
  for (int i = 0; i < 20; ++i) q.recordDelivery(100000, 0.2, true);
  EXPECT_EQ(q.jpegQuality(true), StreamQuality::kMinMovingQuality);
  EXPECT_EQ(q.resolutionDivisor(true), StreamQuality::kMaxExtraDivisor);
  EXPECT_EQ(q.jpegQuality(false), StreamQuality::kRestQuality);  // at rest: full quality, whatever the link
  EXPECT_EQ(q.resolutionDivisor(false), 1u);
  for (int i = 0; i < 40; ++i) q.recordDelivery(10000, 0.005, true);
  EXPECT_EQ(q.resolutionDivisor(true), 1u);
  EXPECT_GE(q.jpegQuality(true), start);
  EXPECT_GT(q.bytesPerSecond(), 0.0);
}

TEST(StreamQuality, DeliveriesAtRestLeaveTheMovingSettingsAlone) {
  StreamQuality q(0.05);
  const int start = q.jpegQuality(true);
  for (int i = 0; i < 10; ++i) q.recordDelivery(1000000, 1.0, false);
  EXPECT_EQ(q.jpegQuality(true), start);
}

TEST(StreamQuality, TheVideoTakesTheMeasuredFrameRateRoundedUpToAStep) {
  const StreamQuality q;
  EXPECT_EQ(q.videoSettings(true, 0.0).framesPerSecond, H264Settings().framesPerSecond) << "not measured yet";
  EXPECT_EQ(q.videoSettings(true, 113.2).framesPerSecond, 115u);
  EXPECT_EQ(q.videoSettings(true, 115.0).framesPerSecond, 115u);
  EXPECT_EQ(q.videoSettings(true, 0.2).framesPerSecond, StreamQuality::kFrameRateStep);
  EXPECT_EQ(q.videoSettings(true, 1e9).framesPerSecond, StreamQuality::kMaxFrameRate);
  EXPECT_EQ(q.videoSettings(false, 12.0).framesPerSecond, 15u) << "at rest, slower than the rest rate";
}

// At rest the stream goes slower, so that each frame gets more of the rate, with a lower rate factor to spend it and
// the deblocking filter; moving, it keeps the measured rate and the encoder's speed.
TEST(StreamQuality, TheVideoAtRestHasFewerFramesAtAHigherQuality) {
  const StreamQuality q;
  for (const double measured : {0.0, 60.0, 240.0}) {
    const H264Settings rest = q.videoSettings(false, measured), moving = q.videoSettings(true, measured);
    EXPECT_EQ(rest.framesPerSecond, StreamQuality::kRestFrameRate) << measured;
    EXPECT_LT(rest.framesPerSecond, moving.framesPerSecond) << measured;
    EXPECT_LT(rest.rateFactor, moving.rateFactor) << measured;
    EXPECT_EQ(rest.maxKilobitsPerSecond, moving.maxKilobitsPerSecond) << "the same cap";
    EXPECT_TRUE(rest.deblocking);
    EXPECT_FALSE(moving.deblocking);
  }
}

}  // namespace
}  // namespace candela
