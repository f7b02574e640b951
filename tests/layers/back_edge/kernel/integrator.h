#pragma once
// A kernel header that reaches up into the app layer: the layer check must refuse it.
#include "app/render_job.h"
