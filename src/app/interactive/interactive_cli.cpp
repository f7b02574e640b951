#include "app/interactive/interactive_cli.h"

#include <map>

#include "io/images/image_io.h"

namespace candela {

void addInteractiveOptions(CLI::App& cmd, InteractiveOptions& options) {
  cmd.add_option("--width", options.width,
                 "Image width in pixels: the window's image beside the panel, or the browser's until it reports its "
                 "view's size")
      ->check(CLI::Range(kMinImageSide, kMaxImageSide))
      ->capture_default_str();
  cmd.add_option("--height", options.height, "Image height in pixels")
      ->check(CLI::Range(kMinImageSide, kMaxImageSide))
      ->capture_default_str();
  cmd.add_option("--max-depth", options.maxDepth, "Longest path in bounces after the camera ray")
      ->check(CLI::Range(1u, kMaxInteractiveDepth))
      ->capture_default_str();
  cmd.add_option("--spp-per-frame", options.samplesPerFrame, "Samples per pixel added each frame at rest")
      ->check(CLI::Range(1u, kMaxSamplesPerFrame))
      ->capture_default_str();
  cmd.add_option("--exposure", options.post.display.exposure, "Exposure in stops")->capture_default_str();
  cmd.add_option_function<std::string>(
         "--tonemap", [&options](const std::string& name) { options.post.display.toneMapper = parseToneMapper(name); },
         "Tone mapper: aces, reinhard or clamp (linear)")
      ->check(CLI::IsMember({"aces", "reinhard", "clamp"}))
      ->default_str(toneMapperName(options.post.display.toneMapper));
  std::map<std::string, DenoiserChoice> denoisers;
  for (DenoiserChoice choice : kViewerDenoiserChoices) denoisers[denoiserName(choice)] = choice;
  cmd.add_option("--denoise", options.post.denoiser,
                 "Denoiser to start with (the panel switches it): " +
                     describeDenoisers({std::begin(kViewerDenoiserChoices), std::end(kViewerDenoiserChoices)}))
      ->transform(CLI::CheckedTransformer(denoisers, CLI::ignore_case))
      ->default_str(denoiserName(options.post.denoiser));
  cmd.add_option("--animation", options.animation,
                 "The scene's animation to play, by name or index (default: the first)");
  cmd.add_option("--frames", options.frames, "Render this many frames, then exit (0: until closed or interrupted)")
      ->capture_default_str();
  cmd.add_option("--screenshot", options.screenshot, "On exit, write the accumulated image (.png, .exr or .pfm)");
}

}  // namespace candela
