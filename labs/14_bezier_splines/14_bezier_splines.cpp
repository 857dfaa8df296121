// lab 14 · Bézier splines                                    difficulty: ★★☆☆
// Cubic Bézier segments joined into one curve (lecture notes ch. 1, §1.6
// Spline representations, "Bézier splines"; lecture notes "Higher Order
// Surfaces", "Joining of Bezier Curves"): the C0, G1, C1 and C2 conditions at
// the joints, with D_i = t_{i+1} - t_i, and the interpolating spline that the
// notes build through de Boor points, with its two free end points b1, b11.
// Notice: C1 puts b_{3i+1} on the tangent line at D_i/D_{i-1} times the length
//   of the last leg; C2 fixes b_{3i+2} as well, so each new segment keeps one
//   free point, and the curve swings wider with every segment.
// Try: drag b1 in end_conditions. How far along the curve does it change the
//   shape? In joining_c1, press [t] for chordal nodes: why does b4 move?
// Keys: [t]/[T] nodes  [k]/[K] G1 factor  [c] construction lines  [n] labels
//   [mouse] drag  [p] print  [Ctrl+S] save  [h] help  [Esc] quit
// Views: joining_c0, joining_g1, joining_c1, joining_c2, de_boor_points, end_conditions
// Reference: reference_images/14_bezier_splines__*.png

#include <algorithm>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "spline/bezier.h"
#include "spline/bspline.h"
#include "spline/cubic_spline.h"
#include "spline/parameterization.h"

namespace {

namespace sp = gllab::spline;
using gllab::format_text;
using sp::BezierCurve;
using sp::Vec3;

// Lab data (edit me) -------------------------------------------------------
// The Bézier points b_0..b_12 of four cubic segments; b_{3i} are the joints
// (the data points p_i of the interpolating spline). The views use the points
// a condition leaves free and construct the others.
const std::vector<Vec3> kBezierPoints = {
    {-3, -1, 0},     {-2.7, 0.2, 0}, {-2.054, 0.905, 0}, {-1.5, 0.8, 0}, {-1.1, -0.2, 0},
    {-0.5, -0.6, 0}, {0, -0.2, 0},   {0.4, 0.8, 0},      {1, 1.3, 0},    {1.5, 0.6, 0},
    {2.2, 0.1, 0},   {2.5, -0.9, 0}, {3, -0.6, 0}};
constexpr int kSegments = 4;  // b_0..b_{3 * kSegments}
using P = sp::Parameterization;
const P kNodes[] = {P::kUniform, P::kChordal, P::kCentripetal};
const gllab::Rgb kSegmentInk[2] = {{1.f, .6f, .2f}, {.3f, .75f, 1.f}}, kFree{1.f, .9f, .3f};
const gllab::Rgb kMade{.85f, .5f, .85f}, kDeBoor{.35f, .9f, .45f}, kLine{.55f, .55f, .6f};
const gllab::Rgb kText{1.f, 1.f, 1.f};

// The spline -----------------------------------------------------------------
std::vector<Vec3> joints(const std::vector<Vec3>& b) {  // b_0, b_3, ..., b_{3 * kSegments}
  std::vector<Vec3> p;
  for (int i = 0; i <= kSegments; ++i) p.push_back(b[3 * i]);
  return p;
}

// Nodes t_0..t_4 from the joints (lecture notes ch. 1, §1.6, "Parameterizations").
std::vector<double> nodes(const gllab::State& s) {
  return sp::parameters(joints(s.points("B")), kNodes[s.integer("nodes")]);
}

BezierCurve segment(const std::vector<Vec3>& b, int i, const std::vector<double>& t) {
  BezierCurve c{{b.begin() + 3 * i, b.begin() + 3 * i + 4}, t[i], t[i + 1]};
  c.dimension = 2;
  return c;
}

// One segment after another: each takes its first points from the previous
// one by the condition (C^k: the polynomial continued, core's
// continuation_points), the rest from the list. G1 is C1 for another length.
struct Joined {
  std::vector<BezierCurve> segments;
  std::vector<sp::BezierContinuation> joints;
};
Joined joined(const gllab::State& s, int condition) {
  const std::vector<double> t = nodes(s);
  std::vector<Vec3> b = s.points("B");
  Joined out{{segment(b, 0, t)}, {}};
  const int k = condition == 0 ? 0 : condition == 3 ? 2 : 1;
  for (int i = 1; i < kSegments; ++i) {
    const BezierCurve& prev = out.segments.back();
    const double length = condition == 1 ? (prev.b - prev.a) / s.get("g1_factor") : t[i + 1] - t[i];
    out.joints.push_back(sp::continuation_points(prev, k, length));
    for (int r = 0; r <= k; ++r) b[3 * i + r] = out.joints.back().points[r];
    out.segments.push_back(segment(b, i, t));
  }
  return out;
}

// The interpolating spline through the joints (lecture notes ch. 1, §1.6,
// "Bézier splines", the three steps): b1 and b11 from the list (chosen) or natural ends.
std::vector<BezierCurve> through_joints(const gllab::State& s, bool natural) {
  const std::vector<Vec3>& b = s.points("B");
  const std::vector<double> t = nodes(s);
  auto segments = natural ? sp::bezier_spline_through(t, joints(b), sp::EndCondition::kNatural)
                          : sp::bezier_spline_through(t, joints(b), b[1], b[3 * kSegments - 1]);
  for (BezierCurve& c : segments) c.dimension = 2;
  return segments;
}

// Drawing --------------------------------------------------------------------
// The segments in alternating colours over their dashed control polygons,
// the constructed points as dots, the free ones draggable.
void draw_spline(const gllab::State& s, const std::vector<BezierCurve>& segments,
                 const std::vector<std::size_t>& free) {
  for (std::size_t i = 0; i < segments.size(); ++i) {
    gllab::draw_dashed_polyline(segments[i].P, kLine);
    gllab::draw_curve(segments[i], kSegmentInk[i % 2], 2.5f);
  }
  const std::vector<Vec3> b = sp::from_bezier_segments(segments).P;
  gllab::draw_dots(b, kMade, 7.f);
  gllab::draw_control_points(s, "B", free, kFree);
  for (std::size_t i = 0; s.flag("labels") && i < b.size(); ++i) {
    const bool is_free = std::find(free.begin(), free.end(), i) != free.end();
    gllab::draw_label(b[i].x, b[i].y, 0, std::to_string(i), is_free ? kFree : kMade, 12, -12);
  }
}

// The views but end_conditions: ortho_fit, then the drawing below the legend.
void begin(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 3.4, 3.4);
  glTranslated(0, -0.5, 0);  // below the text panel
}
void legend(const gllab::State& s) {
  const char* line = "yellow: free, drag them   pink: made by the condition";
  if (s.flag("labels")) gllab::draw_text_panel(8, s.height - 28, {line}, kText);
}

