#include "scene/loaders/gltf/gltf_buffer_charge.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <string_view>
#include <vector>

#include "io/load_budget.h"

namespace candela {

namespace {

using nlohmann::json;

struct BufferClaim {
  uint64_t byteLength = 0;
  uint64_t dataUriBytes = 0;  // the length of a data: URI's text
};

// A SAX reader that keeps, per object of the root's "buffers" array, its byteLength and the length of a data:
// URI, and builds nothing else (a .gltf's data URIs may be most of the file).
class BufferClaimCollector {
 public:
  explicit BufferClaimCollector(std::vector<BufferClaim>& claims) : claims_(claims) {}

  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool number_integer(json::number_integer_t) { return true; }
  bool number_unsigned(json::number_unsigned_t value) {
    if (inBufferMember("byteLength")) claims_.back().byteLength = value;
    return true;
  }
  bool number_float(json::number_float_t, const std::string&) { return true; }
  bool binary(json::binary_t&) { return true; }
  bool string(std::string& value) {
    if (inBufferMember("uri") && value.compare(0, 5, "data:") == 0) claims_.back().dataUriBytes = value.size();
    return true;
  }
  bool start_object(std::size_t) {
    if (levels_.size() == 2 && levels_[0].key == "buffers" && levels_[1].isArray) claims_.emplace_back();
    return open(false);
  }
  bool start_array(std::size_t) { return open(true); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(std::string& name) {
    levels_.back().key = levels_.size() <= 3 ? name : std::string();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const json::exception&) { return false; }

 private:
  struct Level {
    bool isArray;
    std::string key;  // of the member being read, in an object of the first three levels
  };
  // Whether the value being read is `member` of an object of the root's "buffers" array.
  bool inBufferMember(const char* member) const {
    return levels_.size() == 3 && levels_[0].key == "buffers" && levels_[1].isArray && levels_[2].key == member;
  }
  bool open(bool isArray) {
    levels_.push_back({isArray, {}});
    return true;
  }
  bool close() {
    levels_.pop_back();
    return true;
  }

  std::vector<BufferClaim>& claims_;
  std::vector<Level> levels_;
};

// The JSON text of a .gltf, or of a .glb's JSON chunk.
std::string_view jsonText(const uint8_t* data, size_t size) {
  if (size < 4 || std::memcmp(data, "glTF", 4) != 0) return {reinterpret_cast<const char*>(data), size};
  if (size < 20) return {};
  uint32_t length;
  std::memcpy(&length, data + 12, 4);
  return {reinterpret_cast<const char*>(data + 20), std::min<size_t>(length, size - 20)};
}

}  // namespace

GltfBufferCharge::GltfBufferCharge(const uint8_t* data, size_t size, const std::string& file) {
  std::vector<BufferClaim> claims;
  BufferClaimCollector collector(claims);
  if (!json::sax_parse(jsonText(data, size), &collector)) return;
  for (size_t i = 0; i < claims.size(); ++i) {
    const BufferClaim& claim = claims[i];
    // A data: URI's text is copied and decoded (three bytes for every four) before tinygltf checks the length.
    const uint64_t bytes = claim.byteLength + claim.dataUriBytes + claim.dataUriBytes / 4 * 3;
    chargeLoadMemory(bytes, file, "buffers[" + std::to_string(i) + "]" + (claim.dataUriBytes ? " (a data: URI)" : ""));
    charged_ += bytes;
  }
}

GltfBufferCharge::~GltfBufferCharge() { releaseLoadMemory(charged_); }

}  // namespace candela
