#pragma once
#include <string>

#include "io/load_diagnostics.h"
#include "scene/scene.h"

// pbrt scene text loaded as a file named test.pbrt, as the pbrt loader's tests read it.
namespace candela::test::pbrt {

// The scene of `text`; its warnings are copied to `warnings` when given. Throws what the loader throws.
Scene loadText(const std::string& text, LoadWarnings* warnings = nullptr);

// The message of the LoadError that loading `text` throws, or "(no error)".
std::string loadError(const std::string& text);

}  // namespace candela::test::pbrt
