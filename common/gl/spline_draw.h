// common/gl/spline_draw.h — drawing what the spline core computes.
//
// The core (common/spline) computes; these functions only hand its results
// to GL, in immediate mode, so a student can read every call. None of them
// re-implements spline math: curves are flattened by spline::flatten_curve,
// constructions come from spline::de_casteljau and spline::de_boor.
// Lines and points are drawn unlit with the colour given; every function
// restores the GL state it changes (glPushAttrib), except the matrices,
// which it does not touch.
#pragma once

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

/// A control polygon: a thin dashed line through P and a dot at each point
/// (not draggable; draw_control_points makes them draggable).
void draw_control_polygon(const std::vector<spline::Vec3>& P, Rgb colour);

/// A surface's control net: its rows and columns (P[i * columns + j]) as
/// thin lines, a dot at each point.
void draw_control_net(const std::vector<spline::Vec3>& P, int rows, int columns, Rgb colour);

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

// ---- meshes -----------------------------------------------------------------------

/// The triangles with their per-vertex normals (lit as the caller set up).
void draw_mesh(const spline::Mesh& mesh);
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
/// y = f(x) sampled at `samples` + 1 evenly spaced x from x0 to x1, clipped to the box.
void draw_plot_function(const PlotFrame& frame, const std::function<double(double)>& f, Rgb colour,
                        float width = 2.f, int samples = 240);
/// Short ticks at the bottom of the frame at these x (e.g. the knots).
void draw_plot_ticks(const PlotFrame& frame, const std::vector<double>& xs, Rgb colour);

}  // namespace gllab
