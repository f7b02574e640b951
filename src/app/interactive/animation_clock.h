#pragma once
#include "scene/animation.h"

namespace candela {

// The viewer's animation controls: which clip plays, where it is, and whether it runs.
struct AnimationControls {
  bool playing = true;
  int clip = 0;       // an index into SceneAnimation::clips
  float time = 0.0f;  // seconds
};

// Moves a playing animation on by `seconds` of wall-clock time, starting the clip over when it passes its end;
// keeps the clip index and the time within the clip's range. A clip of no length stays at its start.
void advanceAnimation(AnimationControls& controls, const SceneAnimation& animation, double seconds);

// Plays `clip` (kept within the animation's clips) from its start; the controls stay as they are for an animation
// without clips.
void selectClip(AnimationControls& controls, const SceneAnimation& animation, int clip);
// Pauses at `time`, kept within the clip's range: what dragging the panel's time slider does.
void seekAnimation(AnimationControls& controls, const SceneAnimation& animation, float time);

}  // namespace candela
