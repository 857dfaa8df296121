// lab 28 · image morphing                                        difficulty: ★★★☆
// Face A becomes face B as the lecture notes morph pictures (ch. 1, §1.7 Surface
// representations, "Deformation" and "Morphing"): a deformation f2 of the unit square, a
// bicubic B-spline over a 12 x 12 control grid, carries the features picked in A onto B's. The
// geometry moves as f(t, x) = (1 - t) x + t f2(x) while the colours blend. Each picture is a
// texture on a quad mesh: the vertices move to f(t, x), the texture coordinates stay.
// Notice: the cross-fade (1 - t) A + t B shows two faces at once (ghosting: two pairs of
//   eyes, two mouths); the morph shows one face in between. At t = 0 it is A, at t = 1 B.
// Try: in deformation, drag the grid point nearest an eye: what follows it, and how far? Drag
//   it across its neighbour: what does the warning say, and what happens to the face?
// Keys: [t]/[T] t  [m]/[M] mesh cells  [g] grid lines  [f] features
//   left-drag grid points  [h] help  [Esc] quit
// Views: deformation, morph, cross_fade_vs_morph, sequence, fold
// Reference: reference_images/28_image_morphing__*.png

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "deform/plane.h"
#include "gl/gl.h"
#include "gl/morph_view.h"
#include "gl/panels.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"
#include "image/pictures.h"

namespace {

namespace df = gllab::deform;
using df::Vec2;
using gllab::Rgb, gllab::State;
using gllab::spline::Vec3;

// Lab data (edit me) -------------------------------------------------------
// Features picked in face A and the same features in face B, in the unit square (x right, y
// up); build/bin/make_faces --features prints them. f2 must carry each A point onto its B point.
// Top of the head, brows (left, right), eyes, the face's sides, nose tip, mouth (corners,
// centre), chin.
const Vec2 kFeaturesA[] = {
    {.5, .875},        {.4140625, .685546875}, {.5859375, .685546875}, {.4140625, .609375},
    {.5859375, .609375}, {.1640625, .46875},   {.8359375, .46875},     {.5, .5},
    {.40625, .390625}, {.59375, .390625},      {.5, .34375},           {.5, .1328125}};
const Vec2 kFeaturesB[] = {
    {.5, .890625},     {.34375, .57421875},    {.65625, .57421875},    {.34375, .4921875},
    {.65625, .4921875}, {.2265625, .484375},   {.7734375, .484375},    {.5, .359375},
    {.359375, .2578125}, {.640625, .2578125},  {.5, .224609375},       {.5, .1171875}};
constexpr int kGrid = 12, kDegree = 3;  // f2: a bicubic B-spline, kGrid x kGrid control points
// fold: grid point kFold (i = 6 along x, j = 5 along y) pulled right, past its neighbour.
constexpr std::size_t kFold = 6 * kGrid + 5;
const Vec3 kFoldBy{.3, .05, 0};
const double kSequence[] = {0, .2, .4, .6, .8, 1};  // sequence: t of each panel
const Rgb kText{1, 1, 1}, kLines{1.f, 1.f, .45f}, kNet{.8f, .8f, .9f}, kGreen{.25f, 1.f, .4f},
    kRed{1.f, .3f, .3f};

GLuint g_faces[2];  // the textures of face A and face B, made in init()

// The grid the mouse starts from: the identity, its inner points moved as smoothly as they can
// be so that f2 carries every feature of A onto B's (deform/plane.h fit_features).
const std::vector<Vec2> kA(std::begin(kFeaturesA), std::end(kFeaturesA)),
    kB(std::begin(kFeaturesB), std::end(kFeaturesB));
std::vector<Vec3> fitted_grid() {
  return gllab::grid_points(df::fit_features(df::identity_plane(kGrid, kGrid, kDegree), kA, kB));
}
// Each view draws with f2 of the grid the mouse moves, and warns when that grid folds.
template <void (*draw)(const State&, const df::PlaneEvaluator&)>
void with_f2(const State& s) {
  const df::PlaneDeformation f = gllab::grid_deformation(s.points("G"), kGrid, kDegree);
  draw(s, df::PlaneEvaluator(f));
  gllab::draw_fold_warning(f, s.height);
}

// Drawing -------------------------------------------------------------------------------------
// A picture as a texture on a cells x cells quad mesh of the unit square: mesh point x is drawn
// at f(t, x) = (1 - t) x + t f2(x) with texture coordinate x, or with `at_f2` f2(x). GL_MODULATE
// multiplies each texel by the colour (1, 1, 1, alpha).
void draw_picture(GLuint face, const df::PlaneEvaluator& f2, double t, bool at_f2, int cells,
                  double alpha = 1) {
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, face);
  glColor4d(1, 1, 1, alpha);
  for (int i = 0; i < cells; ++i) {
    glBegin(GL_QUAD_STRIP);  // the column of cells between x = i / cells and (i + 1) / cells
    for (int j = 0; j <= cells; ++j)
      for (const int k : {i + 1, i}) {
        const Vec2 x{double(k) / cells, double(j) / cells}, f = f2(x).f;
        const Vec2 uv = at_f2 ? f : x;
        glTexCoord2d(uv.x, uv.y);
        glVertex2d((1 - t) * x.x + t * f.x, (1 - t) * x.y + t * f.y);
      }
    glEnd();
  }
  glDisable(GL_TEXTURE_2D);
}

