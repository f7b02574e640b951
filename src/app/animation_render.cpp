#include "app/animation_render.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "app/backend_factory.h"
#include "app/schedule/render_team.h"
#include "io/atomic_file.h"
#include "io/images/aov_io.h"
#include "io/load_diagnostics.h"
#include "scene/animation_player.h"

namespace candela {

namespace {

namespace fs = std::filesystem;

int64_t parseFrameNumber(std::string_view text, const std::string& whole) {
  int64_t value = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 0 || value > kMaxFrameNumber)
    throw std::invalid_argument("'" + whole + "' is not a frame range A:B of whole numbers from 0 to " +
                                std::to_string(kMaxFrameNumber));
  return value;
}

// The clip to play, with a warning (where `warn`) naming it where the scene has several and none was chosen.
int chooseClip(const Scene& scene, const std::string& choice, bool warn) {
  const SceneAnimation& animation = scene.animation;
  if (animation.empty()) {
    if (!choice.empty()) throw std::runtime_error(scene.name + ": no animation '" + choice + "' (it has none)");
    if (warn)
      std::fprintf(stderr, "candela: warning: %s has no animation; every time shows the same image\n",
                   printableText(scene.name).c_str());
    return -1;
  }
  const size_t clip = findClip(animation, choice);
  if (warn && choice.empty() && animation.clips.size() > 1) {
    std::string names;
    for (size_t i = 0; i < animation.clips.size(); ++i)
      names += (i ? ", " : "") + std::to_string(i) + " '" + animation.clips[i].name + "'";
    std::fprintf(stderr, "candela: warning: %zu animations; playing 0 '%s' (choose with --animation NAME|INDEX: %s)\n",
                 animation.clips.size(), printableText(animation.clips[0].name).c_str(), printableText(names).c_str());
  }
  return int(clip);
}

void checkOutput(const std::string& path) {
  if (!isSupportedImageExtension(path))
    throw std::runtime_error("cannot write '" + path + "': use a .png, .exr or .pfm file name");
  checkAtomicTarget(path);
}

}  // namespace

FrameRange parseFrameRange(const std::string& text) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos)
    throw std::invalid_argument("'" + text + "' is not a frame range A:B (for example 1:48)");
  const std::string_view all(text);
  FrameRange range{parseFrameNumber(all.substr(0, colon), text), parseFrameNumber(all.substr(colon + 1), text)};
  if (range.last < range.first) throw std::invalid_argument("'" + text + "': the last frame comes before the first");
  return range;
}

std::string frameFileName(const std::string& output, int64_t frame) {
  const fs::path path(output);
  std::string name = path.filename().string();
  const size_t last = name.rfind('#');
  std::string number = std::to_string(frame);
  if (last == std::string::npos) {
    const std::string stem = path.stem().string(), extension = path.extension().string();
    number.insert(0, number.size() < 4 ? 4 - number.size() : 0, '0');
    return (path.parent_path() / (stem + "_" + number + extension)).string();
  }
  size_t first = last;
  while (first > 0 && name[first - 1] == '#') --first;
  const size_t width = last - first + 1;
  number.insert(0, number.size() < width ? width - number.size() : 0, '0');
  name.replace(first, width, number);
  return (path.parent_path() / name).string();
}

int runAnimatedRender(const RenderJob& job, const AnimationRequest& request, const std::string& output,
                      const DisplaySettings& display) {
  RenderTeam* const team = job.team;
  const bool writes = !team || team->writes();
  agreedStep(team, [&] {
    if (!writes) return true;
    if (request.frames) {
      checkOutput(frameFileName(output, request.frames->first));
      checkOutput(frameFileName(output, request.frames->last));
    } else {
      checkOutput(output);
    }
    return true;
  });
  RenderJob hinted;
  Scene scene = agreedStep(team, [&] { return loadSceneForJob(job, hinted); });
  const int clip = agreedStep(team, [&] { return chooseClip(scene, request.clip, writes); });
  const AnimationPlayer player(scene);
  std::string why;
  std::unique_ptr<Backend> backend = agreedStep(team, [&] {
    if (team && hinted.devices.given)
      throw std::runtime_error("--devices does not apply under mpirun: each rank renders on the GPU of its local rank");
    return team ? createBackend(hinted.backend, why, team->localIndex())
                : createBackend(hinted.backend, why, hinted.devices);
  });
  if (writes) std::fprintf(stderr, "%s\n", why.c_str());
  // With a team, every process poses the scene and takes its share of each frame's samples; the film, added up
  // on the writer, is written there (distributed/distributed_render.h says why).
  auto renderAt = [&](double seconds, const std::string& path, bool first) {
    const size_t hidden = clip >= 0 ? player.pose(scene, clip, float(seconds)) : 0;
    if (hidden > 0 && writes)
      std::fprintf(stderr, "candela: warning: at %g s, %zu animated instances would lie beyond +-1e8 and are hidden\n",
                   seconds, hidden);
    if (first) {
      std::string fellBack;
      setSceneOrFallBack(backend, hinted.backend, scene, fellBack);
      if (!fellBack.empty() && writes) std::fprintf(stderr, "%s\n", fellBack.c_str());
    } else if (!player.deformedMeshes().empty())
      backend->setDeformedMeshes(scene, player.deformedMeshes());
    else
      backend->setInstanceTransforms(scene);
    const RenderOutcome outcome = renderLoadedScene(hinted, scene, /*showProgress=*/writes, backend.get());
    if (!outcome.writes) return;
    const std::vector<std::string> written = writeImageWithAovs(path, outcome.image, display, outcome.aovs, job.aovs);
    std::fprintf(stderr, "rendered %s at %g s: %ux%u at %u spp in %.2f s, %llu invalid samples dropped\n",
                 fs::path(path).filename().string().c_str(), seconds, outcome.settings.width, outcome.settings.height,
                 outcome.samplesPerPixel, outcome.seconds, (unsigned long long)outcome.stats.invalidSamples);
    warnWhereTheCameraSeesNoLight(outcome, display);
    for (const std::string& file : written) std::printf("%s\n", fs::absolute(file).string().c_str());
    std::fflush(stdout);
  };
  if (request.frames) {
    for (int64_t f = request.frames->first; f <= request.frames->last; ++f) {
      if (team && team->released()) break;  // the writer renders the remaining frames alone
      renderAt(double(f) / request.framesPerSecond, frameFileName(output, f), f == request.frames->first);
    }
  } else {
    renderAt(*request.time, output, true);
  }
  return 0;
}

}  // namespace candela
