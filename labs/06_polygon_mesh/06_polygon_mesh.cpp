// lab 06 · polygon mesh                                      difficulty: ★★☆☆
// The mesh data structure of lecture notes ch. 1, §1.2 Polygonal representation:
// object → surfaces → polygons → edges → vertices, each vertex stored once
// (common/mesh/polygon_mesh.h), drawn flat and smooth with glDrawElements, with
// sharp feature edges ("Comment on edges") and resolution chosen by curvature.
// Notice: a sharp edge costs vertices. The cube's 8 corners become 24 render
//   vertices, because each corner needs one normal per face that meets there.
// Try: set the feature angle to 180 in feature_edges ([]]). Where does the
//   machined part turn soft, and why do its flat caps get dark rims?
// Keys: [+]/[-] slices  [[]/[]] feature angle  [s]/[S] segments  [e] edges  [n] normals
//   right-drag turn  wheel zoom  [0] reset camera  [h] help  [Esc] quit
// Views: flat_vs_gouraud, feature_edges, by_curvature, data_structure
// Reference: reference_images/06_polygon_mesh__*.png

#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/mesh_view.h"
#include "gl/scene.h"
#include "harness/lab.h"
#include "mesh/polygon_mesh.h"

namespace {

using gllab::EdgeType, gllab::IndexedMesh, gllab::kOrbit, gllab::Normals, gllab::PolygonMesh;
using gllab::State;

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
constexpr int kDenseProfile = 2000;      // samples the resampling picks from
constexpr double kCurvatureShare = 0.8;  // 0 = uniform along the curve, 1 = curvature only

// A cube whose top is split into two triangles: the diagonal is a virtual edge.
const std::vector<gllab::Vec3> kCube = {{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}, {1, 1, -1},
                                        {-1, -1, 1},  {1, -1, 1},  {-1, 1, 1},  {1, 1, 1}};
const std::vector<gllab::PolygonInput> kCubeFaces = {  // counter-clockwise from outside
    {{0, 2, 3, 1}}, {{4, 5, 7}, 1}, {{4, 7, 6}, 1}, {{0, 1, 5, 4}},
    {{2, 6, 7, 3}}, {{0, 4, 6, 2}}, {{1, 3, 7, 5}}};
const std::vector<gllab::Surface> kCubeSurfaces = {{"box", {.6f, .6f, .65f}},   // surface 0
                                                   {"lid", {.45f, .55f, .75f}}};  // surface 1

const gllab::Rgb kText{1.f, 1.f, 1.f}, kFeature{1.f, .45f, .15f}, kVirtual{.3f, .8f, 1.f};

// Drawing -------------------------------------------------------------------
void draw_arrays(const IndexedMesh& m) {
  for (GLenum a : {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY}) glEnableClientState(a);
  glVertexPointer(3, GL_FLOAT, 0, m.positions.data());
  glNormalPointer(GL_FLOAT, 0, m.normals.data());
  glColorPointer(3, GL_FLOAT, 0, m.colours.data());
  // Push the fill back a little so edges drawn on top of it win the depth test.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.f, 1.f);
  glDrawElements(GL_TRIANGLES, GLsizei(m.indices.size()), GL_UNSIGNED_INT, m.indices.data());
  glDisable(GL_POLYGON_OFFSET_FILL);
  for (GLenum a : {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY}) glDisableClientState(a);
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
      if (show(e)) glVertex3d(m.vertices[v].position.x, m.vertices[v].position.y,
                              m.vertices[v].position.z);
  glEnd();
  glPopAttrib();
}
bool is_feature(const gllab::Edge& e) { return e.type == EdgeType::kFeature; }
bool is_virtual(const gllab::Edge& e) { return e.type == EdgeType::kVirtual; }

// Every view: the projection, the headlight, then the orbit camera.
void begin_view(const State& s) {
  gllab::ortho_fit(s.width, s.height, 2.5, 2.2);
  gllab::enable_headlight();
  gllab::apply_orbit(s);  // right-drag, wheel, [0]: s.camera
}

// Panel `side` (0 left, 1 right): z up, seen `tilt` degrees from above.
void enter_panel(int side, double y, double tilt, double scale) {
  glPushMatrix();
  glTranslated(side ? 1.25 : -1.25, y, 0);
  glRotated(tilt - 90, 1, 0, 0);
  glScaled(scale, scale, scale);
}

// The panel's title above it and its counts (taken from the data) below.
void caption(const State& s, int side, const std::string& title,
             const std::vector<std::string>& counts) {
  if (!s.flag("labels")) return;
  gllab::draw_label(side ? 1.25 : -1.25, 1.75, 0, title, kText);
  gllab::draw_text_panel(side ? s.width / 2 + 8 : 8, s.height - 64, counts, kText);
}

void draw_flat_vs_gouraud(const State& s) {
  begin_view(s);
  const int slices = s.integer("slices");
  const PolygonMesh m = gllab::make_surface_of_revolution(
      gllab::half_ellipse_profile(1, 1, slices / 2), slices, {kClay});  // a sphere
  for (int side = 0; side < 2; ++side) {
    const IndexedMesh arrays = render_arrays(m, side ? Normals::kAveraged : Normals::kFace);
    // GL_FLAT fills a triangle with the colour lit at its last vertex; GL_SMOOTH
    // interpolates the colours lit at all three (Gouraud). Why do the flat arrays
    // repeat each vertex per polygon? (Its last vertex must carry that face's normal.)
    glShadeModel(side ? GL_SMOOTH : GL_FLAT);
    enter_panel(side, -0.15, 20, 1.0);
    draw_arrays(arrays);
    if (s.flag("normals")) gllab::draw_vertex_normals(arrays, 0.25f);
    glPopMatrix();
    caption(s, side, side ? "GL_SMOOTH, vertex normals" : "GL_FLAT, face normals",
            gllab::mesh_counts(m, arrays));
  }
}

void draw_feature_edges(const State& s) {
  begin_view(s);
  PolygonMesh m = gllab::make_surface_of_revolution(kPartProfile, s.integer("slices"), {kSteel});
  const std::size_t features = classify_edges(m, s.get("feature_angle"));
  for (int side = 0; side < 2; ++side) {
    // Right: one normal per stored vertex, averaged across the rims as well.
    const Normals normals = side ? Normals::kAveraged : Normals::kSplitFeatures;
    const IndexedMesh arrays = render_arrays(m, normals);
    enter_panel(side, -0.15, 20, 1.05);
    draw_arrays(arrays);
    if (s.flag("edges") && side == 0) draw_edges(m, is_feature, kFeature, 2.f, false);
    if (s.flag("normals")) gllab::draw_vertex_normals(arrays, 0.2f);
    glPopMatrix();
    std::vector<std::string> counts = gllab::mesh_counts(m, arrays);
    counts[0] = side ? "no feature edges"
                     : gllab::format_text("%zu feature edges (> %d deg)", features,
                                          s.integer("feature_angle"));
    caption(s, side, side ? "averaged across all edges" : "split at feature edges", counts);
  }
}

void draw_by_curvature(const State& s) {
  begin_view(s);
  const auto dense = gllab::half_ellipse_profile(kA, kB, kDenseProfile);
  for (int side = 0; side < 2; ++side) {
    // The same number of profile segments, placed uniformly (left) or mostly by curvature.
    const auto profile =
        resample_profile(dense, s.integer("segments"), side ? kCurvatureShare : 0.0);
    const PolygonMesh m = gllab::make_surface_of_revolution(profile, s.integer("slices"), {kJade});
    enter_panel(side, 0.45, 15, 1.1);
    draw_arrays(render_arrays(m, Normals::kAveraged));
    // The rings (edges at one height) show where the profile points went.
    auto ring = [&m](const gllab::Edge& e) {
      return m.vertices[e.v0].position.z == m.vertices[e.v1].position.z;
    };
    if (s.flag("edges")) draw_edges(m, ring, {.1f, .25f, .1f}, 1.f, false);
    glPopMatrix();
    // Below: the cross-section over the true ellipse in red (gl/mesh_view.h).
    gllab::draw_profile_section(side ? 1.25 : -1.25, -0.95, 1.1, profile, kA, kB, kDenseProfile);
    const double error = profile_deviation(dense, profile);  // the largest distance to the curve
    caption(s, side, side ? "spaced by curvature" : "spaced uniformly",
            {std::to_string(m.triangle_count()) + " triangles",
             std::to_string(profile.size() - 1) + " profile segments",
             gllab::format_text("max error %.4f (of radius 1)", error)});
  }
}

void draw_data_structure(const State& s) {
  begin_view(s);
  PolygonMesh m = gllab::build_polygon_mesh(kCube, kCubeFaces, kCubeSurfaces);
  classify_edges(m, s.get("feature_angle"));
  const IndexedMesh arrays = render_arrays(m, Normals::kSplitFeatures);
  glPushMatrix();
  glTranslated(0, 0.1, 0);
  glRotated(-65, 1, 0, 0);
  glRotated(25, 0, 0, 1);  // three faces in view
  glScaled(0.75, 0.75, 0.75);
  draw_arrays(arrays);
  if (s.flag("edges")) {
    draw_edges(m, is_feature, kFeature, 3.f, false);
    draw_edges(m, is_virtual, kVirtual, 3.f, true);
  }
  if (s.flag("normals")) gllab::draw_vertex_normals(arrays, 0.5f);
  gllab::draw_mesh_numbers(m);  // the polygons facing us and their vertices
  glPopMatrix();
  if (!s.flag("labels")) return;
  gllab::draw_label(0, 1.75, 0, "object -> surfaces -> polygons -> edges -> vertices", kText);
  const std::size_t diagonal = m.find_edge(4, 7).value();  // the lid's diagonal
  gllab::draw_text_panel(8, s.height - 112, gllab::data_structure_counts(m, arrays, diagonal),
                         kText);
}

// init ----------------------------------------------------------------------
void init() {
  glEnable(GL_DEPTH_TEST);
  glClearColor(0.12f, 0.13f, 0.16f, 1.f);
}

}  // namespace

