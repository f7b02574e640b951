#pragma once
#include <functional>
#include <optional>
#include <string>

#include "scene/loaders/pbrt/pbrt_parameters.h"
#include "scene/scene.h"

namespace candela {

// What shape translation needs from the loader: where a PLY file named by a shape is (confined and recorded as
// an input), and a way to warn once per feature.
struct PbrtShapeInputs {
  std::function<std::string(const std::string& reference)> resolveFile;  // throws LoadError when refused
  std::function<void(const std::string& feature, const std::string& what)> warn;
};

// The triangles of a pbrt shape in its object space: trianglemesh, plymesh, bilinearmesh, loopsubdiv, and the
// quadrics (sphere, disk, cylinder) tessellated. Texture coordinates are pbrt's (v runs up the image). Triangles
// are wound so that, without ReverseOrientation, their front faces the side pbrt's surface normal points to.
// Nothing (after a warning) for shapes candela does not draw (curves, hair, ...). Malformed parameters throw
// LoadError naming params.file and params.line.
std::optional<Mesh> makePbrtShape(const std::string& type, const PbrtParameters& params, const PbrtShapeInputs& inputs);

// Flips the triangles whose winding disagrees with the mean of their vertex normals.
void windTrianglesAlongNormals(Mesh& mesh);

}  // namespace candela