// A opaque, then B over it with alpha t: every pixel becomes (1 - t) A + t B. The morph draws
// both at f(t, x), B's texels taken at f2(x); the cross-fade leaves both where they are.
void draw_blend(const State& s, const df::PlaneEvaluator& f2, double t, bool morph) {
  const int cells = s.integer("cells");
  draw_picture(g_faces[0], f2, morph ? t : 0, false, cells);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);  // new = alpha B + (1 - alpha) old
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);    // the picture itself stays opaque
  draw_picture(g_faces[1], f2, morph ? t : 0, morph, cells, t);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_BLEND);
}

// The notes' "Deformation": face A with its features (left); A through f2 (right) with the
// control grid the mouse moves, A's features carried by f2 (green) onto B's (red).
void draw_deformation(const State& s, const df::PlaneEvaluator& f2) {
  const gllab::Panel left = gllab::enter_panel(0, 0, 2, 1, s.width, s.height);
  gllab::enter_unit_square(left.width, left.height);
  draw_picture(g_faces[0], f2, 0, false, s.integer("cells"));
  if (s.flag("features")) gllab::draw_moved_points(f2, 0, kA, kGreen, 6.f);
  const gllab::Panel right = gllab::enter_panel(1, 0, 2, 1, s.width, s.height);
  gllab::enter_unit_square(right.width, right.height);
  draw_picture(g_faces[0], f2, 1, false, s.integer("cells"));
  if (s.flag("features")) gllab::draw_moved_points(f2, 0, kB, kRed, 11.f);
  if (s.flag("features")) gllab::draw_moved_points(f2, 1, kA, kGreen, 6.f);
  gllab::draw_control_net(gllab::inner_net(s.points("G"), kGrid), kGrid - 2, kGrid - 2, kNet);
  gllab::draw_control_points(s, "G", gllab::inner_grid_points(kGrid), kNet, 7.f);
  gllab::leave_panels(s.width, s.height);
  gllab::draw_panel_caption(left, -7, "face A, its features", kText);
  gllab::draw_panel_caption(right, -7, "A through f2: green onto red", kText);
  const double miss = gllab::feature_miss(f2, kA, kB);
  gllab::draw_text_panel(8, 8, {gllab::format_text("f2: bicubic B-spline, %d x %d control points",
      kGrid, kGrid), gllab::format_text("max |f2(p_k) - q_k| = %.4f", miss)}, kText);
}

void draw_morph(const State& s, const df::PlaneEvaluator& f2) {
  const double t = s.get("t");
  gllab::enter_unit_square(s.width, s.height, .12);
  draw_blend(s, f2, t, true);
  if (s.flag("grid_lines")) gllab::draw_deformed_grid(f2, t, 8, kLines);  // lines of f(t, .)
  if (s.flag("features")) gllab::draw_moved_points(f2, t, kA, kGreen, 6.f);
  gllab::draw_text_panel(8, 8, {gllab::format_text("t = %.2f: at f(t, x) = (1 - t) x + t f2(x)",
      t), "the colour (1 - t) A(x) + t B(f2(x))"}, kText);
}

