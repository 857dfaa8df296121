// lab 06 · polygon mesh                                      difficulty: ★★☆☆
// The seed's mesh data structure (§1.2): object → surfaces → polygons → edges
// → vertices, each vertex stored once (common/mesh/polygon_mesh.h), drawn flat
// and smooth, with sharp feature edges and resolution chosen by curvature.
// Notice: a sharp edge costs vertices. The cube's 8 corners become 24 render
//   vertices, because each corner needs one normal per face that meets there.
// Try: set the feature angle to 180 in feature_edges ([ ]). Where does the
//   machined part turn soft, and why do its flat caps get dark rims?
// Keys: [r]/[R] spin  [+]/[-] slices  [ and ] feature angle  [s]/[S] segments
//       [e] edges  [n] normals  [l] labels  [h] help  [Esc] quit
// Views: flat_vs_gouraud, feature_edges, by_curvature, data_structure
// Reference: reference_images/06_polygon_mesh__*.png

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/scene.h"
#include "harness/lab.h"
#include "mesh/polygon_mesh.h"

namespace {

using gllab::EdgeType;
using gllab::Normals;
using gllab::PolygonMesh;

// Lab data (edit me) -------------------------------------------------------
// A turned (machined) part: its profile (r, z) from the bottom centre to the
// top centre: a shaft, a shoulder, a thinner shaft, a 45 degree chamfer.
const std::vector<gllab::ProfilePoint> kPartProfile = {
    {0, -.9}, {.9, -.9}, {.9, 0}, {.55, 0}, {.55, .6}, {.4, .75}, {0, .75}};
const gllab::Surface kSteel{"part", {.75f, .75f, .8f}}, kClay{"sphere", {.9f, .5f, .35f}},
    kJade{"lentil", {.5f, .8f, .55f}};

// A flattened ellipsoid (a lentil): half-ellipse profile, radius kA, half-height kB.
// Its curvature is kA/kB^2 = 11 at the rim but kB/kA^2 = 0.3 at the poles.
constexpr double kA = 1.0, kB = 0.3;
constexpr int kDenseProfile = 2000;    // samples the resampling picks from
constexpr double kCurvatureShare = 0.8;  // 0 = uniform along the curve, 1 = curvature only

// A cube whose top is split into two triangles: the diagonal is a virtual edge.
const std::vector<gllab::Vec3> kCube = {{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}, {1, 1, -1},
                                        {-1, -1, 1},  {1, -1, 1},  {-1, 1, 1},  {1, 1, 1}};
const std::vector<gllab::PolygonInput> kCubeFaces = {  // counter-clockwise from outside
    {{0, 2, 3, 1}}, {{4, 5, 7}, 1}, {{4, 7, 6}, 1}, {{0, 1, 5, 4}}, {{2, 6, 7, 3}}, {{0, 4, 6, 2}}, {{1, 3, 7, 5}}};
const std::vector<gllab::Surface> kCubeSurfaces = {{"box", {.6f, .6f, .65f}}, {"lid", {.45f, .55f, .75f}}};  // 0, 1

const gllab::Rgb kText{1.f, 1.f, 1.f}, kFeature{1.f, .45f, .15f}, kVirtual{.3f, .8f, 1.f};

// Profiles ------------------------------------------------------------------
// Half an ellipse from the south pole to the north pole in n equal angle steps;
// revolved, a = b gives a sphere. The poles get r = 0 exactly.
std::vector<gllab::ProfilePoint> half_ellipse(double a, double b, int n) {
  std::vector<gllab::ProfilePoint> profile;
  for (int i = 0; i <= n; ++i) {
    const double t = M_PI * i / n - M_PI / 2;
    profile.push_back({i == 0 || i == n ? 0 : a * std::cos(t), b * std::sin(t)});
  }
  return profile;
}

// Drawing -------------------------------------------------------------------
void draw_arrays(const gllab::IndexedMesh& m) {
  for (GLenum array : {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY}) glEnableClientState(array);
  glVertexPointer(3, GL_FLOAT, 0, m.positions.data());
  glNormalPointer(GL_FLOAT, 0, m.normals.data());
  glColorPointer(3, GL_FLOAT, 0, m.colours.data());
  // Push the fill back a little so edges drawn on top of it win the depth test.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.f, 1.f);
  glDrawElements(GL_TRIANGLES, GLsizei(m.indices.size()), GL_UNSIGNED_INT, m.indices.data());
  glDisable(GL_POLYGON_OFFSET_FILL);
  for (GLenum array : {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY}) glDisableClientState(array);
}

// The edges for which `show` is true, as lines; dashed when asked.
template <typename Show>
void draw_edges(const PolygonMesh& m, Show show, gllab::Rgb c, float width, bool dashed) {
  glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT);
  glDisable(GL_LIGHTING);
  glLineWidth(width);
  if (dashed) glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x3333);
  glColor3f(c.r, c.g, c.b);
  glBegin(GL_LINES);
  for (const gllab::Edge& e : m.edges)
    for (std::size_t v : {e.v0, e.v1})
      if (show(e)) glVertex3d(m.vertices[v].position.x, m.vertices[v].position.y, m.vertices[v].position.z);
  glEnd();
  glPopAttrib();
}
bool is_feature(const gllab::Edge& e) { return e.type == EdgeType::kFeature; }
bool is_virtual(const gllab::Edge& e) { return e.type == EdgeType::kVirtual; }

