#pragma once
// The bytes of a .glb: `gltf` as its JSON chunk and `bin` as its BIN chunk, each padded to 4 bytes.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace candela::test {

inline std::vector<uint8_t> glbFile(const nlohmann::json& gltf, std::vector<uint8_t> bin) {
  std::string text = gltf.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');
  bin.resize((bin.size() + 3) / 4 * 4, 0);
  std::vector<uint8_t> out;
  auto word = [&](uint32_t v) {
    out.insert(out.end(), reinterpret_cast<uint8_t*>(&v), reinterpret_cast<uint8_t*>(&v) + 4);
  };
  word(0x46546C67);  // "glTF"
  word(2);
  word(uint32_t(28 + text.size() + bin.size()));
  word(uint32_t(text.size()));
  word(0x4E4F534A);  // "JSON"
  out.insert(out.end(), text.begin(), text.end());
  word(uint32_t(bin.size()));
  word(0x004E4942);  // "BIN\0"
  out.insert(out.end(), bin.begin(), bin.end());
  return out;
}

}  // namespace candela::test
