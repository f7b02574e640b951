#include "scene/loaders/gltf/gltf_buffer_list.h"

#include <nlohmann/json.hpp>

#include "io/path_confinement.h"

namespace candela {

namespace {

using nlohmann::json;

// tinygltf's decoding of a buffer URI (dlib::urldecode in tiny_gltf.h), to recognise what it hands over.
std::string tinygltfDecoded(const std::string& uri) {
  auto hex = [](char c) -> unsigned {
    if (c >= '0' && c <= '9') return unsigned(c - '0');
    if (c >= 'a' && c <= 'f') return unsigned(c - 'a' + 10);
    if (c >= 'A' && c <= 'F') return unsigned(c - 'A' + 10);
    return 0;
  };
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      out += char((hex(uri[i + 1]) << 4) | hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// A SAX reader that keeps, per object of the root's "buffers" array, its byteLength and its uri (only the length
// of a data: URI), and builds nothing else.
class BufferCollector {
 public:
  explicit BufferCollector(std::vector<GltfBufferEntry>& buffers) : buffers_(buffers) {}

  bool null() { return true; }
  bool boolean(bool) { return true; }
  bool number_integer(json::number_integer_t) { return true; }
  bool number_unsigned(json::number_unsigned_t value) {
    if (inBufferMember("byteLength")) buffers_.back().byteLength = value;
    return true;
  }
  bool number_float(json::number_float_t, const std::string&) { return true; }
  bool binary(json::binary_t&) { return true; }
  bool string(std::string& value) {
    if (!inBufferMember("uri")) return true;
    if (value.compare(0, 5, "data:") == 0)
      buffers_.back().dataUriBytes = value.size();
    else
      buffers_.back().uri = std::move(value);
    return true;
  }
  bool start_object(std::size_t) {
    if (levels_.size() == 2 && levels_[0].key == "buffers" && levels_[1].isArray) buffers_.emplace_back();
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

  std::vector<GltfBufferEntry>& buffers_;
  std::vector<Level> levels_;
};

}  // namespace

GltfBufferList::GltfBufferList(std::string_view text) {
  BufferCollector collector(buffers_);
  if (!json::sax_parse(text, &collector)) buffers_.clear();
}

std::optional<std::string> GltfBufferList::pathFor(const std::string& decoded) const {
  std::optional<std::string> found;
  for (const GltfBufferEntry& buffer : buffers_) {
    // (A data: URI is kept as no URI: tinygltf decodes it itself and never asks for it as a file.)
    if (buffer.uri.empty() || tinygltfDecoded(buffer.uri) != decoded) continue;
    std::optional<std::string> path = uriToPath(buffer.uri);
    if (!path || (found && *found != *path)) return std::nullopt;
    found = path;
  }
  return found;
}

}  // namespace candela
