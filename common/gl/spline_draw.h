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
#include "spline/cubic_spline.h"
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
/// The same for every point of the list: point k drawn at at[k].
void draw_control_points_at(const State& state, const std::string& list,
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

/// Handles of the point list `list`: a line from point base to point tip for
/// each pair {base, tip} (tangent handles), then every point of the list as
/// draw_control_points draws it, draggable.
void draw_handles(const State& state, const std::string& list,
                  const std::vector<std::array<std::size_t, 2>>& handles, Rgb line, Rgb points);

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

/// An interpolating cubic spline over [t_0, t_N], from its own evaluator
/// (spline::spline_point).
void draw_curve(const spline::CubicSpline& spline, Rgb colour, float width = 2.f,
                double tolerance = kDrawTolerance);
/// The curve at `samples` + 1 evenly spaced parameters of [a, b] (the last one
/// exactly b) as a polyline, not flattened adaptively: two curves drawn this way
/// land on the same pixels wherever their points agree (lab 13's overlays).
void draw_sampled_curve(const std::function<spline::Vec3(double)>& curve, double a, double b,
                        Rgb colour, int samples = 400, float width = 2.f);
/// A diamond at the curve point of each distinct knot of the domain, with the
/// knot's multiplicity beside it when it is more than 1.
void draw_knot_markers(const spline::BsplineCurve& curve, Rgb colour, bool show_multiplicity = true);

/// de Casteljau's scheme (ch. 1 §1.6): level j's polygon b_0^j .. b_{n-j}^j,
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

/// The curvature comb of an interpolating cubic spline from its own
/// derivatives (spline::spline_derivative), `teeth_per_segment` teeth per segment.
void draw_curvature_comb(const spline::CubicSpline& spline, double scale, Rgb colour,
                         int teeth_per_segment = 30);
// ---- meshes -----------------------------------------------------------------------

/// The trim loops of a surface in its (u, v) plane (z = 0, under the current
/// matrices): each piece in the colour of the GLU call that takes it,
/// `pwl` for a gluPwlCurve polyline, `polynomial` for a GLU_MAP1_TRIM_2 curve,
/// `rational` for GLU_MAP1_TRIM_3, with an arrowhead where it ends, so that
/// the direction GLU's keep-left rule reads shows.
void draw_trim_loops(const std::vector<spline::TrimLoop>& loops, Rgb pwl, Rgb polynomial, Rgb rational);

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
/// plot of zeros). Labs 15 and 16 scale their GLU-difference and error plots
/// with it.
double plot_ceiling(double x);
/// The largest |f(x) - g(x)| at `samples` + 1 evenly spaced x from x0 to x1,
/// x_k = x0 + (x1 - x0) k / samples: the error a plot's caption prints (lab 10's
/// polynomial and spline against Runge's function).
double max_difference(const std::function<double(double)>& f, const std::function<double(double)>& g,
                      double x0, double x1, int samples);

// ---- labels ------------------------------------------------------------------------

/// A knot vector as text, each distinct knot once with "xm" for multiplicity
/// m > 1, each preceded by a space: " 0x4 0.2 0.4 0.6 0.8 1x4" (%g numbers).
std::string knot_vector_text(const std::vector<double>& U);
/// What consecutive Bézier segments share at each joint, one line per joint
/// b_(n i) (n the degree): the angle between the tangents, the speeds |S'| on
/// both sides and the jump of S'' (spline::bezier_end_derivative and
/// bezier_start_derivative): "b3: angle   0.0 deg  |S'| 1.20|1.20  S'' jump 2.30".
std::vector<std::string> bezier_joint_report(const std::vector<spline::BezierCurve>& segments);
/// Parameters t rescaled to [0, 1] (spline::unit_interval_parameters) as text,
/// two decimals without the leading zero: ".00 .24 .29 ... 1" (lab 13's nodes).
std::string unit_parameters_text(const std::vector<double>& t);
/// The polynomial c[0] + c[1] x + ... as text, highest power first, as the
/// lecture notes print them: {1, -0.6, 0.1} -> "0.1x² - 0.6x + 1" (%.4g; zero
/// terms left out, a coefficient 1 or -1 written as a sign; "0" when all are
/// zero). `x` names the variable ("t"). Labs 10 and 11 print bases with it.
std::string polynomial_text(const std::vector<double>& c, const std::string& x = "x");
/// Newton's form sum a_i N_i(x) as text, "1 + 1(x-0) + 0(x-0)(x-2)" for
/// a = {1, 1, 0} at the nodes {0, 2, 4} (%.4g numbers).
std::string newton_form_text(const std::vector<double>& a, const std::vector<double>& nodes);
/// A divided-difference table (spline::NewtonInterpolant::table(): table[k][j]
/// = f[t_j..t_(j+k)]) as a text panel with its top-left corner at lab point
/// (x, y): a title line, a header "t_j k=0 k=1 ...", then row j = t_j, f[t_j],
/// f[t_j, t_(j+1)], ... in columns of 9 characters (%.4g). The entries of node
/// `fresh` (the diagonal k + j = fresh) are drawn again in `fresh_colour`;
/// fresh < 0 marks none. Lab 10 grows the table one node at a time.
void draw_divided_differences(const std::vector<double>& nodes,
                              const std::vector<std::vector<double>>& table, double x, double y,
                              Rgb colour, int fresh = -1, Rgb fresh_colour = {1.f, 0.4f, 0.3f});

/// A point's x and y as text, "(6.624, 4.536)" (%.5g numbers), for panels
/// that print a construction; points_text joins several with spaces.
std::string xy_text(const spline::Vec3& p);
std::string points_text(const std::vector<spline::Vec3>& points);

// ---- colours ---------------------------------------------------------------------

/// One stop of a colour ramp by height: a terrain's water, grass, rock, snow.
struct HeightColour {
  double height;
  Rgb colour;
};
/// One colour per vertex of the mesh, by its height z (for draw_surface):
/// blended linearly between the two stops of the ramp around z (stops in
/// increasing height), the end colours beyond them.
std::vector<Rgb> height_colours(const std::vector<HeightColour>& ramp, const spline::Mesh& mesh);

}  // namespace gllab
