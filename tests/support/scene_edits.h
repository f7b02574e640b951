#pragma once
// Checks of Backend::setMaterials, setEnvironment and setInstanceTransforms that any backend must pass: renders after
// an edit equal, bit for bit, renders of a fresh backend given the edited scene with setScene. With the same seed both
// draw the same random numbers, so they trace the same paths; any sample of the old scene left in the film, or
// any array that missed the edit, changes the image.
#include <functional>
#include <memory>

#include "backends/backend.h"

namespace candela::test {

using BackendFactory = std::function<std::unique_ptr<Backend>()>;

// Expects two images equal bit for bit.
void expectSameImage(const Image& a, const Image& b);

// The material edit of these checks: `scene` with every material re-shaded with the PBR model at roughness 0.2.
Scene withMaterialEdit(Scene scene);

// The material gallery edited by withMaterialEdit.
void expectMaterialEditMatchesRebuild(const BackendFactory& makeBackend);

// The material gallery's uniform sky replaced by a small map, scaled and turned.
void expectEnvironmentEditMatchesRebuild(const BackendFactory& makeBackend);

// The Cornell box with every instance moved and turned a little, its light included (the light table follows).
void expectInstanceTransformEditMatchesRebuild(const BackendFactory& makeBackend);

}  // namespace candela::test
