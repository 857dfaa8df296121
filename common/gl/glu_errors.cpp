// common/gl/glu_errors.cpp — see glu_errors.h.
#include "gl/glu_errors.h"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#if defined(GLLAB_ASAN)
#include <sanitizer/asan_interface.h>
#endif

#include "harness/lab.h"

namespace gllab {

namespace {

constexpr int kNurbsErrors = static_cast<int>(GLU_NURBS_ERROR37 - GLU_NURBS_ERROR1) + 1;

std::string enum_name(GLenum code) {
  switch (code) {
    case GLU_INVALID_ENUM: return "GLU_INVALID_ENUM";
    case GLU_INVALID_VALUE: return "GLU_INVALID_VALUE";
    case GLU_INVALID_OPERATION: return "GLU_INVALID_OPERATION";
    case GLU_OUT_OF_MEMORY: return "GLU_OUT_OF_MEMORY";
    default: break;
  }
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%X", static_cast<unsigned>(code));
  return hex;
}

thread_local LostGluErrorSink t_sink = nullptr;

// True once GLU lost an error outside a GluNurbs call in this process (see
// __lsan_is_turned_off below).
bool g_lost_error_seen = false;

// Is `address` code in libGLU? (dladdr: the shared object it lies in.)
bool in_libglu(const void* address) {
  Dl_info info;
  if (dladdr(address, &info) == 0 || !info.dli_fname) return false;
  const char* slash = std::strrchr(info.dli_fname, '/');
  return std::strncmp(slash ? slash + 1 : info.dli_fname, "libGLU.so", 9) == 0;
}

// The longjmp GLU makes for a lost error carries its number.
void on_glu_longjmp(int value) {
  if (value < 1 || value > kNurbsErrors) return;
  if (t_sink) return t_sink(value);
  g_lost_error_seen = true;
  report_frame_error(glu_error_text(GLU_NURBS_ERROR1 + static_cast<GLenum>(value) - 1) +
                     ", lost by GLU 9.0.2 before its error callback");
}

}  // namespace

std::string glu_error_text(GLenum code) {
  const auto* text = reinterpret_cast<const char*>(gluErrorString(code));
  const std::string why = text ? text : "no text";
  if (code >= GLU_NURBS_ERROR1 && code <= GLU_NURBS_ERROR37)
    return "GLU NURBS error " + std::to_string(code - GLU_NURBS_ERROR1 + 1) + " (" + why + ")";
  return "GLU error " + enum_name(code) + " (" + why + ")";
}

void report_glu_error(GLenum code, const std::string& what) {
  report_frame_error(what.empty() ? glu_error_text(code) : what + ": " + glu_error_text(code));
}

std::string glu_quadric_note(const std::string& call, int slices, const std::string& count_name,
                             int count) {
  const std::string a = "slices=" + std::to_string(slices);
  const std::string b = count_name + "=" + std::to_string(count);
  const bool a_bad = slices < 2, b_bad = count < 1;
  return call + " " + (a_bad == b_bad ? a + " " + b : a_bad ? a : b);
}

LostGluErrorSink set_lost_glu_error_sink(LostGluErrorSink sink) {
  const LostGluErrorSink previous = t_sink;
  t_sink = sink;
  return previous;
}

}  // namespace gllab

// ---- errors GLU finds and then loses -------------------------------------------
// GLU 9.0.2 checks trim loops while it tessellates (libnurbs, Subdivider::
// drawSurfaces and the ccwTurn tests): a trim curve that does not meet the
// next piece gives NURBS error 31, a loop running the wrong way (a clockwise
// outer loop) or two loops that cross give error 28. It leaves the
// tessellation with longjmp, to a setjmp GLU made inside its own
// out-of-line mysetjmp() (libnurbs/internals/mysetjmp.h), a function that has
// already returned. The jump lands in that dead frame, whose return address
// the tessellation has overwritten with its own, and comes back as if the
// tessellation had finished: the error callback is never called and the
// surface silently disappears (measured with gdb, libglu1-mesa 9.0.2-1.1: the
// longjmp carries 28 or 31, no callback follows, no vertex is drawn).
// GLU jumps through glibc's fortified __longjmp_chk (nm -D libGLU.so.1 lists
// it, and no other longjmp). The definition below is linked into every
// program that links gllab_gl (common/CMakeLists.txt: -u __longjmp_chk) and
// found before glibc's. For a jump made from libGLU's code (dladdr of the
// return address, so libpng's error jumps and any other pass untouched) it
// reports the error as the callback would have, then jumps as glibc would
// (the next definition, dlsym RTLD_NEXT: glibc's, or the AddressSanitizer's).
// The parameter is glibc's struct __jmp_buf_tag[1], passed on untouched.
extern "C" [[noreturn]] void __longjmp_chk(void* env, int value) {
  using LongJump = void (*)(void*, int);
  static const auto next = reinterpret_cast<LongJump>(dlsym(RTLD_NEXT, "__longjmp_chk"));
  if (gllab::in_libglu(__builtin_return_address(0))) gllab::on_glu_longjmp(value);
  if (!next) std::abort();  // no glibc: cannot happen in a program that links GLU
#if defined(GLLAB_ASAN)
  // What AddressSanitizer's own __longjmp_chk does first: unpoison the stack
  // the jump abandons. GCC's runtime is libasan.so, so RTLD_NEXT above finds its
  // __longjmp_chk and this is done twice; clang links its runtime into the
  // program, where this definition replaces its, and RTLD_NEXT finds glibc's.
  // Without it the abandoned frames stay poisoned, and the next call that uses
  // that stack (llvmpipe compiling a shader, in lab 22's reversed_outer_loop
  // view) stops with "AddressSanitizer: CHECK failed: asan_thread.cpp:370".
  __asan_handle_no_return();
#endif
  next(env, value);
  std::abort();  // __longjmp_chk does not return
}

#if defined(GLLAB_ASAN)
// GLU 9.0.2 leaks on the path of its lost errors: the jump skips the frames
// that own what the tessellation allocated. Measured with LeakSanitizer:
// 34,712 bytes from operator new and about 1 KB from malloc in libGLU.so for
// each clockwise outer loop, with gluDeleteNurbsRenderer called; nothing for
// a valid trim. libGLU.so has no symbols, so a suppression could not name
// those frames and would hide every GLU leak. GluNurbs exempts exactly its
// own failing gluEndSurface calls (glu_nurbs.cpp); a lab's own gluEndSurface
// cannot be wrapped, so a process in which GLU lost an error outside
// GluNurbs (a lab's error view, a grading fixture with a reversed loop) is
// not leak-checked at exit. Every other process is. LeakSanitizer calls this
// hook before its check (sanitizer/lsan_interface.h).
extern "C" int __lsan_is_turned_off() { return gllab::g_lost_error_seen ? 1 : 0; }
#endif
