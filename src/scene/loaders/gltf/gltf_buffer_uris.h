#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

// The URIs of a glTF file's buffers as the file writes them. tinygltf hands a buffer's URI to its file callbacks
// only after decoding it its own way (dlib's urldecode: '+' becomes a space, a malformed escape a NUL byte);
// this finds the URI again, so that it can be decoded as RFC 3986 says (path_confinement.h, uriToPath).
class GltfBufferUris {
 public:
  // Collects buffers[*].uri of the JSON text; invalid JSON gives none (tinygltf reports it).
  explicit GltfBufferUris(std::string_view json);

  // The file path of the buffer URI that tinygltf decoded to `decoded`; nothing when no URI decodes to it, when
  // URIs that name different files do (a+b and a%20b), or when the URI names no file.
  std::optional<std::string> pathFor(const std::string& decoded) const;

 private:
  std::vector<std::string> uris_;
};

}  // namespace candela