// Lab definition -----------------------------------------------------------
gllab::Lab gllab::define_lab() {
  return {"06_polygon_mesh",
          "lab 06 · polygon mesh",
          {{"flat_vs_gouraud", "GL_FLAT + face normals vs GL_SMOOTH + vertex normals",
            draw_flat_vs_gouraud, kOrbit},
           {"feature_edges", "vertices split at feature edges vs normals averaged",
            draw_feature_edges, kOrbit},
           {"by_curvature", "equal triangles: uniform vs curvature-spaced profile",
            draw_by_curvature, kOrbit},
           {"data_structure", "a cube: indices, edge types, surfaces, counts", draw_data_structure,
            kOrbit}},
          {{"slices", 16, 4, 64, "steps around the axis of the revolved objects"},
           {"feature_angle", 30, 0, 180,
            "an edge is a feature when its polygons' normals differ by more, degrees"},
           {"segments", 12, 2, 64, "profile segments of the lentil (by_curvature)"},
           {"edges", 1, 0, 1, "draw edges as lines: features, virtual ones, the lentil's rings"},
           {"normals", 0, 0, 1, "draw the normals sent to GL"},
           {"labels", 1, 0, 1, "counts and captions"}},
          {{'+', "slices +4", "slices", +4}, {'-', "slices -4", "slices", -4},
           {']', "feature angle +15 degrees", "feature_angle", +15},
           {'[', "feature angle -15 degrees", "feature_angle", -15},
           {'s', "profile segments +2", "segments", +2}, {'S', "segments -2", "segments", -2},
           {'e', "edges on/off", "edges"}, {'n', "normals on/off", "normals"}},
          init};
}
