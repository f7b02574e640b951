#pragma once
// Where OptiX keeps the programs it compiled for the GPU, so that only a machine's first start compiles them.
#include <string>

namespace candela::optix {

// $CANDELA_OPTIX_CACHE, else $XDG_CACHE_HOME/candela/optix (an absolute $XDG_CACHE_HOME only, as the XDG base
// directory specification says), else $HOME/.cache/candela/optix; empty when none of them is set. OptiX's own
// OPTIX_CACHE_PATH, where set, overrides it (OptixContext::cacheDirectory() says which is used).
std::string defaultProgramCacheDirectory();

}  // namespace candela::optix
