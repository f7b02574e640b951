#pragma once
#include <string>

namespace candela {

// "90", "90s", "1.5m", "2h" as seconds; throws std::invalid_argument naming the text when it is not a positive
// duration.
double parseDuration(const std::string& text);

}  // namespace candela
