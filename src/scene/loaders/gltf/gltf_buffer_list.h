#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

// One of a glTF file's buffers as its JSON writes it.
struct GltfBufferEntry {
  uint64_t byteLength = 0;
  std::string uri;            // as written; empty where there is none and for a data: URI, whose text is not kept
  uint64_t dataUriBytes = 0;  // the length of a data: URI's text
};

// The buffers of a glTF's JSON, read in one pass before tinygltf parses the file, for what must be known before
// or beside tinygltf: their sizes, charged to the load budget (gltf_buffer_charge.h), and their URIs as written.
// tinygltf hands a buffer's URI to its file callbacks only after decoding it its own way (dlib's urldecode: '+'
// becomes a space, a malformed escape a NUL byte); pathFor finds the URI again, so that it can be decoded as
// RFC 3986 says (path_confinement.h, uriToPath).
class GltfBufferList {
 public:
  // Reads buffers[*].uri and buffers[*].byteLength of the JSON text and builds nothing else (a .gltf's data URIs
  // may be most of the file); invalid JSON gives no buffers (tinygltf reports it).
  explicit GltfBufferList(std::string_view json);

  const std::vector<GltfBufferEntry>& buffers() const { return buffers_; }

  // The file path of the buffer URI that tinygltf decoded to `decoded`; nothing when no URI decodes to it, when
  // URIs that name different files do (a+b and a%20b), or when the URI names no file.
  std::optional<std::string> pathFor(const std::string& decoded) const;

 private:
  std::vector<GltfBufferEntry> buffers_;
};

}  // namespace candela
