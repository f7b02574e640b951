#include "app/checkpoint/duration.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace candela {

double parseDuration(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  const std::string unit = text.substr(size_t(end - text.c_str()));
  double scale = 0.0;
  if (unit.empty() || unit == "s")
    scale = 1.0;
  else if (unit == "m")
    scale = 60.0;
  else if (unit == "h")
    scale = 3600.0;
  const double seconds = value * scale;
  if (end == text.c_str() || scale == 0.0 || !std::isfinite(seconds) || seconds <= 0.0 || seconds > 1e9)
    throw std::invalid_argument("'" + text + "' is not a duration (like 90s, 10m or 2h)");
  return seconds;
}

}  // namespace candela
