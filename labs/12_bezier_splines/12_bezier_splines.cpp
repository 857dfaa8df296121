// lab 12 · Bézier splines                                    difficulty: ★★☆☆
// Cubic Bézier segments joined into one curve (seed 000 §1.6 "Bézier splines",
// seed 004 "Joining of Bezier Curves"): the C0, G1, C1 and C2 conditions at
// the joints, with D_i = t_{i+1} - t_i, and the interpolating spline that the
// seeds build through de Boor points, with its two free end points b1, b11.
// Notice: C1 puts b_{3i+1} on the tangent line at D_i/D_{i-1} times the length
//   of the last leg; C2 fixes b_{3i+2} as well, so each new segment keeps one
//   free point, and the curve swings wider with every segment.
// Try: drag b1 in end_conditions. How far along the curve does it change the
//   shape? In joining_c1, press [t] for chordal nodes: why does b4 move?
// Keys: [t]/[T] nodes  [k]/[K] G1 factor  [c] construction lines  [n] labels
//   [h] help  [Esc] quit
// Views: joining_c0, joining_g1, joining_c1, joining_c2, de_boor_points, end_conditions
// Reference: reference_images/12_bezier_splines__*.png

#include <algorithm>
#include <cmath>
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

using gllab::spline::BezierCurve;
using gllab::spline::Vec3;

// Lab data (edit me) -------------------------------------------------------
// The Bézier points b_0..b_12 of four cubic segments; b_{3i} are the joints
// (the data points p_i of the interpolating spline). The views use the points
// a condition leaves free and construct the others.
const std::vector<Vec3> kBezierPoints = {
    {-3, -1, 0},    {-2.7, 0.2, 0}, {-2.054, 0.905, 0}, {-1.5, 0.8, 0},  {-1.1, -0.2, 0},
    {-0.5, -0.6, 0}, {0, -0.2, 0},  {0.4, 0.8, 0},  {1, 1.3, 0},     {1.5, 0.6, 0},
    {2.2, 0.1, 0},  {2.5, -0.9, 0}, {3, -0.6, 0}};
constexpr int kSegments = 4;  // b_0..b_{3 * kSegments}
const gllab::spline::Parameterization kNodes[] = {gllab::spline::Parameterization::kUniform,
                                                   gllab::spline::Parameterization::kChordal,
                                                   gllab::spline::Parameterization::kCentripetal};
const gllab::Rgb kSegmentInk[2] = {{1.f, .6f, .2f}, {.3f, .75f, 1.f}}, kFree{1.f, .9f, .3f},
    kMade{.85f, .5f, .85f}, kDeBoor{.35f, .9f, .45f}, kLine{.55f, .55f, .6f}, kText{1.f, 1.f, 1.f};

// The spline -----------------------------------------------------------------
// Nodes t_0..t_4 from the joints (seed 000 §1.6, parameterizations).
std::vector<double> nodes(const gllab::State& s) {
  std::vector<Vec3> joints;
  for (int i = 0; i <= kSegments; ++i) joints.push_back(s.points("B")[3 * i]);
  return gllab::spline::parameters(joints, kNodes[s.integer("nodes")]);
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
  std::vector<gllab::spline::BezierContinuation> joints;
};
Joined joined(const gllab::State& s, int condition) {
  const std::vector<double> t = nodes(s);
  std::vector<Vec3> b = s.points("B");
  Joined out{{segment(b, 0, t)}, {}};
  const int k = condition == 0 ? 0 : condition == 3 ? 2 : 1;
  for (int i = 1; i < kSegments; ++i) {
    const BezierCurve& prev = out.segments.back();
    const double length = condition == 1 ? (prev.b - prev.a) / s.get("g1_factor") : t[i + 1] - t[i];
    out.joints.push_back(gllab::spline::continuation_points(prev, k, length));
    for (int r = 0; r <= k; ++r) b[3 * i + r] = out.joints.back().points[r];
    out.segments.push_back(segment(b, i, t));
  }
  return out;
}

// The interpolating spline through the joints (seed 000 §1.6, three steps):
// b1 and b11 from the list (chosen) or natural ends.
std::vector<BezierCurve> through_joints(const gllab::State& s, bool natural) {
  const std::vector<Vec3>& b = s.points("B");
  std::vector<Vec3> p;
  for (int i = 0; i <= kSegments; ++i) p.push_back(b[3 * i]);
  auto segments = natural ? gllab::spline::bezier_spline_through(nodes(s), p, gllab::spline::EndCondition::kNatural)
                          : gllab::spline::bezier_spline_through(nodes(s), p, b[1], b[3 * kSegments - 1]);
  for (BezierCurve& c : segments) c.dimension = 2;
  return segments;
}

