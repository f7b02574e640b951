#include "backends/optix/program_cache_directory.h"

#include <cstdlib>
#include <filesystem>

namespace candela::optix {

namespace {

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

}  // namespace

std::string defaultProgramCacheDirectory() {
  namespace fs = std::filesystem;
  if (std::string own = environment("CANDELA_OPTIX_CACHE"); !own.empty()) return own;
  if (std::string xdg = environment("XDG_CACHE_HOME"); fs::path(xdg).is_absolute())
    return (fs::path(xdg) / "candela" / "optix").string();
  if (std::string home = environment("HOME"); !home.empty())
    return (fs::path(home) / ".cache" / "candela" / "optix").string();
  return {};
}

}  // namespace candela::optix