void draw_joining(const gllab::State& s, int condition) {
  begin(s);
  const Joined j = joined(s, condition);
  // Free: everything in C0; G1 and C1 make b_{3i+1}, C2 also b_{3i+2}.
  std::vector<std::size_t> free;
  for (std::size_t i = 0; i <= 3 * kSegments; ++i)
    if (i < 4 || condition == 0 || i % 3 == 0 || (i % 3 == 2 && condition != 3)) free.push_back(i);
  // Each level's point lies on a line through two of the level before.
  for (const auto& joint : j.joints)
    for (std::size_t r = 1; s.flag("construction") && r < joint.levels.size(); ++r)
      for (std::size_t k = 0; k < joint.levels[r].size(); ++k) {
        const std::vector<Vec3>& before = joint.levels[r - 1];
        gllab::draw_polyline({before[k], before[k + 1], joint.levels[r][k]}, kLine, 1.f);
      }
  for (const auto& joint : j.joints)  // the de Boor point d
    if (joint.levels.size() == 3) gllab::draw_dots({joint.levels[1][0]}, kDeBoor, 8.f);
  draw_spline(s, j.segments, free);
  if (!s.flag("labels")) return;
  const std::vector<double> t = nodes(s);
  const char* rule[] = {"C0: b_{3i} shared, nothing else",
                        "G1: b_{3i} - b_{3i-1} = k (b_{3i+1} - b_{3i})",
                        "C1: (b_{3i} - b_{3i-1}) / D_{i-1} = (b_{3i+1} - b_{3i}) / D_i",
                        "C2: also S'' equal: b_{3i+2} from d (green)"};
  std::vector<std::string> lines = {
      rule[condition], format_text("nodes %s: D_i = %.2f %.2f %.2f %.2f",
                                   sp::parameterization_name(kNodes[s.integer("nodes")]),
                                   t[1] - t[0], t[2] - t[1], t[3] - t[2], t[4] - t[3])};
  if (condition == 1) lines.push_back(format_text("k = %.2f", s.get("g1_factor")));
  for (const std::string& l : gllab::bezier_joint_report(j.segments)) lines.push_back(l);
  gllab::draw_text_panel(8, 8, lines, kText);
}

