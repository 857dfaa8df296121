// lab 15 · B-spline curves                                    difficulty: ★★★☆
// One cubic B-spline (lecture notes ch. 1, §1.6 Spline representations, "B-splines",
// "Knot insertion", "Displaying B-splines with OpenGL"; "B-Spline Polynomials", cases
// A to D): Cox–de Boor's basis, four kinds of knot vector, knot insertion, the Bézier
// pieces, and gluNurbsCurve drawing the same arrays as the own core.
// Notice: a knot of multiplicity m leaves a cubic C^(3-m) there: A C2, B C1,
//   C C0 (the curve runs through d3), D a gap. Inserting a knot changes the
//   control polygon, not the curve. GLU agrees with the core to float precision.
// Try: drag d3 (ringed) in cases_a_d: which segments move? Press [m] in basis and
//   watch the plot: how many basis functions are non-zero at the repeated knot?
// Keys: [m]/[M] multiplicity of knot 4  [u]/[U] parameter u  [t] before/after insertion
//   [s]/[S] GLU samples per unit of u  [h] help  [Esc] quit
// Views: basis, cases_a_d, knot_vectors, knot_insertion, bezier_pieces, own_vs_glu
// Reference: reference_images/15_bspline_curves__*.png

#include <string>
#include <vector>

#include "gl/curve_view.h"
#include "gl/gl.h"
#include "gl/glu_arrays.h"
#include "gl/glu_errors.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bspline.h"

namespace {

namespace spline = gllab::spline;
using gllab::format_text;
using gllab::PlotFrame;
using gllab::Rgb;
using gllab::State;
using spline::BsplineCurve;

// Lab data (edit me) -------------------------------------------------------
constexpr int kDegree = 3;  // cubic: order 4, as gluNurbsCurve counts it
// d0..d7: the zigzag of "B-Spline Polynomials", moved into the upper half of the window.
const std::vector<spline::Vec3> kPoints = {{-4, 1, 0}, {-3, 3, 0}, {-2, 4, 0}, {-1, 2, 0},
                                   {1, 3, 0},  {2, 1, 0}, {3, 4, 0},  {4, 2, 0}};
constexpr std::size_t kRinged = 3;  // d3: case C's curve runs through it, case D ends there
// 8 points + order 4 = 12 knots. §1.6 "Knot insertion"'s example: t = 0.5 into [u5, u6).
const std::vector<double> kClamped = {0, 0, 0, 0, .2, .4, .6, .8, 1, 1, 1, 1};
const std::vector<double> kNonUniform = {0, 0, 0, 0, .05, .1, .6, .95, 1, 1, 1, 1};
const Rgb kCurve{.35f, .8f, 1.f}, kPolygon{.55f, .55f, .6f}, kPoint{1.f, .8f, .3f}, kText{1, 1, 1},
    kRing{1.f, .3f, .4f}, kKnot{.6f, .9f, .5f}, kNew{1.f, .5f, .2f}, kGlu{1.f, .45f, .1f};
const std::vector<Rgb> kPalette = {{.95f, .35f, .35f}, {.95f, .65f, .25f}, {.9f, .9f, .3f},
                                   {.45f, .85f, .35f}, {.3f, .85f, .8f},   {.4f, .55f, 1.f},
                                   {.75f, .45f, .95f}, {.95f, .5f, .75f}};

// One GLU NURBS object, made in init() ("Displaying B-splines with OpenGL").
GLUnurbs* g_nurb = nullptr;

// GLU calls this from inside the failed call: the window shows it, headless exits 1.
void GLAPIENTRY on_nurbs_error(GLenum code) { gllab::report_glu_error(code, "gluNurbsCurve"); }

// Curves from the State ------------------------------------------------------
BsplineCurve with_knots(const State& s, const std::vector<double>& U) {
  return {kDegree, U, s.points("P"), {}, 2};  // 2D: z = 0
}

// Cases A–D of "B-Spline Polynomials": knots 0, 1, 2, 3, then `mult` copies of 4, then 5, 6, ...
BsplineCurve case_curve(const State& s, int mult) {
  std::vector<double> U = {0, 1, 2, 3};
  U.insert(U.end(), mult, 4.0);
  for (double v = 5; U.size() < kPoints.size() + kDegree + 1; ++v) U.push_back(v);
  return with_knots(s, U);
}

double param_at(const BsplineCurve& c, double fraction) {  // u as a fraction of the domain
  const spline::ParamInterval d = spline::domain(c);
  return d.a + fraction * (d.b - d.a);
}

std::string case_title(int mult) {
  const char* continuity[] = {"C2", "C1", "C0", "a gap"};
  return format_text("%c: knot 4 x%d, %s", 'A' + mult - 1, mult, continuity[mult - 1]);
}

// Drawing -------------------------------------------------------------------
void band(const std::vector<std::string>& lines) { gllab::draw_text_panel(8, 206, lines, kText); }

void draw_points(const State& s, bool numbered) {
  gllab::draw_dots({s.points("P")[kRinged]}, kRing, 15.f);
  gllab::draw_control_points(s, "P", kPoint, 9.f, numbered);
}

// Below: every basis function N_i,3 of the knot vector (gl/curve_view.h).
PlotFrame draw_basis(const BsplineCurve& c, const std::string& title, bool labels) {
  return gllab::draw_basis_functions(c, {-4, -4, 4, -.8}, title, kPalette, kPolygon, kKnot, labels);
}

// The curve with its control polygon and knots above, its basis functions below.
PlotFrame draw_panel(const State& s, const BsplineCurve& c, const std::string& title, bool labels) {
  gllab::draw_control_polygon(c.P, kPolygon);  // periodic: with the wrapped points
  gllab::draw_knot_markers(c, kKnot);
  gllab::draw_curve(c, kCurve, 2.5f);
  draw_points(s, labels);
  return draw_basis(c, title, labels);
}

void draw_basis_view(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const int mult = s.integer("mult");
  const BsplineCurve c = case_curve(s, mult);
  const double u = param_at(c, s.get("u"));
  const spline::DeBoorConstruction construction = spline::de_boor(c, u);
  gllab::draw_de_boor(construction, kPolygon, kText);
  const std::string title = "U =" + gllab::knot_vector_text(c.U) + "  " + case_title(mult);
  const PlotFrame f = draw_panel(s, c, title, true);
  // At u only N_span-p .. N_span are non-zero: the weights of de Boor's p + 1 points.
  const int k = construction.span;
  band({gllab::mark_basis_at(f, c, u, k, kPalette, kText),
        format_text("C(u) = sum N_i(u) d_i: de Boor blends d%d..%d (white)", k - c.p, k)});
}

void draw_cells(const State& s, const std::vector<BsplineCurve>& curves,
                const std::vector<std::string>& titles) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  gllab::draw_quarters(4.5, [&](int k) { draw_panel(s, curves[k], titles[k], false); });
}

