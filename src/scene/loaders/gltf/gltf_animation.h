#pragma once
#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "io/load_diagnostics.h"
#include "scene/animation.h"
#include "scene/loaders/gltf/gltf_accessors.h"

namespace candela {

// The number of morph targets of the mesh of node `node` (that of its first primitive; glTF asks all to have as
// many), 0 where it has none.
uint32_t morphTargetCount(const tinygltf::Model& model, int node);

// Per node of the file: whether a channel of one of its animations moves it (translation, rotation or scale).
std::vector<bool> animatedGltfNodes(const tinygltf::Model& model);

// The file's animations as clips, one per `animations` entry and in that order. `animationNodes` maps a file's
// node to its entry in SceneAnimation::nodes (-1 for nodes outside the scene, whose channels are left out).
// Channels of morph target weights carry as many weights per key as the node's mesh has morph targets (those of
// a node without morph targets are left out with one warning); channels of paths glTF does not define are left
// out with one warning. Key times that are not finite or do not increase, key values that are not finite, a count of
// values that does not match the key times, and an unknown interpolation throw LoadError naming the file and
// the JSON path.
std::vector<AnimationClip> readGltfAnimations(const tinygltf::Model& model, const GltfAccessorReader& accessors,
                                              const std::vector<int32_t>& animationNodes, const std::string& file,
                                              LoadWarnings& warnings);

}  // namespace candela
