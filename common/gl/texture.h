// common/gl/texture.h — textures made in code, for labs whose lesson is what
// uses a texture (gluQuadricTexture in lab 07), not how one is made.
#pragma once

#include "gl/gl.h"

namespace gllab {

/// A size x size RGB checker of squares `square` texels wide, `light` in the
/// square at texel (0, 0) and `dark` in its neighbours, as a new texture name
/// (glGenTextures; the caller deletes it). GL_NEAREST filters, the default
/// GL_REPEAT wrap, one level, unpacked with alignment 1; binds texture 0
/// again when done.
GLuint make_checker_texture(int size, int square, const GLubyte light[3], const GLubyte dark[3]);

}  // namespace gllab