void draw_cases(const State& s) {
  draw_cells(s, {case_curve(s, 1), case_curve(s, 2), case_curve(s, 3), case_curve(s, 4)},
             {case_title(1), case_title(2), case_title(3), case_title(4)});
}

void draw_knot_vectors(const State& s) {
  const BsplineCurve periodic = spline::periodic_curve(s.points("P"), kDegree, 2);  // P, P[0..2]
  draw_cells(s, {with_knots(s, kClamped), with_knots(s, kNonUniform), case_curve(s, 1), periodic},
             {"clamped uniform (open)", "clamped non-uniform", "floating uniform",
              "periodic (closed)"});
}

// §1.6 "Knot insertion": t goes into [u_k, u_k+1); p new points q_i replace p - 1 old ones.
void draw_insertion(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const BsplineCurve c = with_knots(s, kClamped);
  const double t = param_at(c, s.get("u"));
  const spline::KnotInsertStep step = spline::knot_insert_step(c, t);
  const bool after = s.flag("inserted");
  gllab::draw_knot_insertion(c, step, after, kPolygon, kNew, kCurve, kText);
  draw_points(s, true);
  band(gllab::knot_insertion_text(c, step, t));
  const BsplineCurve& shown = after ? step.curve : c;
  draw_basis(shown, (after ? "U' =" : "U =") + gllab::knot_vector_text(shown.U), true);
}

// §1.6 "Displaying B-spline curves (continued)": every interior knot raised to
// multiplicity p makes the curve Bézier pieces; as one curve, its basis functions
// are the Bernstein polynomials, span by span.
void draw_bezier(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const BsplineCurve c = with_knots(s, kClamped);
  const std::vector<spline::BezierCurve> pieces = spline::bezier_decompose(c);
  gllab::draw_control_polygon(c.P, kPolygon);
  gllab::draw_bezier_pieces(pieces, kPalette);  // one colour each
  draw_points(s, true);
  const BsplineCurve refined = spline::from_bezier_segments(pieces);  // the pieces as one curve
  const std::size_t n = pieces.size();
  band({format_text("%zu spans -> %zu cubic Bezier pieces, %zu points:", n, n, refined.P.size()),
        "every interior knot raised to multiplicity p = 3;",
        "below: the basis of the refined U, Bernstein per span"});
  draw_basis(refined, "U' =" + gllab::knot_vector_text(refined.U), false);
}

