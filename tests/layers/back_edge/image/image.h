#pragma once
// A downward include: allowed.
#include "kernel/integrator.h"
