// common/gl/check.cpp
#include "gl/check.h"

#include <cstdio>

#include "harness/lab.h"

namespace gllab {

std::string gl_error_name(GLenum code) {
  switch (code) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    default: {
      char hex[16];
      std::snprintf(hex, sizeof hex, "0x%04X", code);
      return hex;
    }
  }
}

int check_gl_errors(const std::string& where) {
  int count = 0;
  // glGetError returns one recorded error per call; a lost context could make
  // it return errors forever, so stop after a bounded number.
  for (GLenum code = glGetError(); code != GL_NO_ERROR && count < 32; code = glGetError()) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", code);
    report_frame_error("GL error " + gl_error_name(code) + " (" + hex + ") " + where);
    ++count;
  }
  return count;
}

}  // namespace gllab
