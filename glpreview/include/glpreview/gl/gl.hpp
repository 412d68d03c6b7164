// OpenGL 4.5 core declarations. Functions come from libglvnd's libOpenGL (the vendor-neutral GL dispatch library),
// which forwards them to whatever driver made the current EGL context (Mesa llvmpipe, or a GPU driver).
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
