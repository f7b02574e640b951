#pragma once
#include "app/render_job.h"
#include "io/images/image_io.h"
#include "scene/scene.h"

namespace candela {

// What makes a render's samples what they are, as named text values: the scene and the files it takes, the
// camera, size, path depth, seed, sampler, material overrides, texture limits and whether the film has AOV sums.
// Two renders with the same identity draw the same samples at the same sample indices, so a checkpoint of one
// continues as the other. `job` holds the settings as rendered (the scene's render hints applied). The sample
// count, backend, denoiser and outputs are not part of it: they may change between a render and its resumption.
ExrAttributes renderIdentity(const RenderJob& job, bool withAovs);

// What the processes of a team compare before they render together (RenderTeam::checkSameRender): the render
// identity with the scene's files (Scene::inputFiles) and the --env map named by a hash of their contents rather
// than by their paths, so that processes that read the same files under other paths (other nodes, other working
// folders) agree, and processes that read other files under the same name do not. A built-in scene is its name.
ExrAttributes teamIdentity(const RenderJob& job, const Scene& scene, bool withAovs);

}  // namespace candela