// Above: gluNurbsCurve (thick) under the own curve, both from the same arrays (§1.6
// "Displaying B-splines with OpenGL"). Below: their distance at each GLU vertex.
void draw_own_vs_glu(const State& s) {
  gllab::ortho_fit(s.width, s.height, 4.5, 4.5);
  const int mult = s.integer("mult");
  const std::vector<double> U = case_curve(s, mult).U;
  std::vector<GLfloat> knots(U.begin(), U.end());                // 12 knots: case A-D
  std::vector<GLfloat> ctl = gllab::glu_points(s.points("P"));  // d0..d7 as x, y, z
  const GLint n = GLint(knots.size()), order = kDegree + 1;
  const BsplineCurve own =  // the same arguments
      gllab::core_curve(n, knots.data(), 3, ctl.data(), order, GL_MAP1_VERTEX_3);
  gllab::draw_control_polygon(own.P, kPolygon);
  gluNurbsProperty(g_nurb, GLU_U_STEP, GLfloat(s.get("glu_step")));  // samples per unit of u
  if (s.flag("glu")) {
    // GLU draws with the current colour and width. Alone, its line is as
    // thin as ours, so the two pictures can be compared pixel for pixel.
    glColor3f(kGlu.r, kGlu.g, kGlu.b);
    glLineWidth(s.flag("own") ? 7.f : 2.5f);
    gluBeginCurve(g_nurb);
    gluNurbsCurve(g_nurb, n, knots.data(), 3, ctl.data(), order, GL_MAP1_VERTEX_3);
    gluEndCurve(g_nurb);
  }
  if (s.flag("own")) gllab::draw_curve(own, kCurve, 2.5f);
  draw_points(s, false);
  const gllab::GluCurveDifference d =  // GLU's vertices captured (gl/curve_view.h)
      gllab::plot_glu_difference(g_nurb, own, "cases A-D", {-4, -4, 4, -.8}, kGlu, kKnot);
  if (!d.ok()) return;
  const std::string vertices = format_text("%zu vertices; ", d.u.size()) + case_title(mult);
  band({"orange: gluNurbsCurve (GL_MAP1_VERTEX_3), blue: own",
        format_text("GLU_DOMAIN_DISTANCE, u_step %g: ", s.get("glu_step")) + vertices});
}

// init / shutdown ------------------------------------------------------------
void init() {
  glClearColor(.1f, .1f, .12f, 1.f);
  g_nurb = gluNewNurbsRenderer();
  gluNurbsCallback(g_nurb, GLU_NURBS_ERROR, reinterpret_cast<_GLUfuncptr>(on_nurbs_error));
  // GLU_U_STEP samples per unit of u, whatever the window: the same vertices
  // in a window and headless (GLU's default, GLU_PATH_LENGTH, counts pixels).
  gluNurbsProperty(g_nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
  // GLU's default. A curve is one line in every mode (measured: the outlines draw the same).
  gluNurbsProperty(g_nurb, GLU_DISPLAY_MODE, GLU_FILL);
}

// [s]/[S] double or halve GLU's samples per unit of u, clamped to the range.
bool keyboard(State& s, unsigned char key) {
  if (key != 's' && key != 'S') return false;
  s.step("glu_step", key == 's' ? s.get("glu_step") : -s.get("glu_step") / 2);
  return true;
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  Lab lab{"15_bspline_curves",
          "lab 15 · B-spline curves",
          {{"basis", "case A-D's cubic, its basis functions below, de Boor at u", draw_basis_view},
           {"cases_a_d", "cases A-D: knot 4 one to four times: C2, C1, C0, a gap", draw_cases},
           {"knot_vectors", "clamped uniform, non-uniform, floating, periodic", draw_knot_vectors},
           {"knot_insertion", "the notes' t = 0.5 into 0x4 .2 .4 .6 .8 1x4", draw_insertion},
           {"bezier_pieces", "Bezier pieces: every interior knot to multiplicity 3", draw_bezier},
           {"own_vs_glu", "own curve over gluNurbsCurve; below, their distance", draw_own_vs_glu}},
          {{"mult", 1, 1, kDegree + 1, "multiplicity of knot 4 (cases A-D)"},
           {"u", .5, .0625, .9375, "de Boor's u and the inserted t, as a fraction of the domain"},
           {"inserted", 1, 0, 1, "knot_insertion: show the curve after inserting t"},
           {"glu_step", 8, 1, 256, "GLU_U_STEP: GLU's samples per unit of u"},
           {"own", 1, 0, 1, "own_vs_glu: draw the own curve"},
           {"glu", 1, 0, 1, "own_vs_glu: draw gluNurbsCurve"}},
          {{'m', "knot 4 multiplicity +1", "mult", +1}, {'M', "knot 4 multiplicity -1", "mult", -1},
           {'u', "u +1/16 of the domain", "u", +.0625}, {'U', "u -1/16 of the domain", "u", -.0625},
           {'t', "knot insertion: before/after", "inserted"},
           {'s', "GLU samples per unit of u x2"}, {'S', "GLU samples per unit of u /2"}},
          init};
  lab.keyboard = keyboard;
  lab.shutdown = [] { gluDeleteNurbsRenderer(g_nurb); };
  lab.points = {{"P", kPoints, "control points d0..d7"}};
  lab.model = [](const State& s) -> Model { return case_curve(s, s.integer("mult")); };
  return lab;
}
