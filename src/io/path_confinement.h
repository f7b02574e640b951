#pragma once
#include <optional>
#include <string>

namespace candela {

// Whether the files a model or scene file refers to (material libraries, textures, glTF buffers and images, a
// scene file's models and environment map) may lie outside its folder. They may not unless the user says so
// (--allow-outside-paths): a model downloaded from anywhere must not read /etc/passwd or ~/.ssh as a "texture".
enum class OutsidePaths { Refused, Allowed };

// Where references must stay: the folder of the model (or scene file) that makes them.
struct PathRule {
  std::string folder;
  OutsidePaths outside = OutsidePaths::Refused;

  static PathRule forFile(const std::string& file, OutsidePaths outside);  // the folder `file` is in
};

// A reference resolved: where it leads, and why it may not be read when it may not.
struct ResolvedPath {
  std::string path;     // the reference joined to its base folder, lexically normal (also when refused)
  std::string refusal;  // empty when the file may be read
  bool allowed() const { return refusal.empty(); }
};

// `reference` as a model writes it ('\' taken for '/') joined to `baseFolder` unless absolute, lexically normal.
std::string joinModelPath(const std::string& baseFolder, const std::string& reference);

// `reference` as a model writes it ('\' taken for '/'), relative to `baseFolder` unless absolute, checked
// against `rule`: with symbolic links followed (those of the model's folder too), it must lead inside
// rule.folder. The refusal says where it leads and how to allow it.
ResolvedPath resolveModelPath(const std::string& baseFolder, const std::string& reference, const PathRule& rule);

// The same for a path that is already joined to its base folder.
ResolvedPath confineModelPath(const std::string& path, const PathRule& rule);

// The file path a URI reference of a glTF file stands for: percent-encoding decoded as RFC 3986 says ('+' stays
// '+'). Nothing when it is no relative path: a scheme ("file:", "http:"), a malformed %-escape, or an encoded
// NUL byte, which would cut the path short.
std::optional<std::string> uriToPath(const std::string& uri);

}  // namespace candela
