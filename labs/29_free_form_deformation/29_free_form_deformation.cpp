// lab 29 · free-form deformation                                 difficulty: ★★★★
// The Utah teapot in a lattice whose control points move (Sederberg and Parry 1986; lecture
// notes ch. 1, §1.7 Surface representations, "Morphing": "B-spline volumes, which are called
// free-form deformations (FFDs)"). Every vertex goes to X(s, t, u), the volume at its place in
// the box, every normal through cof J = det(J) J^-T, the inverse transpose of the Jacobian. The
// same 5 x 5 x 5 points drive a Bernstein lattice (degree 4) and a cubic B-spline lattice.
// Notice: pull one point and the Bernstein teapot moves everywhere (global control), the
//   B-spline teapot only near it (local). det J < 1 shrinks (blue), > 1 grows (red).
// Try: in global_vs_local, drag the point above the spout: how much of each teapot follows?
//   In normals, press [r] a few times: where do the face-averaged normals go wrong first?
// Keys: [r]/[R] teapot resolution  [l] lattice  [c] det J colours
//   left-drag lattice points  right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: global_vs_local, bend, twist, normals, volume_change, fold
// Reference: reference_images/29_free_form_deformation__*.png

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "deform/fast_deform.h"
#include "gl/ffd_view.h"
#include "gl/gl.h"
#include "gl/panels.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"

namespace {

namespace df = gllab::deform;
using gllab::Rgb, gllab::State, gllab::kOrbit;
using gllab::spline::Vec3;

// Lab data (edit me) -------------------------------------------------------
constexpr int kPoints = 5;  // lattice points per direction: 5 x 5 x 5
constexpr int kDegree = 3;  // of the B-spline lattices (the Bernstein one has kPoints - 1)
const df::Frame kBox = df::box_frame({-3.3, -2.3, -.2}, {3.7, 2.3, 3.4});  // round the teapot
const Vec3 kCentre{.2, 0, 1.6}, kLookAt{.7, 0, 1.8};  // the box's centre, the picture's
// global_vs_local: the point above the spout, (i, j, k) = (4, 2, 4), pulled out and up.
constexpr int kPulled = (4 * kPoints + 2) * kPoints + 4;
const Vec3 kPull{1.6, 0, .5};
constexpr double kBendDegrees = 80;   // bend: the box's length bent into an arc this wide
constexpr double kTwistDegrees = 90;  // twist: the top turned this far against the bottom
constexpr int kFolded = (2 * kPoints + 2) * kPoints + 4;  // fold: the top centre point ...
const Vec3 kFoldBy{0, 0, -5};                             // ... pushed down through the lid
const Rgb kClay{.86f, .62f, .42f}, kNet{.6f, .75f, .9f}, kText{1, 1, 1}, kRed{1, .4f, .35f};
// The lattices: the identity of the box (Bernstein: degree 0 here), their points moved.
df::Lattice cube(int degree) { return gllab::cube_lattice(kBox, kPoints, degree); }
std::vector<Vec3> moved(int degree, int point, Vec3 by) {
  std::vector<Vec3> P = cube(degree).volume.P;
  P[point] += by;
  return P;
}
// bend: every point onto an arc about the line y = 0, z = centre + r; the middle keeps its
// length (the arc is the box's length), the top shortens, the bottom stretches.
std::vector<Vec3> bent() {
  const double r = 7 / (kBendDegrees * M_PI / 180), top = kCentre.z + r;
  return gllab::lattice_points(cube(kDegree), [=](Vec3 x) {
    const double a = (x.x - kCentre.x) / r, d = top - x.z;  // d: from the arc's centre
    return Vec3{kCentre.x + d * std::sin(a), x.y, top - d * std::cos(a)};
  });
}
// twist: every point turned about the vertical axis through the centre, in proportion to z.
std::vector<Vec3> twisted() {
  return gllab::lattice_points(cube(kDegree), [](Vec3 x) {
    const double a = kTwistDegrees * M_PI / 180 * (x.z - kCentre.z) / 3.6, dx = x.x - kCentre.x;
    return Vec3{kCentre.x + dx * std::cos(a) - x.y * std::sin(a),
                dx * std::sin(a) + x.y * std::cos(a), x.z};
  });
}

// Drawing -----------------------------------------------------------------------------------
// The deformed teapot through vertex arrays: positions X(s, t, u), the normals given, one
// colour per vertex when `colours` has them (GL_COLOR_MATERIAL: they are lit).
void draw_mesh(const gllab::IndexedMesh& m, const std::vector<float>& normals,
               const std::vector<float>& colours) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, m.positions.data());
  glEnableClientState(GL_NORMAL_ARRAY);
  glNormalPointer(GL_FLOAT, 0, normals.data());
  if (!colours.empty()) glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(3, GL_FLOAT, 0, colours.data());
  glColor3f(kClay.r, kClay.g, kClay.b);
  glDrawElements(GL_TRIANGLES, GLsizei(m.indices.size()), GL_UNSIGNED_INT, m.indices.data());
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

// The teapot (deform/teapot.h) through the lattice of point list `list`: Bernstein (degree 0)
// or B-spline. deform_mesh (ffd.h) computes it; deform_mesh_fast the same, 15 times faster.
struct Deformed {
  df::Lattice lattice;
  df::DeformedMesh d;
  double ms;  // how long the deformation took (shown in the window only)
};
Deformed deform(const State& s, const char* list, int degree, int resolution) {
  Deformed r{gllab::with_points(cube(degree), s.points(list)), {}, 0};
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  r.d = df::deform_mesh_fast(r.lattice, gllab::cached_teapot(resolution));
  r.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return r;
}

