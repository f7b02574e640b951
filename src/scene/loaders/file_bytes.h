#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace candela {

// The whole content of a file; throws LoadError naming the file when it cannot be read.
std::vector<uint8_t> readFileBytes(const std::string& path);

}  // namespace candela
