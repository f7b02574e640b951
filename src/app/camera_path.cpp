#include "app/camera_path.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "kernel/camera.h"

namespace candela {

namespace {

bool parseFloat(const std::string& token, float& value) {
  char* end = nullptr;
  const double v = std::strtod(token.c_str(), &end);
  if (token.empty() || end != token.c_str() + token.size() || !std::isfinite(v) || std::fabs(v) > 3e38) return false;
  value = float(v);
  return true;
}

bool withinRayOrigin(Vec3 p) {
  return std::fabs(p.x) < kMaxCameraRayOrigin && std::fabs(p.y) < kMaxCameraRayOrigin &&
         std::fabs(p.z) < kMaxCameraRayOrigin;
}

}  // namespace

std::vector<CameraDescription> readCameraPath(const std::string& path, const CameraDescription& base) {
  std::error_code error;
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (error) throw std::runtime_error("cannot read camera path '" + path + "': " + error.message());
  if (size > kMaxCameraPathBytes)
    throw std::runtime_error("camera path '" + path + "' is larger than " + std::to_string(kMaxCameraPathBytes >> 20) +
                             " MiB");
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read camera path '" + path + "'");
  std::vector<CameraDescription> frames;
  std::string line;
  for (size_t number = 1; std::getline(in, line); ++number) {
    const std::string where = path + ":" + std::to_string(number) + ": ";
    std::istringstream tokens(line);
    std::vector<float> values;
    std::string token;
    bool comment = false;
    while (tokens >> token) {
      if (values.empty() && token[0] == '#') {
        comment = true;
        break;
      }
      float v;
      if (values.size() == 7 || !parseFloat(token, v))
        throw std::runtime_error(where + "expected 'eye_x eye_y eye_z target_x target_y target_z [fov_degrees]', " +
                                 "6 or 7 finite numbers");
      values.push_back(v);
    }
    if (comment || values.empty()) continue;
    if (values.size() < 6)
      throw std::runtime_error(where + "expected 'eye_x eye_y eye_z target_x target_y target_z [fov_degrees]'");
    CameraDescription frame = base;
    frame.eye = {values[0], values[1], values[2]};
    frame.target = {values[3], values[4], values[5]};
    if (values.size() == 7) frame.verticalFovDegrees = values[6];
    if (!withinRayOrigin(frame.eye) || !withinRayOrigin(frame.target))
      throw std::runtime_error(where + "eye and target must lie within +-1e18");
    if (!(length(frame.target - frame.eye) > 0.0f) || !std::isfinite(length(frame.target - frame.eye)))
      throw std::runtime_error(where + "the eye lies on its target");
    if (!(frame.verticalFovDegrees > 0.0f && frame.verticalFovDegrees < 180.0f))
      throw std::runtime_error(where + "the field of view must lie in (0, 180) degrees");
    if (frames.size() == kMaxCameraPathFrames)
      throw std::runtime_error(where + "more than " + std::to_string(kMaxCameraPathFrames) + " frames");
    frames.push_back(frame);
  }
  if (frames.empty()) throw std::runtime_error("camera path '" + path + "' has no frame");
  return frames;
}

std::vector<CameraDescription> orbitCameraPath(const CameraDescription& base, uint32_t frames, float degrees) {
  if (frames == 0 || frames > kMaxCameraPathFrames)
    throw std::invalid_argument("an orbit needs 1 to " + std::to_string(kMaxCameraPathFrames) + " frames");
  if (!std::isfinite(degrees)) throw std::invalid_argument("an orbit's arc must be finite");
  const bool circle = std::fabs(degrees) >= 360.0f;
  const float step = degrees * kPi / 180.0f / float(circle || frames == 1 ? frames : frames - 1);
  const Vec3 up = normalize(base.up), offset = base.eye - base.target;
  const Vec3 along = up * dot(offset, up), radial = offset - along;
  const Vec3 side = cross(up, radial);  // the radial vector turned a quarter about the up axis
  std::vector<CameraDescription> path;
  for (uint32_t i = 0; i < frames; ++i) {
    const float angle = step * float(i);
    CameraDescription frame = base;
    frame.eye = base.target + along + radial * std::cos(angle) + side * std::sin(angle);
    path.push_back(frame);
  }
  return path;
}

std::string frameFileName(const std::string& output, size_t index, size_t frameCount) {
  const std::filesystem::path p(output);
  size_t digits = 4;
  for (size_t last = frameCount > 0 ? frameCount - 1 : 0, d = 1; last >= 10; last /= 10) digits = std::max(digits, ++d);
  std::string number = std::to_string(index);
  if (number.size() < digits) number.insert(0, digits - number.size(), '0');
  std::filesystem::path name = p;
  name.replace_filename(p.stem().string() + "." + number + p.extension().string());
  return name.string();
}

}  // namespace candela
