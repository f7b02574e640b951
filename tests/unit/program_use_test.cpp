// Which of the GPU backend's pipelines a frame needs and which it compiles ahead (backends/optix/program_use.h):
// a first start compiles only these, so a wrong answer either stalls a frame or compiles what nothing runs.
#include <gtest/gtest.h>

#include <vector>

#include "backends/optix/program_use.h"

namespace candela::optix {
namespace {

using Kinds = std::vector<PipelineKind>;
using Modules = std::vector<ProgramModule>;

// What `render` and `bench` compile before their first frame: the modules of the pipelines that frame needs.
Modules firstFrameModules(const ProgramUse& use) { return modulesOf(pipelinesNeeded(use)); }

TEST(ProgramUse, AutoScheduleNeedsTheProbeAndItsLikelyChoice) {
  EXPECT_EQ(pipelinesNeeded({}), (Kinds{PipelineKind::Megakernel, PipelineKind::Wavefront}));
}

TEST(ProgramUse, ADecidedScheduleNeedsItsPipelineOnly) {
  EXPECT_EQ(pipelinesNeeded({PathSchedule::Megakernel, false, false}), Kinds{PipelineKind::Megakernel});
  EXPECT_EQ(pipelinesNeeded({PathSchedule::Wavefront, false, false}), Kinds{PipelineKind::Wavefront});
}

TEST(ProgramUse, AovsNeedTheAovPathTracerWhateverTheSchedule) {
  for (PathSchedule schedule : {PathSchedule::Auto, PathSchedule::Megakernel, PathSchedule::Wavefront})
    EXPECT_EQ(pipelinesNeeded({schedule, true, false}), Kinds{PipelineKind::AovMegakernel});
}

TEST(ProgramUse, RestirNeedsItsOwnPipelineWithOrWithoutAovs) {
  EXPECT_EQ(pipelinesNeeded({PathSchedule::Auto, false, true}), Kinds{PipelineKind::Restir});
  EXPECT_EQ(pipelinesNeeded({PathSchedule::Megakernel, true, true}), Kinds{PipelineKind::Restir});
}

TEST(ProgramUse, MediaNeedTheirOwnPipelineAndPrefetchNothing) {
  for (bool aovs : {false, true})
    for (PathSchedule schedule : {PathSchedule::Auto, PathSchedule::Megakernel, PathSchedule::Wavefront}) {
      const ProgramUse use{schedule, aovs, false, true};
      EXPECT_EQ(pipelinesNeeded(use), Kinds{PipelineKind::Media});
      EXPECT_TRUE(pipelinesLikely(use).empty());
    }
}

TEST(ProgramUse, NothingNeedsTheRawTrace) {
  for (bool aovs : {false, true})
    for (bool restir : {false, true})
      for (PathSchedule schedule : {PathSchedule::Auto, PathSchedule::Megakernel, PathSchedule::Wavefront}) {
        const ProgramUse use{schedule, aovs, restir};
        for (const Kinds& kinds : {pipelinesNeeded(use), pipelinesLikely(use)})
          for (PipelineKind kind : kinds) EXPECT_NE(kind, PipelineKind::RawTrace);
      }
}

TEST(ProgramUse, ADenoiserIsLikelyAndSoIsSwitchingItOff) {
  EXPECT_EQ(pipelinesLikely({PathSchedule::Wavefront, false, false}), Kinds{PipelineKind::AovMegakernel});
  EXPECT_EQ(pipelinesLikely({PathSchedule::Wavefront, true, false}), Kinds{PipelineKind::Wavefront});
}

TEST(ProgramUse, RestirPrefetchesNothing) {
  EXPECT_TRUE(pipelinesLikely({PathSchedule::Auto, false, true}).empty());
  EXPECT_TRUE(pipelinesLikely({PathSchedule::Auto, true, true}).empty());
}

TEST(ProgramUse, ADenoisedRenderCompilesTheAovPathTracerAndTheRayProgramsOnly) {
  for (PathSchedule schedule : {PathSchedule::Auto, PathSchedule::Megakernel, PathSchedule::Wavefront})
    EXPECT_EQ(firstFrameModules({schedule, true, false}), (Modules{ProgramModule::Rays, ProgramModule::AovMegakernel}));
}

TEST(ProgramUse, ARestirRenderCompilesRestirsModuleAndTheRayProgramsOnly) {
  for (bool aovs : {false, true})
    EXPECT_EQ(firstFrameModules({PathSchedule::Megakernel, aovs, true}),
              (Modules{ProgramModule::Rays, ProgramModule::Restir}));
}

TEST(ProgramUse, AForcedScheduleCompilesItsModuleOnly) {
  EXPECT_EQ(firstFrameModules({PathSchedule::Megakernel, false, false}),
            (Modules{ProgramModule::Rays, ProgramModule::Megakernel}));
  EXPECT_EQ(firstFrameModules({PathSchedule::Wavefront, false, false}),
            (Modules{ProgramModule::Rays, ProgramModule::Wavefront}));
}

TEST(ProgramUse, TheAutoScheduleCompilesTheProbesModuleAndTheWavefrontsTogether) {
  EXPECT_EQ(firstFrameModules({}), (Modules{ProgramModule::Rays, ProgramModule::Megakernel, ProgramModule::Wavefront}));
}

// The first frame waits for the megakernel alone where the schedule is Auto's, decided or not: the wavefront's
// module compiles beside it and takes over when done.
TEST(ProgramUse, TheMegakernelStandsInForAutosWavefront) {
  EXPECT_EQ(pipelinesAwaited({}), Kinds{PipelineKind::Megakernel});
  EXPECT_EQ(pipelinesAwaited({PathSchedule::Wavefront, false, false}), Kinds{PipelineKind::Megakernel});
  EXPECT_EQ(pipelinesAwaited({PathSchedule::Megakernel, false, false}), Kinds{PipelineKind::Megakernel});
}

TEST(ProgramUse, ARequestedWavefrontIsAwaited) {
  const ProgramUse requested{PathSchedule::Wavefront, false, false, false, false};
  EXPECT_EQ(pipelinesAwaited(requested), Kinds{PipelineKind::Wavefront});
}

TEST(ProgramUse, NothingStandsInForTheOtherPipelines) {
  for (PathSchedule schedule : {PathSchedule::Auto, PathSchedule::Wavefront}) {
    EXPECT_EQ(pipelinesAwaited({schedule, true, false}), Kinds{PipelineKind::AovMegakernel});
    EXPECT_EQ(pipelinesAwaited({schedule, false, true}), Kinds{PipelineKind::Restir});
    EXPECT_EQ(pipelinesAwaited({schedule, false, false, true}), Kinds{PipelineKind::Media});
  }
}

TEST(ProgramUse, EveryProgramIsLaunchedByThePipelineThatHoldsIt) {
  for (size_t k = 0; k < kPipelineKinds; ++k)
    for (RaygenProgram program : pipelinePrograms(PipelineKind(k)))
      EXPECT_EQ(pipelineLaunching(program), PipelineKind(k));
}

}  // namespace
}  // namespace candela::optix
