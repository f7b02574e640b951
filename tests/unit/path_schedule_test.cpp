#include "backends/path_schedule.h"

#include <gtest/gtest.h>

using namespace candela;

TEST(PathSchedule, ParsesTheThreeNamesOnly) {
  EXPECT_EQ(parsePathSchedule("auto"), PathSchedule::Auto);
  EXPECT_EQ(parsePathSchedule("megakernel"), PathSchedule::Megakernel);
  EXPECT_EQ(parsePathSchedule("wavefront"), PathSchedule::Wavefront);
  EXPECT_FALSE(parsePathSchedule("Wavefront"));
  EXPECT_FALSE(parsePathSchedule(""));
  EXPECT_FALSE(parsePathSchedule("wavefront "));
  for (PathSchedule s : {PathSchedule::Auto, PathSchedule::Megakernel, PathSchedule::Wavefront})
    EXPECT_EQ(parsePathSchedule(pathScheduleName(s)), s);
}

TEST(PathSchedule, AutoWaitsForTheProbeAndDecidesByRaysPerSample) {
  PathScheduleChoice choice;
  EXPECT_FALSE(choice.decided());
  choice.decide(1.14);
  EXPECT_TRUE(choice.decided());
  EXPECT_EQ(choice.next(), PathSchedule::Megakernel);
  EXPECT_NE(choice.describe().find("1.14 rays per sample"), std::string::npos) << choice.describe();
  choice.reset();
  EXPECT_FALSE(choice.decided());
  choice.decide(3.05);
  EXPECT_EQ(choice.next(), PathSchedule::Wavefront);
  choice.decide(PathScheduleChoice::kWavefrontRaysPerSample);
  EXPECT_EQ(choice.next(), PathSchedule::Wavefront);
  choice.decide(PathScheduleChoice::kWavefrontRaysPerSample * 0.999);
  EXPECT_EQ(choice.next(), PathSchedule::Megakernel);
}

TEST(PathSchedule, RequestsNeedNoProbe) {
  PathScheduleChoice choice(PathSchedule::Wavefront);
  EXPECT_TRUE(choice.decided());
  EXPECT_EQ(choice.next(), PathSchedule::Wavefront);
  choice.reset();
  EXPECT_TRUE(choice.decided());
  choice.request(PathSchedule::Megakernel);
  EXPECT_EQ(choice.next(), PathSchedule::Megakernel);
  EXPECT_NE(choice.describe().find("as requested"), std::string::npos) << choice.describe();
  choice.request(PathSchedule::Auto);
  EXPECT_FALSE(choice.decided());
}

TEST(PathSchedule, AWavefrontThatDoesNotFitLeavesTheMegakernelUntilTheNextReset) {
  PathScheduleChoice choice;
  choice.decide(3.0);
  choice.wavefrontUnavailable();
  EXPECT_EQ(choice.next(), PathSchedule::Megakernel);
  EXPECT_NE(choice.describe().find("do not fit"), std::string::npos) << choice.describe();
  choice.reset();
  choice.decide(3.0);
  EXPECT_EQ(choice.next(), PathSchedule::Wavefront);
}
