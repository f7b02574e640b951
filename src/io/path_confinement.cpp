#include "io/path_confinement.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace candela {

namespace fs = std::filesystem;

namespace {

// The path with every symbolic link of its existing part followed; the part that does not exist is kept.
fs::path withLinksFollowed(const fs::path& path) {
  std::error_code ec;
  fs::path real = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path, ec).lexically_normal() : real;
}

bool isInside(const fs::path& path, const fs::path& folder) {
  fs::path relative = path.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != "..";
}

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = char(std::tolower(static_cast<unsigned char>(c)));
  return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

}  // namespace

PathRule PathRule::forFile(const std::string& file, OutsidePaths outside) {
  std::string folder = fs::path(file).parent_path().string();
  return {folder.empty() ? "." : folder, outside};
}

ResolvedPath confineModelPath(const std::string& path, const PathRule& rule) {
  ResolvedPath resolved{fs::path(path).lexically_normal().string(), {}};
  if (rule.outside == OutsidePaths::Allowed) return resolved;
  const fs::path target = withLinksFollowed(path), folder = withLinksFollowed(rule.folder);
  if (!isInside(target, folder))
    resolved.refusal = "leads to " + target.string() + ", outside the folder " + folder.string() +
                       " of the file that names it (--allow-outside-paths allows it)";
  return resolved;
}

std::string joinModelPath(const std::string& baseFolder, const std::string& reference) {
  std::string file = reference;
  std::replace(file.begin(), file.end(), '\\', '/');
  fs::path p(file);
  return (p.is_absolute() ? p : fs::path(baseFolder) / p).lexically_normal().string();
}

ResolvedPath resolveModelPath(const std::string& baseFolder, const std::string& reference, const PathRule& rule) {
  if (reference.find('\0') != std::string::npos) return {reference, "names a file with a NUL byte in it"};
  if (reference.empty()) return {reference, "names no file"};
  return confineModelPath(joinModelPath(baseFolder, reference), rule);
}

std::optional<std::string> uriToPath(const std::string& uri) {
  // RFC 3986: a scheme is a letter, then letters, digits, '+', '-' or '.', then ':'.
  size_t colon = uri.find(':');
  if (colon != std::string::npos && colon > 0 && std::isalpha(static_cast<unsigned char>(uri[0])) &&
      std::all_of(uri.begin(), uri.begin() + std::ptrdiff_t(colon), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
      }))
    return std::nullopt;
  std::string path;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      path += uri[i];
      continue;
    }
    if (i + 2 >= uri.size()) return std::nullopt;
    int high = hexValue(uri[i + 1]), low = hexValue(uri[i + 2]);
    if (high < 0 || low < 0 || (high == 0 && low == 0)) return std::nullopt;
    path += char(high * 16 + low);
    i += 2;
  }
  return path;
}

}  // namespace candela
