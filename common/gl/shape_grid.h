// common/gl/shape_grid.h — a grid of shapes with captions under them, the
// layout of labs 07 (GLU quadrics) and 09 (glut shapes), and what they
// measure on screen: not their lesson.
//
//   gllab::enter_cell(-2.2, 1.4, 1.0, -60.f);
//   gluSphere(q, 0.9, 24, 12);
//   glPopMatrix();
//   gllab::draw_caption(-2.2, 1.4 - 1.15, "gluSphere", "radius 0.9");
#pragma once

#include <functional>
#include <string>

#include "gl/text.h"

namespace gllab {

/// Pushes the modelview and enters the cell centred at (x, y): translated
/// there, scaled by `scale`, turned `tilt_degrees` about x (-60: the shape's z
/// axis leans up and towards the eye; 0: no turn), then `spin_degrees` about
/// z (0: no turn). glPopMatrix leaves the cell.
void enter_cell(double x, double y, double scale, float tilt_degrees, double spin_degrees = 0);

/// White text centred on the lab point (x, y, 0) under the current matrices,
/// and `second`, when not empty, one text line (16 pixels) below it.
void draw_caption(double x, double y, const std::string& first, const std::string& second = "");

/// A shape as a wireframe over its fill, hidden lines removed: draw(false)
/// in the current colour, lit as set, pushed back by glPolygonOffset(1, 1);
/// then draw(true) unlit in `wire`. `draw` sets the draw style from its
/// argument (gluQuadricDrawStyle GLU_LINE or GLU_FILL) and draws. Lighting
/// is on afterwards, polygon offset fill off.
void wire_over_fill(const std::function<void(bool wire)>& draw, Rgb wire);

/// Window pixels per lab unit along x under the current projection (an
/// orthographic one, as gllab::ortho_fit and the orbit camera's zoom make it),
/// in a window `width` pixels wide.
double pixels_per_unit(int width);

}  // namespace gllab
