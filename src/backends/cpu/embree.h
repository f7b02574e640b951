#pragma once
// Embree 3 and 4 differ in header path and in how ray queries take their context.
#if CANDELA_EMBREE_VERSION >= 4
#include <embree4/rtcore.h>
#else
#include <embree3/rtcore.h>
#endif
