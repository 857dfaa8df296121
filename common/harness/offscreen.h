// common/harness/offscreen.h — a GL context without a display.
//
// Two implementations; a build links one (CMake's GLLAB_HEADLESS):
//  - EGL surfaceless (offscreen_egl.cpp), the default: it links through GLVND,
//    so the same lab program also opens a window; Mesa 25.1 and later have
//    only this one.
//  - OSMesa (offscreen_osmesa.cpp), the reference renderer that MANIFEST names,
//    up to Mesa 25.0; a program linking it has no window (docs/platform.md).
// Their frames are byte-identical for every view (.ci/run checks it).
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

  std::string backend() const;   // "EGL surfaceless" or "OSMesa"
  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  /// The frame as a top-down image (glReadPixels rows are bottom-up).
  Image read_pixels() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gllab
