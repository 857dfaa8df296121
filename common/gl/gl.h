// common/gl/gl.h — the one way to include OpenGL and GLU in gllab.
// GL_GLEXT_PROTOTYPES must come before the first GL header so that
// glGenBuffers, glWindowPos2i and friends are declared (docs/platform.md).
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>
