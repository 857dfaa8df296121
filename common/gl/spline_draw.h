// common/gl/spline_draw.h — drawing what the spline core computes.
//
// The core (common/spline) computes; these functions only hand its results
// to GL, in immediate mode, so a student can read every call. None of them
// re-implements spline math: curves are flattened by spline::flatten_curve,
// constructions come from spline::de_casteljau and spline::de_boor.
// Lines and points are drawn unlit with the colour given; they test depth
// but do not write it (where lines meet, the one drawn last wins, on every
// rasteriser), so draw surfaces first and what goes on them after. Every
// function restores the GL state it changes (glPushAttrib), except the
// matrices, which it does not touch.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "gl/text.h"
#include "harness/lab.h"
#include "spline/bezier.h"
#include "spline/bspline.h"
#include "spline/tessellate.h"
#include "spline/types.h"
#include "spline/vec.h"

namespace gllab {

/// How far (lab units) a drawn curve may be from the true one. At the labs'
/// usual scale (about 100 pixels per unit) that is a tenth of a pixel.
inline constexpr double kDrawTolerance = 1e-3;

// ---- points and polygons ----------------------------------------------------

/// A line strip through the points; closed: a line loop.
void draw_polyline(const std::vector<spline::Vec3>& points, Rgb colour, float width = 2.f, bool closed = false);

/// The same, dashed (glLineStipple): construction lines, control polygons.
void draw_dashed_polyline(const std::vector<spline::Vec3>& points, Rgb colour, float width = 1.f);

/// Square dots of `size` pixels.
void draw_dots(const std::vector<spline::Vec3>& points, Rgb colour, float size = 6.f);

/// The points of the State's point list `list` as squares, optionally with
/// their index beside them, and registered for the mouse (gl/pick.h): the
/// one way a lab draws points a student can drag.
void draw_control_points(const State& state, const std::string& list, Rgb colour, float size = 9.f,
                         bool numbered = false);
/// The same for the first `count` points of the list only; the others are
/// neither drawn nor draggable (a list whose points join one at a time).
void draw_control_points_prefix(const State& state, const std::string& list, std::size_t count, Rgb colour,
                                float size = 9.f, bool numbered = false);

/// Only the points of `list` at `indices`, drawn and made pickable as above.
/// A lab leaves out the points it constructs from the others (a C1 neighbour,
/// the inner Bézier points of an interpolating spline): the mouse cannot grab
/// them, and the lab draws them itself where the construction puts them.
void draw_control_points(const State& state, const std::string& list, const std::vector<std::size_t>& indices,
                         Rgb colour, float size = 9.f, bool numbered = false);

/// Points of `list` drawn where the lab shows them: at[k] for list point
/// indices[k], pickable as that point (the mouse starts from at[k]). For lists
/// whose points the lab only partly uses: a height field keeps each control
/// point above its grid position and reads only its z.
void draw_control_points_at(const State& state, const std::string& list, const std::vector<std::size_t>& indices,
                            const std::vector<spline::Vec3>& at, Rgb colour, float size = 9.f);

/// A control polygon: a thin dashed line through P and a dot at each point
/// (not draggable; draw_control_points makes them draggable).
void draw_control_polygon(const std::vector<spline::Vec3>& P, Rgb colour);

/// The convex hull of the points (spline::convex_hull_xy, in the xy plane) as
/// an outline, filled translucent when fill_alpha > 0: where a Bézier curve
/// (or a B-spline span, with the points that act on it) must lie.
void draw_convex_hull(const std::vector<spline::Vec3>& P, Rgb colour, float fill_alpha = 0.f, float width = 1.f);

/// A surface's control net: its rows and columns (P[i * columns + j]) as
/// thin lines, a dot at each point.
void draw_control_net(const std::vector<spline::Vec3>& P, int rows, int columns, Rgb colour);

/// A line from `from` to `to` with an arrow head of `head_px` pixels at `to`
/// (sized on screen under the current matrices, like draw_knot_markers):
/// tangent vectors, derivatives, handles.
void draw_arrow(const spline::Vec3& from, const spline::Vec3& to, Rgb colour, float width = 2.f, double head_px = 9);

// ---- curves -------------------------------------------------------------------

/// A curve C(t), t in [a, b], flattened by the core to `tolerance`.
void draw_curve(const std::function<spline::Vec3(double)>& curve, double a, double b, Rgb colour, float width = 2.f,
                double tolerance = kDrawTolerance);
/// A B-spline or NURBS curve over its domain. At a knot where the curve has
/// a gap (multiplicity p + 1) the pieces are drawn separately, not joined.
void draw_curve(const spline::BsplineCurve& curve, Rgb colour, float width = 2.f, double tolerance = kDrawTolerance);
/// A Bézier curve over its interval.
void draw_curve(const spline::BezierCurve& curve, Rgb colour, float width = 2.f, double tolerance = kDrawTolerance);

/// A diamond at the curve point of each distinct knot of the domain, with the
/// knot's multiplicity beside it when it is more than 1.
void draw_knot_markers(const spline::BsplineCurve& curve, Rgb colour, bool show_multiplicity = true);

/// de Casteljau's scheme (seed 000 §1.6): level j's polygon b_0^j .. b_{n-j}^j,
/// colours blended from `first` (the control polygon) to `last`, and X(t) as
/// a large dot.
void draw_de_casteljau(const spline::DeCasteljau& scheme, Rgb first, Rgb last);

/// de Boor's construction the same way: levels[0] are the p + 1 control
/// points that act at u, levels[p][0] = C(u).
void draw_de_boor(const spline::DeBoorConstruction& construction, Rgb first, Rgb last);

/// A curvature comb (curvature from the curve's own derivatives,
/// spline/curvature.h): at `teeth` + 1 evenly spaced u in [a, b] a thin tooth
/// from X(u) to X(u) - scale k N (spline::curvature_vector: away from the
/// centre of curvature, as CAD programs draw it), and the line through the
/// tips. `derivatives(u)` returns {X(u), X'(u), X''(u)}. Teeth spaced evenly
/// in u also show the parameter speed. A sample where X' = 0 has no
/// curvature and gets no tooth.
void draw_curvature_comb(const std::function<std::array<spline::Vec3, 3>(double)>& derivatives, double a, double b,
                         double scale, Rgb colour, int teeth = 120);

// ---- meshes -----------------------------------------------------------------------

/// The triangles with their per-vertex normals (lit as the caller set up).
void draw_mesh(const spline::Mesh& mesh);
/// A surface in one colour, pushed back in depth (glPolygonOffset, see
/// kSurfaceOffset) so that curves, nets and iso-lines drawn on it afterwards
/// stay visible.
void draw_surface(const spline::Mesh& mesh, Rgb colour);
/// The same with one colour per vertex (colours[k] for positions[k], e.g. by
/// height); with GL_COLOR_MATERIAL on (enable_headlight) they are lit.
void draw_surface(const spline::Mesh& mesh, const std::vector<Rgb>& colours);
/// Line segments (GL_LINES), e.g. contour_segments' iso-lines.
void draw_segments(const std::vector<std::array<spline::Vec3, 2>>& segments, Rgb colour, float width = 1.f);
/// Every triangle edge as a line.
void draw_mesh_wireframe(const spline::Mesh& mesh, Rgb colour, float width = 1.f);
/// A needle of `length` along the normal at every `every`-th vertex.
void draw_normal_needles(const spline::Mesh& mesh, double length, Rgb colour, int every = 1);
/// Some of the mesh's triangles (indices into mesh.triangles), unlit in one
/// colour over whatever is drawn (no depth test): to point at them, e.g. the
/// faces spline::mesh_fidelity found tilted. Filled when width is 0, else
/// their outlines `width` pixels wide (which a sliver thinner than a pixel
/// still shows the same way on every rasterizer).
void draw_mesh_faces(const spline::Mesh& mesh, const std::vector<std::size_t>& faces, Rgb colour,
                     float width = 0);

// ---- plots ----------------------------------------------------------------------

/// A rectangle of the lab's plane showing data x in [x0, x1], y in [y0, y1]:
/// basis functions, curvature, a difference along u.
struct PlotFrame {
  double left = -1, bottom = -1, right = 1, top = 1;  // where, in lab coordinates (z = 0)
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;               // what: the data range shown

