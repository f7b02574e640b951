#include "candela/candela.h"

namespace candela::api {

const char* version() { return CANDELA_VERSION; }

}  // namespace candela::api
