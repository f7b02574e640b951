// libFuzzer entry point for NanoVDB files as pbrt-v4's `nanovdb` medium reads them: the input is written as
// smoke.nvdb into a private folder beside a fixed scene that names it, which is loaded (the file's grid
// descriptions, the density grid's tree resampled into a dense grid, its majorant grid) and repaired. Any bytes
// must load or throw LoadError as one printable line, never crash, hang or allocate more than the file can hold.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "private_folder.h"
#include "scene/loaders/pbrt/pbrt_loader.h"
#include "scene/scene_repair.h"

namespace {

constexpr const char* kScene =
    "Camera \"perspective\"\nWorldBegin\n"
    "MakeNamedMedium \"smoke\" \"string type\" \"nanovdb\" \"string filename\" \"smoke.nvdb\"\n"
    "AttributeBegin\nMaterial \"interface\"\nMediumInterface \"smoke\" \"\"\nShape \"sphere\"\nAttributeEnd\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string scene = candela::fuzz::writePrivateFile("scene.pbrt", kScene);
  candela::fuzz::writePrivateFile("smoke.nvdb", std::string_view(reinterpret_cast<const char*>(data), size));
  candela::LoadWarnings warnings;
  try {
    candela::Scene loaded = candela::loadPbrt(scene, warnings);
    candela::repairScene(loaded, scene, warnings);  // ends with validateScene
  } catch (const candela::LoadError& e) {
    // Messages quote the file's grid names: they must reach a terminal as one printable line.
    if (candela::printableText(e.what()) != e.what()) std::abort();
  }
  for (const std::string& w : warnings.messages)
    if (candela::printableText(w) != w) std::abort();
  return 0;
}