  /// The lab point of data (x, y).
  spline::Vec3 at(double x, double y) const;
};

/// The frame's box, the line y = 0 when it is in range, and `title` above it.
void draw_plot_axes(const PlotFrame& frame, Rgb colour, const std::string& title = "");
/// Pushes (glPushMatrix) a model-view transform under which data (x, y) lands
/// where frame.at(x, y) does, so a State point list can live in data units
/// inside a plot and still be dragged (draw_control_points under it).
/// equal_aspect: one scale for both axes (a circle stays round); the data
/// range is then widened about its centre until it fills the frame. Returns
/// the frame as seen under the transform (left = x0, ..., top = y1, with the
/// widened range) for draw_plot_axes and draw_plot_function. Pop with glPopMatrix.
PlotFrame enter_plot(const PlotFrame& frame, bool equal_aspect = false);
/// Turns on the scissor test for the window rectangle that the lab box
/// [left, right] x [bottom, top] of `frame` covers under the current matrices:
/// nothing drawn afterwards leaves that cell (curvature combs that spike,
/// curves that run off). glDisable(GL_SCISSOR_TEST) ends it.
void scissor_to(const PlotFrame& frame);
/// Distinct colours for the i-th of several things (basis functions and their
/// control points, curves compared in one view); repeats after 8.
Rgb series_colour(int i);
/// y = f(x) sampled at `samples` + 1 evenly spaced x from x0 to x1, clipped to the box.
void draw_plot_function(const PlotFrame& frame, const std::function<double(double)>& f, Rgb colour,
                        float width = 2.f, int samples = 240);
/// Short ticks at the bottom of the frame at these x (e.g. the knots).
void draw_plot_ticks(const PlotFrame& frame, const std::vector<double>& xs, Rgb colour);

/// 1, 2 or 5 times a power of ten, the smallest such value >= x: a plot top
/// that reads well (3.7e-7 -> 5e-7); 1 when x is not > 0 or not finite (a
/// plot of zeros). Labs 13 and 14 scale their GLU-difference and error plots
/// with it.
double plot_ceiling(double x);

// ---- labels ------------------------------------------------------------------------

/// A knot vector as text, each distinct knot once with "xm" for multiplicity
/// m > 1, each preceded by a space: " 0x4 0.2 0.4 0.6 0.8 1x4" (%g numbers).
std::string knot_vector_text(const std::vector<double>& U);

}  // namespace gllab
