#include "support/pbrt_text.h"

#include "scene/loaders/pbrt/pbrt_loader.h"

namespace candela::test::pbrt {

Scene loadText(const std::string& text, LoadWarnings* warningsOut) {
  LoadWarnings warnings;
  Scene scene = loadPbrtText("test.pbrt", text, warnings);
  if (warningsOut) *warningsOut = warnings;
  return scene;
}

std::string loadError(const std::string& text) {
  try {
    loadText(text);
  } catch (const LoadError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace candela::test::pbrt
