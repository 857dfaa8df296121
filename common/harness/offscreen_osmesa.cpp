// common/harness/offscreen_osmesa.cpp — OffscreenContext over OSMesa.
//
// Facts this file depends on (docs/platform.md):
//  - libOSMesa exports every gl* symbol itself; it must come before libGLU on
//    the link line and no program may also link libGL, or every GL call
//    silently does nothing. A null GL_RENDERER is the symptom we check for.
//  - Without OSMESA_DEPTH_BITS there is silently no depth buffer, and the core
//    profile rejects glBegin: ask for 24 bits and the compatibility profile.
//    The same holds for OSMESA_STENCIL_BITS: asked for 8, Mesa 22.3 gives 8.
#include "harness/offscreen.h"

#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

#include "gl/gl.h"

namespace gllab {

struct OffscreenContext::Impl {
  OSMesaContext context = nullptr;
  std::vector<GLubyte> buffer;
  int width = 0, height = 0;
};

OffscreenContext::OffscreenContext(int width, int height) : impl_(std::make_unique<Impl>()) {
  const int attributes[] = {OSMESA_FORMAT,       OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,   24,
                            OSMESA_STENCIL_BITS, 8,
                            OSMESA_PROFILE,      OSMESA_COMPAT_PROFILE,
                            0};
  impl_->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!impl_->context) throw std::runtime_error("OSMesaCreateContextAttribs failed (compatibility profile, 24-bit depth)");
  impl_->width = width;
  impl_->height = height;
  impl_->buffer.assign(static_cast<std::size_t>(width) * height * 4, 0);
  if (!OSMesaMakeCurrent(impl_->context, impl_->buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
    OSMesaDestroyContext(impl_->context);
    throw std::runtime_error("OSMesaMakeCurrent failed for " + std::to_string(width) + "x" +
                             std::to_string(height));
  }
  if (glGetString(GL_RENDERER) == nullptr) {
    OSMesaDestroyContext(impl_->context);
    throw std::runtime_error(
        "GL_RENDERER is null: GL calls are not reaching OSMesa (is libGL linked before libOSMesa?)");
  }
  GLint depth_bits = 0, stencil_bits = 0;
  glGetIntegerv(GL_DEPTH_BITS, &depth_bits);
  glGetIntegerv(GL_STENCIL_BITS, &stencil_bits);  // 8 on Mesa 22.3 (lab 33's CSG needs them)
  if (depth_bits < 24 || stencil_bits < 8) {
    OSMesaDestroyContext(impl_->context);
    throw std::runtime_error("OSMesa context has " + std::to_string(depth_bits) +
                             " depth bits and " + std::to_string(stencil_bits) +
                             " stencil bits; 24 and 8 needed");
  }
}

OffscreenContext::~OffscreenContext() {
  // Finish first: a frame left unfinished (display() threw after drawing
  // text) still has glBitmap calls queued, and Mesa 22.3 crashed flushing
  // them inside OSMesaDestroyContext (measured, SIGSEGV).
  if (impl_->context) {
    glFinish();
    OSMesaDestroyContext(impl_->context);
  }
}

std::string OffscreenContext::backend() const { return "OSMesa"; }

std::string OffscreenContext::renderer() const {
  const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return r ? r : "";
}

Image OffscreenContext::read_pixels() const {
  std::vector<std::uint8_t> rows(impl_->buffer.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, impl_->width, impl_->height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  return image_from_bottom_up(rows.data(), impl_->width, impl_->height);
}

}  // namespace gllab