void draw_cross_fade_vs_morph(const State& s, const df::PlaneEvaluator& f2) {
  const double t = s.get("t");
  const char* what[] = {"cross-fade (1 - t) A + t B", "morph: both at f(t, x)"};
  for (int k = 0; k < 2; ++k) {
    const gllab::Panel p = gllab::enter_panel(k, 0, 2, 1, s.width, s.height);
    gllab::enter_unit_square(p.width, p.height);
    draw_blend(s, f2, t, k == 1);
    gllab::draw_panel_caption(p, -7, what[k], kText);
  }
  gllab::leave_panels(s.width, s.height);
  gllab::draw_text_panel(8, 8, {gllab::format_text("t = %.2f", t)}, kText);
}

void draw_sequence(const State& s, const df::PlaneEvaluator& f2) {
  for (int k = 0; k < 6; ++k) {
    const gllab::Panel p = gllab::enter_panel(k % 3, k / 3, 3, 2, s.width, s.height);
    gllab::enter_unit_square(p.width, p.height, .06);
    draw_blend(s, f2, kSequence[k], true);
    gllab::draw_panel_caption(p, -1, gllab::format_text("t = %.1f", kSequence[k]), kText);
  }
  gllab::leave_panels(s.width, s.height);
}

// One grid point dragged across its neighbour: f2 folds, the mesh overlaps itself, and the
// backward warp the core's morph needs has no unique answer there.
void draw_fold(const State& s) {
  std::vector<Vec3> grid = s.points("G");
  grid[kFold] += kFoldBy;
  const df::PlaneDeformation f = gllab::grid_deformation(grid, kGrid, kDegree);
  const df::PlaneFold fold = df::find_plane_fold(f);
  gllab::enter_unit_square(s.width, s.height, .12);
  draw_picture(g_faces[0], df::PlaneEvaluator(f), 1, false, s.integer("cells"));
  gllab::draw_control_net(gllab::inner_net(grid, kGrid), kGrid - 2, kGrid - 2, kNet);
  gllab::draw_dots({{fold.at.x, fold.at.y, 0}}, kRed, 12.f);
  gllab::draw_text_panel(8, 8, {gllab::format_text("grid point %zu moved by (%.2f, %.2f)", kFold,
      kFoldBy.x, kFoldBy.y), "where det J <= 0, f2 turns the picture over"}, kText);
  gllab::draw_fold_warning(f, s.height);
}

// init / shutdown -------------------------------------------------------------------------------
void init() {
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
  glGenTextures(2, g_faces);
  for (int k = 0; k < 2; ++k) {
    const gllab::Image im = gllab::embedded_picture(k ? gllab::Picture::kFaceB
                                                       : gllab::Picture::kFaceA);
    // A texture's rows run from t = 0 at the bottom, the picture's from the top: flip them.
    std::vector<GLubyte> rows(im.rgba.size());
    for (int y = 0; y < im.height; ++y)
      std::copy_n(im.pixel(0, im.height - 1 - y), 4 * im.width,
                  &rows[4 * std::size_t(im.width) * y]);
    glBindTexture(GL_TEXTURE_2D, g_faces[k]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, im.width, im.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 rows.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);  // one level, no mipmaps
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glBindTexture(GL_TEXTURE_2D, 0);
}
void shutdown() { glDeleteTextures(2, g_faces); }

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  gllab::Lab lab{
      "28_image_morphing",
      "lab 28 · image morphing",
      {{"deformation", "face A and A through f2: its features on B's", with_f2<draw_deformation>},
       {"morph", "the morph at t, with the grid lines of f(t, x)", with_f2<draw_morph>},
       {"cross_fade_vs_morph", "the cross-fade (ghosting) beside the morph at the same t",
        with_f2<draw_cross_fade_vs_morph>},
       {"sequence", "the morph at t = 0, 0.2, ..., 1", with_f2<draw_sequence>},
       {"fold", "a grid point dragged across its neighbour: f2 folds", draw_fold}},
      {{"t", 0.5, 0, 1, "the morph's t: 0 face A, 1 face B"},
       {"cells", 32, 4, 64, "quad mesh cells per side"},
       {"grid_lines", 1, 0, 1, "the lines of f(t, x)"},
       {"features", 1, 0, 1, "feature points"}},
      {{'t', "t +0.05", "t", +0.05}, {'T', "t -0.05", "t", -0.05},
       {'m', "mesh cells -4", "cells", -4}, {'M', "mesh cells +4", "cells", +4},
       {'g', "grid lines on/off", "grid_lines"}, {'f', "feature points on/off", "features"}},
      init};
  lab.shutdown = shutdown;
  lab.points = {{"G", fitted_grid(), "f2's control grid c_ij = G[12 i + j]", 2}};
  return lab;
}
