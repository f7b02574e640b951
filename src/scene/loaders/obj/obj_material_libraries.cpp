#include "scene/loaders/obj/obj_material_libraries.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "io/file_bytes.h"

namespace candela {

namespace fs = std::filesystem;

namespace {

// The names after "mtllib": separated by spaces, a '\' taking the next character as it is.
std::vector<std::string> libraryNames(std::string_view text) {
  std::vector<std::string> names;
  std::string name;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '\\' && i + 1 < text.size()) {
      name += text[++i];
    } else if (c == ' ' || c == '\t') {
      if (!name.empty()) names.push_back(std::move(name));
      name.clear();
    } else {
      name += c;
    }
  }
  if (!name.empty()) names.push_back(std::move(name));
  return names;
}

// tinyobjloader's messages, one line each, repeated ones counted.
void forwardMessages(const std::string& file, const std::string& text, LoadWarnings& warnings) {
  std::map<std::string, size_t> counts;
  std::vector<std::string> order;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    while (!line.empty() && (line.back() == '.' || line.back() == ' ' || line.back() == '\r')) line.pop_back();
    if (line.empty()) continue;
    if (counts[line]++ == 0) order.push_back(line);
  }
  for (const std::string& l : order)
    warnings.add(file, counts[l] > 1 ? l + " (" + std::to_string(counts[l]) + " times)" : l);
}

}  // namespace

const MtlLibraryCache::Library& MtlLibraryCache::get(const std::string& path, LoadWarnings& warnings) {
  std::unique_ptr<Library>& library = libraries_[path];
  if (library) return *library;
  library = std::make_unique<Library>();
  std::vector<uint8_t> bytes;
  try {
    bytes = readFileBytes(path);
  } catch (const LoadError& e) {
    std::error_code ec;
    library->failure = fs::exists(path, ec) ? std::string("cannot be read (") + e.what() + ")" : "not found";
    return *library;
  }
  // A UTF-8 byte order mark would hide the first statement from tinyobjloader.
  const size_t start = bytes.size() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF ? 3 : 0;
  std::istringstream in(std::string(bytes.begin() + std::ptrdiff_t(start), bytes.end()));
  std::map<std::string, int> index;
  std::string mtlWarnings, mtlErrors;
  tinyobj::LoadMtl(&index, &library->materials, &in, &mtlWarnings, &mtlErrors);
  forwardMessages(path, mtlWarnings + mtlErrors, warnings);
  return *library;
}

ObjMaterialLibraries::ObjMaterialLibraries(std::string objFile, std::optional<PathRule> files, MtlLibraryCache& cache,
                                           LoadWarnings& warnings)
    : objFile_(std::move(objFile)), rule_(std::move(files)), cache_(cache), warnings_(warnings) {}

void ObjMaterialLibraries::loadLibraries(size_t line, std::string_view text) {
  if (!rule_) return;
  std::vector<std::string> names = libraryNames(text);
  if (names.empty()) warnings_.add(objFile_ + ":" + std::to_string(line), "'mtllib' names no file");
  for (const std::string& name : names) load(line, name);
}

void ObjMaterialLibraries::load(size_t line, const std::string& name) {
  const std::string where = objFile_ + ":" + std::to_string(line);
  ResolvedPath path = resolveModelPath(rule_->folder, name, *rule_);
  if (std::find(files_.begin(), files_.end(), path.path) != files_.end()) return;
  if (!path.allowed()) {
    warnings_.add(where, "material library '" + name + "' " + path.refusal + "; its materials are replaced by grey");
    return;
  }
  files_.push_back(path.path);
  const MtlLibraryCache::Library& library = cache_.get(path.path, warnings_);
  if (!library.failure.empty()) {
    warnings_.add(where, "material library '" + name + "' " + library.failure + "; its materials are replaced by grey");
    return;
  }
  // As tinyobjloader merges libraries: a name already known keeps its first material.
  for (const tinyobj::material_t& m : library.materials) {
    index_.try_emplace(m.name, int(materials_.size()));
    materials_.push_back(m);
  }
  sources_.resize(materials_.size(), path.path);
}

uint32_t ObjMaterialLibraries::find(size_t line, std::string_view name) {
  auto it = index_.find(std::string(name));
  if (it != index_.end()) return uint32_t(it->second);
  Unknown& u = unknown_[std::string(name)];
  if (u.uses++ == 0) u.firstLine = line;
  return kObjNoMaterial;
}

void ObjMaterialLibraries::reportUnknownNames() {
  std::vector<std::pair<std::string, Unknown>> byLine(unknown_.begin(), unknown_.end());
  std::sort(byLine.begin(), byLine.end(),
            [](const auto& a, const auto& b) { return a.second.firstLine < b.second.firstLine; });
  for (const auto& [name, u] : byLine)
    warnings_.add(objFile_ + ":" + std::to_string(u.firstLine),
                  "material '" + name + "' is in no material library; its faces are grey" +
                      (u.uses > 1 ? " (" + std::to_string(u.uses) + " times)" : std::string()));
}

}  // namespace candela
