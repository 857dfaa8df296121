// common/gl/check.h — GL errors by name.
#pragma once

#include <string>

#include "gl/gl.h"

namespace gllab {

/// "GL_INVALID_ENUM" for GL_INVALID_ENUM, "0x1234" for codes without a name.
std::string gl_error_name(GLenum code);

/// Drains glGetError(). Each error found is passed to report_frame_error()
/// as "GL error GL_INVALID_ENUM (0x0500) <where>". Returns how many there were.
int check_gl_errors(const std::string& where);

}  // namespace gllab