// Short white lines along the normals sent to GL, one per render vertex.
void draw_normals(const gllab::IndexedMesh& m, float length) {
  glDisable(GL_LIGHTING);
  glColor3f(1.f, 1.f, 1.f);
  glBegin(GL_LINES);
  for (std::size_t i = 0; i < m.positions.size(); i += 3) {
    const float *p = &m.positions[i], *n = &m.normals[i];
    glVertex3fv(p);
    glVertex3f(p[0] + length * n[0], p[1] + length * n[1], p[2] + length * n[2]);
  }
  glEnd();
  glEnable(GL_LIGHTING);
}

// Panel `side` (0 left, 1 right): z up, seen `tilt` degrees from above, turned by spin.
void enter_panel(int side, double y, double tilt, double scale, const gllab::State& s) {
  glPushMatrix();
  glTranslated(side ? 1.25 : -1.25, y, 0);
  glRotated(tilt - 90, 1, 0, 0);
  glRotated(s.get("spin"), 0, 0, 1);
  glScaled(scale, scale, scale);
}

// The panel's title above it and its counts (taken from the data) below.
void caption(int side, const std::string& title, const std::vector<std::string>& counts, const gllab::State& s) {
  if (!s.flag("labels")) return;
  gllab::draw_label(side ? 1.25 : -1.25, 1.75, 0, title, kText);
  gllab::draw_text_panel(side ? s.width / 2 + 8 : 8, s.height - 64, counts, kText);
}

std::string str(std::size_t n) { return std::to_string(n); }

void draw_flat_vs_gouraud(const gllab::State& s) {
  const int slices = s.integer("slices");
  const PolygonMesh m = gllab::make_surface_of_revolution(half_ellipse(1, 1, slices / 2), slices, {kClay});
  for (int side = 0; side < 2; ++side) {
    const gllab::IndexedMesh arrays = render_arrays(m, side ? Normals::kAveraged : Normals::kFace);
    // GL_FLAT fills a triangle with the colour lit at its last vertex; GL_SMOOTH
    // interpolates the colours lit at all three (Gouraud). Why do the flat arrays
    // repeat each vertex per polygon? (Its last vertex must carry that face's normal.)
    glShadeModel(side ? GL_SMOOTH : GL_FLAT);
    enter_panel(side, -0.15, 20, 1.0, s);
    draw_arrays(arrays);
    if (s.flag("normals")) draw_normals(arrays, 0.25f);
    glPopMatrix();
    caption(side, side ? "GL_SMOOTH, vertex normals" : "GL_FLAT, face normals",
            {str(m.polygons.size()) + " polygons", str(m.vertices.size()) + " vertices stored",
             str(arrays.vertex_count()) + " sent to GL"}, s);
  }
}

