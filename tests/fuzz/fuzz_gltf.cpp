// libFuzzer entry point for the glTF loader (.gltf text or .glb bytes, no external files) and the scene repair,
// then the animation player at times away from the rest pose (posed_clips.h).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "posed_clips.h"
#include "scene/loaders/gltf/gltf_loader.h"
#include "scene/scene_repair.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  candela::LoadWarnings warnings;
  try {
    candela::Scene scene = candela::loadGltfBytes("fuzz.gltf", data, size, warnings);
    candela::repairScene(scene, "fuzz.gltf", warnings);  // ends with validateScene
    candela::fuzz::poseClips(scene);
  } catch (const candela::LoadError& e) {
    // Messages quote the input: they must reach a terminal as one printable line (load_diagnostics.h).
    if (candela::printableText(e.what()) != e.what()) std::abort();
  }
  for (const std::string& w : warnings.messages)
    if (candela::printableText(w) != w) std::abort();
  return 0;
}
