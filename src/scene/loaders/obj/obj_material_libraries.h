#pragma once
#include <tiny_obj_loader.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/load_diagnostics.h"
#include "io/path_confinement.h"
#include "scene/loaders/obj/obj_geometry_reader.h"

namespace candela {

// Material libraries parsed once per load and shared by every OBJ file of it that names them, by resolved path.
// A library's own warnings are given when it is parsed, not again for each file that uses it.
class MtlLibraryCache {
 public:
  struct Library {
    std::string failure;                         // why it could not be read ("not found", ...); empty when it was
    std::vector<tinyobj::material_t> materials;  // in file order; the first of two equal names is the one used
  };
  const Library& get(const std::string& path, LoadWarnings& warnings);

 private:
  std::map<std::string, std::unique_ptr<Library>> libraries_;
};

// The material libraries an OBJ file names, parsed by tinyobjloader's MTL reader, and the lookups of the file's
// "usemtl" statements. Every library of an "mtllib" statement is read, relative to the OBJ file's directory (a
// '\' escapes a space in a name); a missing one is a warning, and so is one that `files` does not allow
// (outside the OBJ file's folder), and a material name found in none.
class ObjMaterialLibraries : public ObjMaterialResolver {
 public:
  // Without `files` (text that is not a file) "mtllib" statements are ignored. Libraries come from `cache`,
  // which may be shared with the other models of a load.
  ObjMaterialLibraries(std::string objFile, std::optional<PathRule> files, MtlLibraryCache& cache,
                       LoadWarnings& warnings);

  void loadLibraries(size_t line, std::string_view names) override;
  uint32_t find(size_t line, std::string_view name) override;

  // Warns about the material names that were not found, once per name.
  void reportUnknownNames();

  const std::vector<tinyobj::material_t>& materials() const { return materials_; }
  const std::string& sourceOf(size_t material) const { return sources_[material]; }  // the library it came from
  const std::vector<std::string>& libraryFiles() const { return files_; }            // those read or looked for

 private:
  void load(size_t line, const std::string& name);

  std::string objFile_;
  std::optional<PathRule> rule_;
  MtlLibraryCache& cache_;
  LoadWarnings& warnings_;
  std::vector<tinyobj::material_t> materials_;
  std::map<std::string, int> index_;
  std::vector<std::string> sources_, files_;
  struct Unknown {
    size_t firstLine = 0, uses = 0;
  };
  std::map<std::string, Unknown> unknown_;
};

}  // namespace candela
