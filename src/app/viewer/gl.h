#pragma once
// OpenGL 3.3 core entry points. On Linux the GL vendor-neutral dispatch library exports every core function,
// so no loader is needed; GLFW is told to include no GL header of its own.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