// Panel `row` of `rows` (one above the other): the teapot lit with `normals` (det J colours when
// asked), the lattice `list` the mouse moves (none: null), captions, the core's warning when
// the lattice folds.
void draw_panel(const State& s, int row, int rows, const char* list, const Deformed& t,
                const std::vector<float>& normals, bool colours, std::vector<std::string> lines) {
  const gllab::Panel p = gllab::enter_panel(0, row, 1, rows, s.width, s.height);
  gllab::ffd_camera(s, p.width, p.height, rows == 1 ? 4.4 : list ? 3.5 : 2.7, kLookAt);
  const GLfloat specular[] = {.5f, .5f, .5f, 1.f};
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);  // highlights show the normals
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.f);
  colours = colours || s.flag("colours");
  draw_mesh(t.d.mesh, normals, colours ? gllab::det_colours(t.d.det) : std::vector<float>{});
  if (list && s.flag("lattice")) {
    gllab::draw_lattice_lines(s.points(list), kPoints, kNet);
    gllab::draw_control_points(s, list, kNet, 6.f);
  }
  lines.push_back(gllab::format_text("det J %.2f .. %.2f", t.d.min_det, t.d.max_det));
  if (s.interactive) lines.push_back(gllab::format_text("deformed in %.1f ms", t.ms));
  gllab::leave_panels(s.width, s.height);
  gllab::draw_text_panel(8, p.window_height - p.y - 16 * int(lines.size()) - 16, lines, kText);
  if (colours) gllab::draw_det_legend(8, 8);
  const df::Fold fold = df::find_fold(t.lattice);
  const std::string which = rows == 1 ? "" : row == 0 ? "top: " : "bottom: ";
  if (fold.folds) gllab::draw_text_panel(8, 40 + 30 * row, {which + df::fold_text(fold)}, kRed);
}

// One lattice of the B-spline kind in the whole window.
void draw_one(const State& s, const char* list, bool colours, const std::string& what) {
  const Deformed t = deform(s, list, kDegree, s.integer("resolution"));
  draw_panel(s, 0, 1, list, t, t.d.mesh.normals, colours, {what});
}

// The same point pulled in a Bernstein lattice (top) and a B-spline lattice (bottom).
void draw_global_vs_local(const State& s) {
  for (const int degree : {0, kDegree}) {
    const char* list = degree ? "Q" : "P";
    const Deformed t = deform(s, list, degree, s.integer("resolution"));
    const gllab::IndexedMesh& before = gllab::cached_teapot(s.integer("resolution"));
    draw_panel(s, degree ? 1 : 0, 2, list, t, t.d.mesh.normals, false,
               {degree ? "B-spline, cubic: local" : "Bernstein, degree 4: global",
                gllab::format_text("%zu of %zu vertices moved", gllab::moved_vertices(
                    before.positions, t.d.mesh.positions), before.vertex_count())});
  }
}
void draw_bend(const State& s) { draw_one(s, "B", false, "bend: the lattice on an arc"); }
void draw_twist(const State& s) { draw_one(s, "T", false, "twist: its layers turned"); }
void draw_volume_change(const State& s) { draw_one(s, "B", true, "the bend: volume change"); }
void draw_fold(const State& s) { draw_one(s, "F", true, "the top point pushed down"); }

// The twisted teapot, at half the resolution, lit with the Jacobian's normals (top) and with
// normals averaged from its deformed triangles (bottom): the same positions, other highlights.
void draw_normals(const State& s) {
  const Deformed t = deform(s, "T", kDegree, std::max(2, s.integer("resolution") / 2));
  const std::vector<float> averaged = df::face_averaged_normals(t.d.mesh);
  const df::AngleStats a = df::normal_angles(t.d.mesh.normals, averaged);
  draw_panel(s, 0, 2, nullptr, t, t.d.mesh.normals, false, {"normals cof(J) n"});
  draw_panel(s, 1, 2, nullptr, t, averaged, false, {"normals from the faces"});
  gllab::draw_text_panel(8, 8, {gllab::format_text("%zu triangles: normals differ by %.2f deg "
      "mean, %.1f max", t.d.mesh.triangle_count(), a.mean_deg, a.max_deg)}, kText);
}

// init ---------------------------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "29_free_form_deformation",
      "lab 29 · free-form deformation",
      {{"global_vs_local", "one lattice point pulled: Bernstein (global), B-spline (local)",
        draw_global_vs_local, kOrbit},
       {"bend", "the bend preset", draw_bend, kOrbit},
       {"twist", "the twist preset", draw_twist, kOrbit},
       {"normals", "Jacobian normals beside normals averaged from the faces", draw_normals, kOrbit},
       {"volume_change", "det J as colour: blue shrinks, red grows", draw_volume_change, kOrbit},
       {"fold", "a point pushed down through its neighbours: det J <= 0", draw_fold, kOrbit}},
      {{"resolution", 8, 2, 56, "teapot samples per patch side (56: about 10^5 vertices)"},
       {"lattice", 1, 0, 1, "lattice lines and points"},
       {"colours", 0, 0, 1, "det J colours in every view"}},
      {{'r', "coarser teapot (-2)", "resolution", -2}, {'R', "finer teapot (+2)", "resolution", +2},
       {'l', "lattice on/off", "lattice"}, {'c', "det J colours on/off", "colours"}},
      init};
  lab.points = {{"P", moved(0, kPulled, kPull), "Bernstein lattice, P[(5 i + j) 5 + k]", 3},
                {"Q", moved(kDegree, kPulled, kPull), "B-spline lattice, the same point pulled", 3},
                {"B", bent(), "the bend preset's lattice", 3},
                {"T", twisted(), "the twist preset's lattice", 3},
                {"F", moved(kDegree, kFolded, kFoldBy), "the fold's lattice", 3}};
  return lab;
}