void draw_feature_edges(const gllab::State& s) {
  PolygonMesh m = gllab::make_surface_of_revolution(kPartProfile, s.integer("slices"), {kSteel});
  const std::size_t features = classify_edges(m, s.get("feature_angle"));
  for (int side = 0; side < 2; ++side) {
    // Right: one normal per stored vertex, averaged across the rims as well.
    const gllab::IndexedMesh arrays = render_arrays(m, side ? Normals::kAveraged : Normals::kSplitFeatures);
    enter_panel(side, -0.15, 20, 1.05, s);
    draw_arrays(arrays);
    if (s.flag("edges") && side == 0) draw_edges(m, is_feature, kFeature, 2.f, false);
    if (s.flag("normals")) draw_normals(arrays, 0.2f);
    glPopMatrix();
    caption(side, side ? "averaged across all edges" : "split at feature edges",
            {side ? "no feature edges" : str(features) + " feature edges (> " + str(s.integer("feature_angle")) + " deg)",
             str(m.vertices.size()) + " vertices stored", str(arrays.vertex_count()) + " sent to GL"}, s);
  }
}

// The lentil's cross-section flat on the screen: the true ellipse in red and
// the profile polygon (mirrored for the left half) filled on top of it, so the
// red that shows is shape the polygons miss. The profile points are dots.
void draw_section(const std::vector<gllab::ProfilePoint>& profile) {
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glColor3f(1.f, .3f, .2f);
  glBegin(GL_TRIANGLE_FAN);
  for (int i = 0; i < kDenseProfile; ++i)
    glVertex2d(kA * std::cos(2 * M_PI * i / kDenseProfile), kB * std::sin(2 * M_PI * i / kDenseProfile));
  glEnd();
  glColor3f(.3f, .55f, .35f);
  glBegin(GL_TRIANGLE_FAN);  // the section is convex: a fan covers it
  for (const gllab::ProfilePoint& p : profile) glVertex2d(p.r, p.z);
  for (auto p = profile.rbegin() + 1; p + 1 != profile.rend(); ++p) glVertex2d(-p->r, p->z);
  glEnd();
  glColor3f(.6f, 1.f, .65f);
  glPointSize(5.f);
  glBegin(GL_POINTS);
  for (const gllab::ProfilePoint& p : profile)
    for (double sign : {-1.0, 1.0}) glVertex2d(sign * p.r, p.z);
  glEnd();
  glPopAttrib();
}

void draw_by_curvature(const gllab::State& s) {
  const auto dense = half_ellipse(kA, kB, kDenseProfile);
  for (int side = 0; side < 2; ++side) {
    // The same number of profile segments, placed uniformly (left) or mostly by curvature.
    const auto profile = resample_profile(dense, s.integer("segments"), side ? kCurvatureShare : 0.0);
    const PolygonMesh m = gllab::make_surface_of_revolution(profile, s.integer("slices"), {kJade});
    enter_panel(side, 0.45, 15, 1.1, s);
    draw_arrays(render_arrays(m, Normals::kAveraged));
    // The rings (edges at one height) show where the profile points went.
    auto ring = [&m](const gllab::Edge& e) { return m.vertices[e.v0].position.z == m.vertices[e.v1].position.z; };
    if (s.flag("edges")) draw_edges(m, ring, {.1f, .25f, .1f}, 1.f, false);
    glPopMatrix();
    glPushMatrix();
    glTranslated(side ? 1.25 : -1.25, -0.95, 0);
    glScaled(1.1, 1.1, 1.1);
    draw_section(profile);
    glPopMatrix();
    char error[64];
    std::snprintf(error, sizeof error, "max error %.4f (of radius 1)", profile_deviation(dense, profile));
    caption(side, side ? "spaced by curvature" : "spaced uniformly",
            {str(m.triangle_count()) + " triangles", str(profile.size() - 1) + " profile segments",
             error}, s);
  }
}

