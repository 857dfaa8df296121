// common/gl/glu_errors.h — GLU's errors as frame errors (harness/lab.h), for
// the GLU calls a lab writes itself and for gllab::GluNurbs.
//
// A lab that calls GLU registers its own error callback, as the Red Book's
// surface.c does, and hands the code on:
//
//   void GLAPIENTRY on_nurbs_error(GLenum code) { gllab::report_glu_error(code, "the hill"); }
//   gluNurbsCallback(nurb, GLU_NURBS_ERROR, reinterpret_cast<_GLUfuncptr>(on_nurbs_error));
//
// The window shows the line on screen; a headless run exits 1 with it. (The
// Red Book's callback prints and calls exit(0): a run that failed must never
// look like a success.)
//
// Errors GLU finds and then loses. GLU 9.0.2 finds a misoriented or crossing
// trim loop (NURBS error 28) and a trim curve that does not meet the next
// piece (error 31) while gluEndSurface tessellates, and leaves with a longjmp
// into a frame that has already returned: the error callback is never called
// and the surface silently disappears (measured, docs/glu.md). Every program
// that links gllab_gl catches that longjmp (glu_errors.cpp) and reports the
// error as if the callback had: "GLU NURBS error 28 (intersecting or
// misoriented trim curves), lost by GLU 9.0.2 before its error callback".
#pragma once

#include <string>

#include "gl/gl.h"

namespace gllab {

/// "GLU NURBS error 4 (decreasing knot sequence knot)" for GLU_NURBS_ERROR4,
/// "GLU error GLU_INVALID_VALUE (invalid value)" for the other GLU codes:
/// the number or enum, and gluErrorString's text.
std::string glu_error_text(GLenum code);

/// report_frame_error("<what>: <glu_error_text(code)>"), or the text alone
/// when `what` is empty. For a lab's GLU error callbacks (NURBS, quadrics).
void report_glu_error(GLenum code, const std::string& what = "");

/// For a lab's quadric error callback: the call and the counts GLU 9.0.2
/// checks (src/libutil/quad.c: slices >= 2, and stacks or loops >= 1), as
/// "gluSphere slices=-4" or "gluDisk loops=0" when one is out of range, both
/// ("gluSphere slices=1 stacks=-1") when both or neither are. count_name is
/// "stacks" or "loops". GLU hands the callback only an error code, so a lab
/// notes this text before each quadric call and passes it to report_glu_error.
std::string glu_quadric_note(const std::string& call, int slices, const std::string& count_name,
                             int count);

/// While set (not null), a NURBS error that GLU raises and then loses goes to
/// this function (its number, 1..37) instead of being reported: GluNurbs sets
/// it for the length of one of its calls, so the error joins that call's.
/// Thread-local; returns the previous sink.
using LostGluErrorSink = void (*)(int nurbs_error);
LostGluErrorSink set_lost_glu_error_sink(LostGluErrorSink sink);

}  // namespace gllab