std::vector<Vec3> points_of(const std::vector<BezierCurve>& segments) {
  return gllab::spline::from_bezier_segments(segments).P;
}

// Drawing --------------------------------------------------------------------
using gllab::format_text;

// The segments in alternating colours over their dashed control polygons,
// the constructed points as dots, the free ones draggable.
void draw_spline(const gllab::State& s, const std::vector<BezierCurve>& segments, const std::vector<std::size_t>& free) {
  for (std::size_t i = 0; i < segments.size(); ++i) {
    gllab::draw_dashed_polyline(segments[i].P, kLine);
    gllab::draw_curve(segments[i], kSegmentInk[i % 2], 2.5f);
  }
  const std::vector<Vec3> b = points_of(segments);
  gllab::draw_dots(b, kMade, 7.f);
  gllab::draw_control_points(s, "B", free, kFree);
  if (s.flag("labels"))
    for (std::size_t i = 0; i < b.size(); ++i)
      gllab::draw_label(b[i].x, b[i].y, 0, std::to_string(i),
                        std::find(free.begin(), free.end(), i) != free.end() ? kFree : kMade, 12, -12);
}

// What each joint has in common: the tangent angle, the speeds |S'| and the
// jump of S'' (core: bezier_end_derivative / bezier_start_derivative).
std::vector<std::string> joint_report(const std::vector<BezierCurve>& segments) {
  std::vector<std::string> lines;
  for (std::size_t i = 1; i < segments.size(); ++i) {
    const Vec3 d1a = bezier_end_derivative(segments[i - 1], 1), d1b = bezier_start_derivative(segments[i], 1);
    const Vec3 d2a = bezier_end_derivative(segments[i - 1], 2), d2b = bezier_start_derivative(segments[i], 2);
    const double angle = std::fabs(std::atan2(cross(d1a, d1b).z, dot(d1a, d1b))) * 180 / M_PI;
    lines.push_back(format_text("b%zu: angle %5.1f deg  |S'| %.2f|%.2f  S'' jump %.2f", 3 * i, angle, norm(d1a),
                                norm(d1b), norm(d2b - d2a)));
  }
  return lines;
}

void draw_joining(const gllab::State& s, int condition) {
  const Joined j = joined(s, condition);
  // Free: everything in C0; G1 and C1 make b_{3i+1}, C2 also b_{3i+2}.
  std::vector<std::size_t> free;
  for (std::size_t i = 0; i <= 3 * kSegments; ++i)
    if (i < 4 || condition == 0 || i % 3 == 0 || (i % 3 == 2 && condition != 3)) free.push_back(i);
  if (s.flag("construction"))
    for (const auto& joint : j.joints)  // each level's point lies on a line through two of the previous
      for (std::size_t r = 1; r < joint.levels.size(); ++r)
        for (std::size_t k = 0; k < joint.levels[r].size(); ++k)
          gllab::draw_polyline({joint.levels[r - 1][k], joint.levels[r - 1][k + 1], joint.levels[r][k]}, kLine, 1.f);
  for (const auto& joint : j.joints)
    if (joint.levels.size() == 3) gllab::draw_dots({joint.levels[1][0]}, kDeBoor, 8.f);  // the de Boor point d
  draw_spline(s, j.segments, free);
  if (!s.flag("labels")) return;
  const std::vector<double> t = nodes(s);
  const char* rule[] = {"C0: b_{3i} shared, nothing else",
                        "G1: b_{3i} - b_{3i-1} = k (b_{3i+1} - b_{3i})",
                        "C1: (b_{3i} - b_{3i-1}) / D_{i-1} = (b_{3i+1} - b_{3i}) / D_i",
                        "C2: also S'' equal: b_{3i+2} from d (green)"};
  std::vector<std::string> lines = {
      rule[condition], format_text("nodes %s: D_i = %.2f %.2f %.2f %.2f", parameterization_name(kNodes[s.integer("nodes")]),
                                   t[1] - t[0], t[2] - t[1], t[3] - t[2], t[4] - t[3])};
  if (condition == 1) lines.push_back(format_text("k = %.2f", s.get("g1_factor")));
  for (const std::string& l : joint_report(j.segments)) lines.push_back(l);
  gllab::draw_text_panel(8, 8, lines, kText);
}

