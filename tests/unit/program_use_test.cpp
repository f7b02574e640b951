// Which of the GPU backend's pipelines a frame needs and which it compiles ahead (backends/optix/program_use.h):
// a first start compiles only these, so a wrong answer either stalls a frame or compiles what nothing runs.
#include <gtest/gtest.h>

#include <vector>

#include "backends/optix/program_use.h"
#include "curves/curve_scenes.h"
#include "kernel/bsdf/material_models.h"

namespace candela::optix {
namespace {

using Kinds = std::vector<PipelineKind>;
using Modules = std::vector<ProgramModule>;

// What `render` and `bench` compile before their first frame: the modules of the pipelines that frame needs.
Modules firstFrameModules(const ProgramUse& use, bool lean = true) { return modulesOf(pipelinesNeeded(use), lean); }

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
    EXPECT_EQ(firstFrameModules({schedule, true, false}),
              (Modules{ProgramModule::Rays, ProgramModule::LeanAovMegakernel}));
}

TEST(ProgramUse, ARestirRenderCompilesRestirsModuleAndTheRayProgramsOnly) {
  for (bool aovs : {false, true})
    EXPECT_EQ(firstFrameModules({PathSchedule::Megakernel, aovs, true}),
              (Modules{ProgramModule::Rays, ProgramModule::Restir}));
}

TEST(ProgramUse, AForcedScheduleCompilesItsModuleOnly) {
  EXPECT_EQ(firstFrameModules({PathSchedule::Megakernel, false, false}),
            (Modules{ProgramModule::Rays, ProgramModule::LeanMegakernel}));
  EXPECT_EQ(firstFrameModules({PathSchedule::Wavefront, false, false}),
            (Modules{ProgramModule::Rays, ProgramModule::LeanWavefront}));
}

TEST(ProgramUse, TheAutoScheduleCompilesTheProbesModuleAndTheWavefrontsTogether) {
  EXPECT_EQ(firstFrameModules({}),
            (Modules{ProgramModule::Rays, ProgramModule::LeanMegakernel, ProgramModule::LeanWavefront}));
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

// What a scene needs is the lean kernel's unless the scene uses a part it leaves out (kernel/kernel_variant.h).
TEST(ProgramUse, ASceneNeedsTheFullKernelOnlyForWhatTheLeanOneLeavesOut) {
  Scene scene = test::tubeGrid(false, 0.5f);  // triangles, diffuse
  EXPECT_TRUE(leanKernelSuffices(FlatScene::build(scene)));
  for (MaterialType type :
       {MaterialType::BlinnPhong, MaterialType::Pbr, MaterialType::Disney, MaterialType::Mirror, MaterialType::Glass}) {
    scene.materials[0].type = type;
    EXPECT_TRUE(leanKernelSuffices(FlatScene::build(scene))) << int(type);
  }
  for (MaterialType type : {MaterialType::Hair, MaterialType::DiffuseTransmission}) {
    scene.materials[0].type = type;
    EXPECT_FALSE(leanKernelSuffices(FlatScene::build(scene))) << int(type);
  }
  scene.materials[0].type = MaterialType::Pbr;
  scene.materials[0].iridescence = 1.0f;
  EXPECT_FALSE(leanKernelSuffices(FlatScene::build(scene)));
  EXPECT_FALSE(leanKernelSuffices(FlatScene::build(test::tubeGrid(true, 0.5f))));  // curves, diffuse
}

TEST(ProgramUse, TheFullKernelsPathTracersAreModulesOfTheirOwn) {
  ProgramUse use;
  EXPECT_EQ(firstFrameModules(use, false),
            (Modules{ProgramModule::Rays, ProgramModule::Megakernel, ProgramModule::Wavefront}));
  use.aovs = true;
  EXPECT_EQ(firstFrameModules(use, false), (Modules{ProgramModule::Rays, ProgramModule::AovMegakernel}));
  for (size_t k = 0; k < kPipelineKinds; ++k)
    for (RaygenProgram program : pipelinePrograms(PipelineKind(k))) {
      const bool pathTracer = PipelineKind(k) == PipelineKind::Megakernel ||
                              PipelineKind(k) == PipelineKind::AovMegakernel ||
                              PipelineKind(k) == PipelineKind::Wavefront;
      EXPECT_EQ(moduleHolding(program, true) != moduleHolding(program, false), pathTracer) << int(program);
    }
}

}  // namespace
}  // namespace candela::optix
