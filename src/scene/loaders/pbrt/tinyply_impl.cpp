// The implementation of the vendored tinyply (third_party/tinyply), compiled once without our warning flags.
#define TINYPLY_IMPLEMENTATION
#include "tinyply.h"
