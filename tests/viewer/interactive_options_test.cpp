#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "app/interactive/interactive_cli.h"

namespace candela {
namespace {

// The options `candela <command> <args>` parses, or nullopt where the command line refuses them.
std::optional<InteractiveOptions> parse(const std::string& command, std::vector<std::string> args) {
  CLI::App app;
  InteractiveOptions options;
  addInteractiveOptions(*app.add_subcommand(command), options);
  args.insert(args.begin(), command);
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
  try {
    app.parse(args);
  } catch (const CLI::ParseError&) {
    return std::nullopt;
  }
  return options;
}

void expectSame(const InteractiveOptions& a, const InteractiveOptions& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.maxDepth, b.maxDepth);
  EXPECT_EQ(a.samplesPerFrame, b.samplesPerFrame);
  EXPECT_EQ(a.post.display.exposure, b.post.display.exposure);
  EXPECT_EQ(a.post.display.toneMapper, b.post.display.toneMapper);
  EXPECT_EQ(a.post.denoiser, b.post.denoiser);
  EXPECT_EQ(a.animation, b.animation);
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_EQ(a.screenshot, b.screenshot);
}

TEST(InteractiveOptions, ViewAndServeParseTheSameArguments) {
  const std::vector<std::string> args = {"--width",         "640",    "--height",    "480",  "--max-depth", "1024",
                                         "--spp-per-frame", "16",     "--exposure",  "-1.5", "--tonemap",   "reinhard",
                                         "--denoise",       "atrous", "--animation", "Walk", "--frames",    "3",
                                         "--screenshot",    "out.exr"};
  const std::optional<InteractiveOptions> view = parse("view", args), serve = parse("serve", args);
  ASSERT_TRUE(view);
  ASSERT_TRUE(serve);
  expectSame(*view, *serve);
  EXPECT_EQ(serve->width, 640u);
  EXPECT_EQ(serve->maxDepth, 1024u);
  EXPECT_EQ(serve->samplesPerFrame, 16u);
  EXPECT_EQ(serve->post.display.exposure, -1.5f);
  EXPECT_EQ(serve->post.display.toneMapper, ToneMapper::Reinhard);
  EXPECT_EQ(serve->post.denoiser, DenoiserChoice::Atrous);
  EXPECT_EQ(serve->animation, "Walk");
  EXPECT_EQ(serve->frames, 3u);
  EXPECT_EQ(serve->screenshot, "out.exr");
}

TEST(InteractiveOptions, TheDefaultsAreTheStructs) {
  for (const char* command : {"view", "serve"}) {
    const std::optional<InteractiveOptions> parsed = parse(command, {});
    ASSERT_TRUE(parsed) << command;
    expectSame(*parsed, InteractiveOptions());
  }
}

// The viewer's limits are the ones: serve took depths and samples per frame up to 64 and images of 16 to 4096.
TEST(InteractiveOptions, BothTakeTheSameLimits) {
  for (const char* command : {"view", "serve"}) {
    for (const auto& [option, lowest, highest] :
         {std::tuple{"--max-depth", 1u, kMaxInteractiveDepth}, std::tuple{"--spp-per-frame", 1u, kMaxSamplesPerFrame},
          std::tuple{"--width", kMinImageSide, kMaxImageSide}, std::tuple{"--height", kMinImageSide, kMaxImageSide}}) {
      EXPECT_TRUE(parse(command, {option, std::to_string(lowest)})) << command << " " << option;
      EXPECT_TRUE(parse(command, {option, std::to_string(highest)})) << command << " " << option;
      EXPECT_FALSE(parse(command, {option, std::to_string(lowest - 1)})) << command << " " << option;
      EXPECT_FALSE(parse(command, {option, std::to_string(highest + 1)})) << command << " " << option;
    }
    EXPECT_EQ(parse(command, {"--max-depth", "1024"})->maxDepth, 1024u);
    EXPECT_FALSE(parse(command, {"--tonemap", "filmic"}));
    EXPECT_FALSE(parse(command, {"--denoise", "magic"}));
  }
}

}  // namespace
}  // namespace candela
