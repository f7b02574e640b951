#pragma once
#include <string>
#include <vector>

#include "image/aov_images.h"
#include "io/images/image_io.h"

namespace candela {

enum class Aov { Albedo, Normal, Depth };

const char* aovName(Aov aov);  // "albedo", "normal", "depth"
// A comma-separated list of AOV names, each at most once; throws std::invalid_argument naming a bad entry.
std::vector<Aov> parseAovList(const std::string& list);

// Writes `image` to `path` (see writeImage) together with the chosen AOVs:
// - .exr: one file, the beauty in R, G, B and the AOVs as layers albedo.{R,G,B}, normal.{X,Y,Z} and Z (depth);
// - .pfm: beside it, <stem>.<aov>.pfm in linear floats (depth repeated in all three channels);
// - .png: beside it, <stem>.<aov>.png for viewing: albedo sRGB-encoded, normal as (n + 1) / 2, depth as
//   depth / (largest depth), both stored as is.
// All files are complete before any is renamed over its predecessor (the image last), so a failure leaves every
// previous file as it was. Returns the paths written, the image's first. Throws std::runtime_error naming the
// file that failed.
std::vector<std::string> writeImageWithAovs(const std::string& path, const Image& image, const DisplaySettings& display,
                                            const AovImages& aovs, const std::vector<Aov>& which);

}  // namespace candela
