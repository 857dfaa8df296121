// common/harness/offscreen.h — a GL context without a display.
//
// The one implementation today is OSMesa (offscreen_osmesa.cpp), the
// reference renderer. OSMesa was removed from Mesa 25.1; its successor, EGL
// surfaceless, fits behind this same interface (docs/platform.md,
// "After OSMesa: EGL surfaceless", has what a port needs, measured).
#pragma once

#include <memory>
#include <string>

#include "image/image.h"

namespace gllab {

class OffscreenContext {
 public:
  /// Creates a compatibility-profile context with RGBA8 colour, a 24-bit
  /// depth buffer and an 8-bit stencil buffer, makes it current and checks that GL answers. Throws
  /// std::runtime_error with one line saying what failed.
  OffscreenContext(int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  /// The frame as a top-down image (glReadPixels rows are bottom-up).
  Image read_pixels() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gllab
