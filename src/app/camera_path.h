#pragma once
// Camera paths for image sequences (`candela render --camera-path FILE`, `--camera-orbit FRAMES`).
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace candela {

// The most frames a path may have, and the largest camera-path file read.
constexpr size_t kMaxCameraPathFrames = 100000;
constexpr size_t kMaxCameraPathBytes = size_t(16) << 20;

// Reads a camera path: a text file with one frame per line,
//   eye_x eye_y eye_z  target_x target_y target_z  [vertical_fov_degrees]
// numbers separated by spaces or tabs; blank lines and lines starting with '#' are skipped. Each frame takes the
// rest (up vector, aperture, and the field of view where the line gives none) from `base`, the scene's camera.
// Throws std::runtime_error naming the file and line: unreadable, too large, a line that is not 6 or 7 finite
// numbers, an eye as far as kMaxCameraRayOrigin or on its target, a field of view outside (0, 180), no frame.
std::vector<CameraDescription> readCameraPath(const std::string& path, const CameraDescription& base);

// `frames` cameras on an arc of `degrees` around the base camera's target, about its up axis, starting at the base
// camera's eye (at its height and distance), evenly spaced (a full circle: a turntable that does not repeat its
// first frame). Throws std::invalid_argument for 0 frames, more than kMaxCameraPathFrames, or degrees that are not
// finite.
std::vector<CameraDescription> orbitCameraPath(const CameraDescription& base, uint32_t frames, float degrees = 360.0f);

// The file name of frame `index` of a sequence written to `output`: its number, zero-padded to four digits or to
// the digits `frameCount - 1` needs, before the extension ("out.png" -> "out.0007.png").
std::string frameFileName(const std::string& output, size_t index, size_t frameCount);

}  // namespace candela