void draw_data_structure(const gllab::State& s) {
  PolygonMesh m = gllab::build_polygon_mesh(kCube, kCubeFaces, kCubeSurfaces);
  classify_edges(m, s.get("feature_angle"));
  const gllab::IndexedMesh arrays = render_arrays(m, Normals::kSplitFeatures);
  glPushMatrix();
  glTranslated(0, 0.1, 0);
  glRotated(-65, 1, 0, 0);
  glRotated(s.get("spin") + 25, 0, 0, 1);  // three faces in view
  glScaled(0.75, 0.75, 0.75);
  draw_arrays(arrays);
  if (s.flag("edges")) {
    draw_edges(m, is_feature, kFeature, 3.f, false);
    draw_edges(m, is_virtual, kVirtual, 3.f, true);
  }
  if (s.flag("normals")) draw_normals(arrays, 0.5f);
  // Number the polygons that face us (eye-space normal z > 0) and their vertices.
  GLdouble mv[16];
  glGetDoublev(GL_MODELVIEW_MATRIX, mv);
  for (std::size_t p = 0; p < m.polygons.size(); ++p) {
    const gllab::Polygon& poly = m.polygons[p];
    if (mv[2] * poly.normal.x + mv[6] * poly.normal.y + mv[10] * poly.normal.z <= 0) continue;
    gllab::Vec3 centre;
    for (std::size_t v : poly.vertices) {
      centre += m.vertices[v].position / double(poly.vertices.size());
      const gllab::Vec3 q = 1.2 * m.vertices[v].position;  // just outside the corner
      gllab::draw_label(q.x, q.y, q.z, std::to_string(v), kText);
    }
    gllab::draw_label(centre.x, centre.y, centre.z, "p" + std::to_string(p), {1.f, 1.f, .6f});
  }
  glPopMatrix();
  if (!s.flag("labels")) return;
  gllab::draw_label(0, 1.75, 0, "object -> surfaces -> polygons -> edges -> vertices", kText);
  const gllab::Edge& diagonal = m.edges[m.find_edge(4, 7).value()];  // the lid's diagonal
  gllab::draw_text_panel(8, s.height - 112, {
        str(m.surfaces.size()) + " surfaces: " + m.surfaces[0].name + " " + str(m.surfaces[0].polygons.size()) +
            " polygons, " + m.surfaces[1].name + " " + str(m.surfaces[1].polygons.size()),
        "V " + str(m.vertices.size()) + "  E " + str(m.edges.size()) + "  F " + str(m.polygons.size()) +
            "  V-E+F = " + std::to_string(long(m.vertices.size() + m.polygons.size()) - long(m.edges.size())),
        str(m.count(EdgeType::kFeature)) + " feature edges (orange), " + str(m.count(EdgeType::kVirtual)) +
            " virtual (blue, dashed)",
        "edge 4-7 is used by polygons " + str(diagonal.polygons[0]) + " and " + str(diagonal.polygons[1]),
        str(arrays.vertex_count()) + " vertices sent to GL: one per corner and smoothing group"}, kText);
}

// init / display ----------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

void display(const gllab::State& s) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gllab::ortho_fit(s.width, s.height, 2.5, 2.2);
  gllab::enable_headlight();
  const std::string& view = s.view();
  if (view == "flat_vs_gouraud") draw_flat_vs_gouraud(s);
  else if (view == "feature_edges") draw_feature_edges(s);
  else if (view == "by_curvature") draw_by_curvature(s);
  else draw_data_structure(s);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  return {"06_polygon_mesh",
          "lab 06 · polygon mesh",
          {{"flat_vs_gouraud", "GL_FLAT + face normals vs GL_SMOOTH + vertex normals"},
           {"feature_edges", "vertices split at feature edges vs normals averaged"},
           {"by_curvature", "equal triangles: uniform vs curvature-spaced profile"},
           {"data_structure", "a cube: indices, edge types, surfaces, counts"}},
          {{"spin", 0, -180, 180, "turn the objects about their axis, degrees"},
           {"slices", 16, 4, 64, "steps around the axis of the revolved objects"},
           {"feature_angle", 30, 0, 180, "an edge is a feature when its polygons' normals differ by more, degrees"},
           {"segments", 12, 2, 64, "profile segments of the lentil (by_curvature)"},
           {"edges", 1, 0, 1, "draw edges as lines: features, virtual ones, the lentil's rings"},
           {"normals", 0, 0, 1, "draw the normals sent to GL"},
           {"labels", 1, 0, 1, "counts and captions"}},
          {{'r', "spin +15 degrees", "spin", +15},
           {'R', "spin -15 degrees", "spin", -15},
           {'+', "slices +4", "slices", +4},
           {'-', "slices -4", "slices", -4},
           {']', "feature angle +15 degrees", "feature_angle", +15},
           {'[', "feature angle -15 degrees", "feature_angle", -15},
           {'s', "profile segments +2", "segments", +2},
           {'S', "profile segments -2", "segments", -2},
           {'e', "edges on/off", "edges"},
           {'n', "normals on/off", "normals"},
           {'l', "counts and captions on/off", "labels"}},
          init,
          display};
}