void draw_c0(const gllab::State& s) { draw_joining(s, 0); legend(s); }
void draw_g1(const gllab::State& s) { draw_joining(s, 1); legend(s); }
void draw_c1(const gllab::State& s) { draw_joining(s, 2); legend(s); }
void draw_c2(const gllab::State& s) { draw_joining(s, 3); legend(s); }

void draw_de_boor_points(const gllab::State& s) {
  begin(s);
  const std::vector<Vec3>& b = s.points("B");
  const std::vector<Vec3> d =
      sp::de_boor_points_through(nodes(s), joints(b), b[1], b[3 * kSegments - 1]);
  gllab::draw_dashed_polyline(d, kDeBoor, 1.5f);
  gllab::draw_dots(d, kDeBoor, 10.f);
  draw_spline(s, through_joints(s, false), {0, 1, 3, 6, 9, 11, 12});
  for (std::size_t i = 0; s.flag("labels") && i < d.size(); ++i)
    gllab::draw_label(d[i].x, d[i].y, 0, "d" + std::to_string(i), kDeBoor, -14, 14);
  if (s.flag("labels"))
    gllab::draw_text_panel(8, 8, {"1) choose b1 and b11 (drag them)",
                                  "2) solve for the de Boor points d0..d4",
                                  "3) b_3i+1, b_3i+2 divide the leg d_i d_i+1",
                                  "   in the ratio D_i-1 : D_i : D_i+1"},
                           kText);
  legend(s);
}

void draw_end_conditions(const gllab::State& s) {
  gllab::ortho_fit(s.width, s.height, 3.4, 3.4);
  const std::vector<BezierCurve> chosen = through_joints(s, false);
  const std::vector<BezierCurve> natural = through_joints(s, true);
  const char* caption[] = {"b1 and b11 as chosen", "natural ends: S''(t0) = S''(t4) = 0"};
  for (int row = 0; row < 2; ++row) {
    glPushMatrix();
    glTranslated(0, row ? -1.7 : 1.5, 0);
    glScaled(0.8, 0.8, 1);  // the other row's curve thin, then this row's
    for (const BezierCurve& c : row ? chosen : natural) gllab::draw_curve(c, kLine, 1.f);
    if (row == 0) draw_spline(s, chosen, {0, 1, 3, 6, 9, 11, 12});
    else draw_spline(s, natural, {0, 3, 6, 9, 12});
    glPopMatrix();
    if (s.flag("labels")) gllab::draw_label(0, row ? -0.25 : 3.05, 0, caption[row], kText);
  }
  legend(s);
}

// init ----------------------------------------------------------------------
void init() { glClearColor(0.12f, 0.13f, 0.16f, 1.f); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "14_bezier_splines",
      "lab 14 · Bézier splines",
      {{"joining_c0", "four cubic segments sharing their end points only", draw_c0},
       {"joining_g1", "G1: the next inner point on the tangent line, k times shorter", draw_g1},
       {"joining_c1", "C1: the next inner point at D_i / D_i-1 of the last leg", draw_c1},
       {"joining_c2", "C2: two points made per joint, through the de Boor point", draw_c2},
       {"de_boor_points", "interpolating spline: de Boor, Bézier points", draw_de_boor_points},
       {"end_conditions", "b1, b11 as chosen vs natural ends", draw_end_conditions}},
      {{"nodes", 0, 0, 2, "node spacing D_i: 0 uniform, 1 chordal, 2 centripetal"},
       {"g1_factor", 2, 0.25, 4, "G1: b_3i - b_3i-1 = k (b_3i+1 - b_3i)"},
       {"construction", 1, 0, 1, "draw the lines the conditions put points on"},
       {"labels", 1, 0, 1, "point numbers, formulas and measurements"}},
      {{'t', "nodes: next spacing", "nodes", +1}, {'T', "nodes: previous spacing", "nodes", -1},
       {'k', "G1 factor +0.25", "g1_factor", +0.25}, {'K', "G1 factor -0.25", "g1_factor", -0.25},
       {'c', "construction lines on/off", "construction"}, {'n', "labels on/off", "labels"}},
      init};
  lab.points = {{"B", kBezierPoints, "Bézier points b0..b12 (joints b0, b3, ..., b12)"}};
  // [Ctrl+S] saves the interpolating spline (de_boor_points, b1 and b11 as
  // chosen) as one B-spline with triple knots at the joints, in every view.
  lab.model = [](const gllab::State& s) -> gllab::Model {
    return sp::from_bezier_segments(through_joints(s, false));
  };
  return lab;
}
