// libFuzzer entry point for the OBJ loader and the scene repair: any text must load and be repaired, or throw
// LoadError, never crash or hang.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "scene/loaders/obj/obj_loader.h"
#include "scene/scene_repair.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  candela::LoadWarnings warnings;
  try {
    candela::Scene scene = candela::loadObjText("fuzz.obj", {reinterpret_cast<const char*>(data), size}, warnings);
    candela::repairScene(scene, "fuzz.obj", warnings);  // ends with validateScene
  } catch (const candela::LoadError& e) {
    // Messages quote the input: they must reach a terminal as one printable line (load_diagnostics.h).
    if (candela::printableText(e.what()) != e.what()) std::abort();
  }
  for (const std::string& w : warnings.messages)
    if (candela::printableText(w) != w) std::abort();
  return 0;
}
