#include <gtest/gtest.h>

#include <cmath>

#include "app/interactive/interactive_policy.h"

namespace candela {
namespace {

constexpr double kBudget = 1.0 / 30.0;
constexpr double kSettle = 0.2;

TEST(InteractivePolicy, AtRestRendersTheFullImageWithTheChosenSamples) {
  InteractivePolicy policy(kBudget, kSettle);
  FramePlan plan = policy.plan(640, 480, 4, /*cameraMoved=*/false, 1.0);
  EXPECT_FALSE(plan.preview);
  EXPECT_EQ(plan.width, 640u);
  EXPECT_EQ(plan.height, 480u);
  EXPECT_EQ(plan.samplesPerPixel, 4u);
}

TEST(InteractivePolicy, MotionDividesTheResolutionToFitTheBudget) {
  InteractivePolicy policy(kBudget, kSettle);
  // A full 640x480 frame at one sample per pixel took 0.25 s, 7.5 times the budget: a third of each side fits.
  policy.recordFrame({640, 480, 1, false}, 0.25);
  FramePlan plan = policy.plan(640, 480, 4, /*cameraMoved=*/true, 1.0);
  EXPECT_TRUE(plan.preview);
  EXPECT_EQ(plan.width, 640u / 3);
  EXPECT_EQ(plan.height, 480u / 3);
  EXPECT_EQ(plan.samplesPerPixel, 1u);
  EXPECT_LE(policy.secondsPerSample() * plan.width * plan.height, kBudget * 1.0001);
}

TEST(InteractivePolicy, CheapFramesStayAtFullResolutionWhileMoving) {
  InteractivePolicy policy(kBudget, kSettle);
  policy.recordFrame({640, 480, 1, false}, 0.01);
  FramePlan plan = policy.plan(640, 480, 8, true, 1.0);
  EXPECT_TRUE(plan.preview);
  EXPECT_EQ(plan.width, 640u);
  EXPECT_EQ(plan.samplesPerPixel, 1u);
}

TEST(InteractivePolicy, ReturnsToFullQualityAfterTheSettleTime) {
  InteractivePolicy policy(kBudget, kSettle);
  policy.recordFrame({640, 480, 1, false}, 0.3);
  EXPECT_TRUE(policy.plan(640, 480, 4, true, 1.0).preview);
  EXPECT_TRUE(policy.plan(640, 480, 4, false, 1.0 + 0.5 * kSettle).preview);
  FramePlan rest = policy.plan(640, 480, 4, false, 1.0 + 1.5 * kSettle);
  EXPECT_FALSE(rest.preview);
  EXPECT_EQ(rest.width, 640u);
  EXPECT_EQ(rest.samplesPerPixel, 4u);
}

TEST(InteractivePolicy, TheDivisorHoldsForTheWholeMotion) {
  InteractivePolicy policy(kBudget, kSettle);
  policy.recordFrame({640, 480, 1, false}, 0.3);
  FramePlan first = policy.plan(640, 480, 1, true, 1.0);
  policy.recordFrame(first, 0.5);  // a slow preview frame does not change the resolution mid-motion
  FramePlan second = policy.plan(640, 480, 1, true, 1.05);
  EXPECT_EQ(second.width, first.width);
}

TEST(InteractivePolicy, TheDivisorIsBounded) {
  InteractivePolicy policy(kBudget, kSettle);
  policy.recordFrame({640, 480, 1, false}, 1e3);
  FramePlan plan = policy.plan(640, 480, 1, true, 1.0);
  EXPECT_EQ(plan.width, 640u / InteractivePolicy::kMaxDivisor);
  FramePlan tiny = policy.plan(640, 480, 1, true, 1.0);
  EXPECT_GE(tiny.height, 1u);
}

}  // namespace
}  // namespace candela