void draw_de_boor_points(const gllab::State& s) {
  const std::vector<Vec3>& b = s.points("B");
  std::vector<Vec3> p;
  for (int i = 0; i <= kSegments; ++i) p.push_back(b[3 * i]);
  const std::vector<Vec3> d = gllab::spline::de_boor_points_through(nodes(s), p, b[1], b[3 * kSegments - 1]);
  gllab::draw_dashed_polyline(d, kDeBoor, 1.5f);
  gllab::draw_dots(d, kDeBoor, 10.f);
  draw_spline(s, through_joints(s, false), {0, 1, 3, 6, 9, 11, 12});
  if (!s.flag("labels")) return;
  for (std::size_t i = 0; i < d.size(); ++i) gllab::draw_label(d[i].x, d[i].y, 0, "d" + std::to_string(i), kDeBoor, -14, 14);
  gllab::draw_text_panel(8, 8, {"1) choose b1 and b11 (drag them)", "2) solve for the de Boor points d0..d4",
                                "3) b_3i+1, b_3i+2 divide the leg d_i d_i+1", "   in the ratio D_i-1 : D_i : D_i+1"},
                         kText);
}

void draw_end_conditions(const gllab::State& s) {
  const std::vector<BezierCurve> chosen = through_joints(s, false), natural = through_joints(s, true);
  for (int row = 0; row < 2; ++row) {
    glPushMatrix();
    glTranslated(0, row ? -1.7 : 1.5, 0);
    glScaled(0.8, 0.8, 1);
    for (const BezierCurve& c : row ? chosen : natural) gllab::draw_curve(c, kLine, 1.f);  // the other one, thin
    if (row == 0) draw_spline(s, chosen, {0, 1, 3, 6, 9, 11, 12});
    else draw_spline(s, natural, {0, 3, 6, 9, 12});
    glPopMatrix();
    if (s.flag("labels"))
      gllab::draw_label(0, row ? -0.25 : 3.05, 0, row ? "natural ends: S''(t0) = S''(t4) = 0" : "b1 and b11 as chosen",
                        kText);
  }
}

// init / display ----------------------------------------------------------
void init() { glClearColor(0.12f, 0.13f, 0.16f, 1.f); }

void display(const gllab::State& s) {
  glClear(GL_COLOR_BUFFER_BIT);
  gllab::ortho_fit(s.width, s.height, 3.4, 3.4);
  if (s.view() == "end_conditions") draw_end_conditions(s);
  glTranslated(0, -0.5, 0);  // below the text panel
  if (s.view() == "de_boor_points") draw_de_boor_points(s);
  else if (s.view_index() < 4) draw_joining(s, static_cast<int>(s.view_index()));
  if (s.flag("labels"))
    gllab::draw_text_panel(8, s.height - 28, {"yellow: free, drag them   pink: made by the condition"}, kText);
}

// The curve on screen as one B-spline (joints of multiplicity 3): Ctrl+S saves it.
gllab::Model model(const gllab::State& s) {
  const std::size_t v = s.view_index();
  return gllab::spline::from_bezier_segments(v < 4 ? joined(s, static_cast<int>(v)).segments : through_joints(s, false));
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{"12_bezier_splines",
                 "lab 12 · Bézier splines",
                 {{"joining_c0", "four cubic segments sharing their end points only"},
                  {"joining_g1", "G1: the next inner point on the tangent line, k times shorter"},
                  {"joining_c1", "C1: the next inner point at D_i / D_i-1 of the last leg"},
                  {"joining_c2", "C2: two points made per joint, through the de Boor point"},
                  {"de_boor_points", "the interpolating spline: de Boor points and Bézier points"},
                  {"end_conditions", "b1, b11 as chosen vs natural ends, one above the other"}},
                 {{"nodes", 0, 0, 2, "node spacing D_i: 0 uniform, 1 chordal, 2 centripetal"},
                  {"g1_factor", 2, 0.25, 4, "G1: b_3i - b_3i-1 = k (b_3i+1 - b_3i)"},
                  {"construction", 1, 0, 1, "draw the lines the conditions put points on"},
                  {"labels", 1, 0, 1, "point numbers, formulas and measurements"}},
                 {{'t', "nodes: next spacing", "nodes", +1},
                  {'T', "nodes: previous spacing", "nodes", -1},
                  {'k', "G1 factor k +0.25", "g1_factor", +0.25},
                  {'K', "G1 factor k -0.25", "g1_factor", -0.25},
                  {'c', "construction lines on/off", "construction"},
                  {'n', "labels on/off", "labels"}},
                 init,
                 display};
  lab.points = {{"B", kBezierPoints, "Bézier points b0..b12 (joints b0, b3, ..., b12)"}};
  lab.model = model;
  return lab;
}
