// common/gl/curve_view.h — what labs 15 and 16 show beside their curves:
// the basis functions as a plot, the numbers of knot insertion, GLU's
// distance from the own curve, the radial error of a circle. None of it is
// the lesson: the labs write their gluNurbsCurve calls themselves, and the
// spline core (common/spline) does the mathematics.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/glu_compare.h"
#include "gl/spline_draw.h"
#include "gl/text.h"
#include "spline/bspline.h"
#include "spline/types.h"
#include "spline/vec.h"

namespace gllab {

/// Every basis function N_i,p(u) of the curve's knot vector by Cox–de Boor
/// (spline::cox_de_boor), each only on its support [U[i], U[i+p+1]], in
/// colours[i % size]: plotted in `area` (its left, bottom, right, top) over
/// the whole knot vector, N from 0 to 1.1. Axes and `title` in `axes`; the
/// knots as ticks and the domain [U[p], U[n+1]] (where the N_i sum to 1)
/// dashed, in `knots`; with `labels`, each i above its maximum (near its
/// Greville abscissa). Returns the frame (data x = u, y = N).
PlotFrame draw_basis_functions(const spline::BsplineCurve& curve, const PlotFrame& area,
                               const std::string& title, const std::vector<Rgb>& colours, Rgb axes,
                               Rgb knots, bool labels);

/// The p + 1 basis functions that are non-zero at u (spline::all_basis_funs,
/// span as spline::find_span gives it) marked in the plot f that
/// draw_basis_functions returned: a line at u in `ink`, a dot on each in
/// colours[i % size]. Returns their values as text: "u = 5.5: N2..5 = 0.021 ...".
std::string mark_basis_at(const PlotFrame& f, const spline::BsplineCurve& curve, double u, int span,
                          const std::vector<Rgb>& colours, Rgb ink);

/// glPushMatrix, then a move to (x, y) and a scale by `scale` in x and y:
/// where one of a view's several curves goes (pop with glPopMatrix).
void push_placed(double x, double y, double scale);

/// draw(k) for k = 0, 1, 2, 3 in the quarters of a square of half width
/// `half` about the origin (top left, top right, bottom left, bottom right),
/// each at half size about its centre (±half / 2, ±half / 2).
void draw_quarters(double half, const std::function<void(int k)>& draw);

/// Knot insertion as spline::knot_insert_step made it: the old control
/// polygon (dashed, `polygon`) and the curve thick in `curve`; after the
/// insertion also the new polygon and its new points q_i (labelled) in
/// `fresh`, and the new curve thin in `thin`, inside the old one.
void draw_knot_insertion(const spline::BsplineCurve& c, const spline::KnotInsertStep& step,
                         bool after, Rgb polygon, Rgb fresh, Rgb curve, Rgb thin);
/// Its numbers, four lines: the span [u_k, u_k+1) that t goes into, the
/// formulas of q_i and a_i, and each a_i (as a fraction where it is one).
std::vector<std::string> knot_insertion_text(const spline::BsplineCurve& c,
                                             const spline::KnotInsertStep& step, double t);

/// Bézier pieces (spline::bezier_decompose), each in its colour: its control
/// polygon, its points, its curve 3 px wide. Piece k gets colours[(3 k) % size],
/// so that neighbours differ.
void draw_bezier_pieces(const std::vector<spline::BezierCurve>& pieces,
                        const std::vector<Rgb>& colours);

/// " = 5/6" when a is a fraction with a denominator up to 12 (as the lecture
/// notes print knot insertion's a_i), else "".
std::string fraction_text(double a);

/// GLU's curve for `fed`, made with the properties the lab set on its own
/// `nurb` (read back: GluNurbsProperties::of), captured and measured against
/// `truth` at GLU's own u (compare_with_glu, gl/glu_compare.h). GLU's
/// errors come back in the result and as frame errors.
GluCurveDifference glu_difference(GLUnurbs* nurb, const spline::BsplineCurve& fed,
                                  const spline::BsplineCurve& truth, const std::string& name);

/// The same for one curve (fed = truth), plotted in `area` as
/// draw_glu_difference does, with the curve's knots as ticks below. Nothing
/// is plotted when GLU reported an error.
GluCurveDifference plot_glu_difference(GLUnurbs* nurb, const spline::BsplineCurve& curve,
                                       const std::string& name, const PlotFrame& area, Rgb ink,
                                       Rgb axes);

/// The radial error |C(u) - centre| / radius - 1 of each curve over u in
/// [0, 1], plotted in `area` in colours[k] under a title in `axes`; the
/// plot's top is the plot_ceiling of the largest error (written at its top
/// left in `text`), its bottom a fifth of that below 0; the first curve's
/// knots as ticks. Returns each curve's largest |error| at u = k / 1000.
std::vector<double> draw_radial_errors(const std::vector<spline::BsplineCurve>& curves,
                                       const std::vector<Rgb>& colours, spline::Vec3 centre,
                                       double radius, const PlotFrame& area, Rgb axes, Rgb ticks,
                                       Rgb text);

// ---- lab 16's captions ------------------------------------------------------

/// A weight as lab 16 prints it: "1/4" below 1, else "%g" ("4").
std::string weight_text(double w);

/// weights: the current weight w of P_i, the formula, and where the dots are
/// (C(xi) for each weight, xi the Greville abscissa of P_i).
std::vector<std::string> weights_caption(int i, double w, double xi);

/// conics: "r=0.25 ellipse" (spline::classify_conic) beside a shoulder point,
/// and the caption for the current r (its kind and w1 = r / (1 - r)).
std::string conic_label(double r);
std::vector<std::string> conics_caption(double r);

/// circle: the exact circle's control polygon (in `axes`), the polynomial
/// curve and the exact circle 2 px wide, their radial errors plotted in
/// `area` (draw_radial_errors), and a panel at window pixel (292, 40) with
/// what the curves are and the largest error of each.
void draw_circle_comparison(const spline::BsplineCurve& exact, const spline::BsplineCurve& polynomial,
                            spline::Vec3 centre, double radius, const PlotFrame& area, Rgb exact_ink,
                            Rgb polynomial_ink, Rgb axes, Rgb ticks, Rgb text);

/// own_vs_glu: how GLU was fed and sampled, over the per-curve table whose
/// rows glu_row makes: "circle  40 vertices  6.0e-07" (name padded to 7).
std::vector<std::string> glu_table_caption(double u_step);
std::string glu_row(const std::string& name, const GluCurveDifference& d);

/// not_premultiplied: the two columns' titles at y = 4.2 above x = -2.25 and
/// 2.25, and a panel at window pixel (8, 256): how far GLU's mistaken circle
/// is off (in radii) and the cubic's weight w of P_i (at w = 1 the mistake
/// shows nothing).
void draw_mistake_captions(double off_in_radii, int i, double w, Rgb right, Rgb wrong, Rgb text);

}  // namespace gllab
