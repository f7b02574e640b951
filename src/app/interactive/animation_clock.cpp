#include "app/interactive/animation_clock.h"

#include <algorithm>
#include <cmath>

namespace candela {

void advanceAnimation(AnimationControls& controls, const SceneAnimation& animation, double seconds) {
  if (animation.clips.empty()) return;
  controls.clip = std::clamp(controls.clip, 0, int(animation.clips.size()) - 1);
  const AnimationClip& clip = animation.clips[size_t(controls.clip)];
  const double length = double(clip.end) - double(clip.start);
  double time = std::isfinite(controls.time) ? controls.time : clip.start;
  if (controls.playing && seconds > 0.0) time += seconds;
  if (!(length > 0.0))
    time = clip.start;
  else if (time > clip.end)
    time = clip.start + std::fmod(time - clip.start, length);
  else if (time < clip.start)
    time = clip.start;
  controls.time = float(time);
}

void selectClip(AnimationControls& controls, const SceneAnimation& animation, int clip) {
  if (animation.clips.empty()) return;
  controls.clip = std::clamp(clip, 0, int(animation.clips.size()) - 1);
  controls.time = animation.clips[size_t(controls.clip)].start;
}

void seekAnimation(AnimationControls& controls, const SceneAnimation& animation, float time) {
  controls.playing = false;
  if (animation.clips.empty()) return;
  controls.clip = std::clamp(controls.clip, 0, int(animation.clips.size()) - 1);
  const AnimationClip& clip = animation.clips[size_t(controls.clip)];
  controls.time = std::max(clip.start, std::min(time, clip.end));
}

}  // namespace candela
