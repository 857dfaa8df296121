// common/gl/space_view.cpp — labs 30 and 31's drawing that is not their
// lesson (space_view.h).
#include "gl/space_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>

#include "gl/gl.h"
#include "gl/scene.h"
#include "gl/spline_draw.h"
#include "harness/lab.h"

namespace gllab {

using spline::Vec3;

void space_camera(const State& s, int width, int height, double half, double azimuth,
                  double elevation) {
  ortho_fit(width, height, half, half);
  enable_headlight();
  apply_orbit(s);
  glRotated(elevation - 90, 1, 0, 0);
  glRotated(azimuth, 0, 0, 1);
}

namespace {
Vec3 corner(const space::Box3& b, int c) {
  return {c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z};
}
void vertex(Vec3 p) { glVertex3d(p.x, p.y, p.z); }
// The six faces as corner numbers (counter-clockwise from outside) with their normals.
constexpr int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                              {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
constexpr int kNormals[6][3] = {{-1, 0, 0}, {1, 0, 0},  {0, -1, 0},
                                {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};
}  // namespace

void draw_box_edges(const space::Box3& box, Rgb colour, float width) {
  glPushAttrib(GL_ENABLE_BIT | GL_LINE_BIT | GL_CURRENT_BIT | GL_LIGHTING_BIT);
  glDisable(GL_LIGHTING);
  glLineWidth(width);
  glColor3f(colour.r, colour.g, colour.b);
  glBegin(GL_LINES);
  for (int a = 0; a < 8; ++a)
    for (int bit = 1; bit < 8; bit <<= 1)
      if (!(a & bit)) {
        vertex(corner(box, a));
        vertex(corner(box, a | bit));
      }
  glEnd();
  glPopAttrib();
}

void draw_box_faces(const space::Box3& box, Rgb colour) {
  glColor3f(colour.r, colour.g, colour.b);
  glBegin(GL_QUADS);
  for (int f = 0; f < 6; ++f) {
    glNormal3i(kNormals[f][0], kNormals[f][1], kNormals[f][2]);
    for (int c : kFaces[f]) vertex(corner(box, c));
  }
  glEnd();
}

std::size_t draw_voxel_faces(const space::VoxelGrid& g, Rgb colour) {
  const int n = g.n();
  const double h = g.voxel_size();
  const Vec3 lo = g.cube().lo;
  std::size_t faces = 0;
  glColor3f(colour.r, colour.g, colour.b);
  glBegin(GL_QUADS);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (!g.at(i, j, k)) continue;
        const space::Box3 b{lo + h * Vec3{double(i), double(j), double(k)},
                            lo + h * Vec3{i + 1.0, j + 1.0, k + 1.0}};
        for (int f = 0; f < 6; ++f) {
          const int di = kNormals[f][0], dj = kNormals[f][1], dk = kNormals[f][2];
          const int a = i + di, b2 = j + dj, c = k + dk;
          const bool outside = a < 0 || b2 < 0 || c < 0 || a >= n || b2 >= n || c >= n;
          if (!outside && g.at(a, b2, c)) continue;  // hidden by its neighbour
          glNormal3i(di, dj, dk);
          for (int q : kFaces[f]) vertex(corner(b, q));
          ++faces;
        }
      }
  glEnd();
  return faces;
}

Rgb coverage_colour(space::Coverage state) {
  switch (state) {
    case space::Coverage::kCovered:
      return {.95f, .6f, .25f};
    case space::Coverage::kUncovered:
      return {.35f, .38f, .45f};
    case space::Coverage::kPartial:
      return {.95f, .9f, .35f};
  }
  return {1, 1, 1};
}

void draw_octree_diagram(const space::RegionOctree& tree, int levels, int x, int y, int w, int h) {
  const std::vector<space::OctreeNode>& nodes = tree.nodes();
  if (nodes.empty() || levels < 1) return;
  const PixelSpace pixels;
  const int row = h / levels;
  const auto top = [&](int level) { return pixels.height - y - level * row; };  // from the bottom
  // Each node owns a horizontal slot; its children split the slot in eight.
  struct Item {
    std::size_t node;
    double left, width;
    int level, number;
  };
  std::vector<Item> items{{0, double(x), double(w), 0, -1}}, labels;
  for (std::size_t it = 0; it < items.size(); ++it) {
    const Item a = items[it];
    const space::OctreeNode& n = nodes[a.node];
    if (n.first_child >= 0 && a.level + 1 < levels)
      for (int c = 0; c < 8; ++c)
        items.push_back({std::size_t(n.first_child) + c, a.left + c * a.width / 8, a.width / 8,
                         a.level + 1, c});
  }
  const auto centre = [](const Item& a) { return a.left + a.width / 2; };
  glLineWidth(1.f);
  glColor3f(.7f, .7f, .75f);
  glBegin(GL_LINES);  // parent to child
  for (const Item& a : items)
    for (const Item& b : items)
      if (b.level == a.level + 1 && b.left >= a.left && b.left < a.left + a.width) {
        glVertex2d(centre(a), top(a.level) - row * 0.45);
        glVertex2d(centre(b), top(b.level) - row * 0.1);
      }
  glEnd();
  for (const Item& a : items) {
    const double s = std::min(a.width * 0.8, row * 0.35), cx = centre(a);
    const double t = top(a.level) - row * 0.1;
    const Rgb c = coverage_colour(nodes[a.node].state);
    glColor3f(c.r, c.g, c.b);
    glRectd(cx - s / 2, t - s, cx + s / 2, t);
  }
  for (const Item& a : items)  // numbers where there is room
    if (a.number >= 0 && a.width >= 12)
      draw_text(
          int(centre(a)) - 3,
          pixels.height - top(a.level) + int(row * 0.1 + 2 + std::min(a.width * 0.8, row * 0.35)),
          std::to_string(a.number), {1, 1, 1});
}

std::string bytes_text(std::size_t bytes) {
  if (bytes < 1024) return std::to_string(bytes) + " B";
  if (bytes < 1024 * 1024) return format_text("%.1f KB", bytes / 1024.0);
  return format_text("%.1f MB", bytes / (1024.0 * 1024.0));
}

std::string count_text(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

space::Ray view_ray(Vec3 through, double back) {
  GLdouble m[16];
  glGetDoublev(GL_MODELVIEW_MATRIX, m);  // column-major: row r of R is m[r], m[4 + r], m[8 + r]
  // Eye space looks along -z; in the lab's space that is -(row 2 of R) when
  // R (the model-view's 3 x 3 part) is a rotation times a uniform scale.
  const Vec3 into = -normalized(Vec3{m[2], m[6], m[10]});
  return {through - back * into, into};
}

PanelDifference compare_panels(const Panel& a, const Panel& b) {
  const int w = a.width, h = a.height;
  std::vector<std::uint8_t> pa(std::size_t(w) * h * 4), pb(pa.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(a.x, a.y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pa.data());
  glReadPixels(b.x, b.y, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pb.data());
  const auto px = [&](const std::vector<std::uint8_t>& p, int i, int j) {
    const std::uint8_t* q = &p[(std::size_t(j) * w + i) * 4];
    return std::uint32_t(q[0]) << 16 | std::uint32_t(q[1]) << 8 | q[2];
  };
  PanelDifference d;
  d.pixels = std::size_t(w) * h;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      if (px(pa, i, j) == px(pb, i, j)) continue;
      ++d.differing;
      bool edge = false;  // a colour edge in either picture within one pixel
      for (int dj = -1; dj <= 1 && !edge; ++dj)
        for (int di = -1; di <= 1 && !edge; ++di) {
          const int u = i + di, v = j + dj;
          if (u >= 0 && v >= 0 && u < w && v < h)
            edge = px(pb, u, v) != px(pb, i, j) || px(pa, u, v) != px(pa, i, j);
        }
      d.away_from_edges += !edge;
    }
  return d;
}

}  // namespace gllab

namespace gllab {

void draw_tree_diagram(const std::vector<DiagramNode>& nodes, int x, int y, int w, int h) {
  if (nodes.empty()) return;
  const std::size_t n = nodes.size();
  std::vector<std::vector<std::size_t>> children(n);
  std::vector<int> depth(n, 0);
  for (std::size_t i = 1; i < n; ++i) {
    children[std::size_t(nodes[i].parent)].push_back(i);
    depth[i] = depth[std::size_t(nodes[i].parent)] + 1;
  }
  // Leaves in depth-first order get slots 0, 1, 2, ...; a parent sits over its children.
  std::vector<double> slot(n, 0);
  double leaves = 0;
  const std::function<void(std::size_t)> place = [&](std::size_t i) {
    if (children[i].empty()) {
      slot[i] = leaves++;
      return;
    }
    for (std::size_t c : children[i]) place(c);
    slot[i] = (slot[children[i].front()] + slot[children[i].back()]) / 2;
  };
  place(0);
  const int levels = *std::max_element(depth.begin(), depth.end()) + 1;
  const PixelSpace pixels;
  const double dx = w / std::max(leaves, 1.0), dy = double(h) / levels;
  const double size = std::min({dx * 0.7, dy * 0.45, 12.0});
  const auto px = [&](std::size_t i) { return x + (slot[i] + 0.5) * dx; };
  const auto py = [&](std::size_t i) { return pixels.height - y - (depth[i] + 0.3) * dy; };
  glLineWidth(1.f);
  glColor3f(.7f, .7f, .75f);
  glBegin(GL_LINES);
  for (std::size_t i = 1; i < n; ++i) {
    glVertex2d(px(std::size_t(nodes[i].parent)), py(std::size_t(nodes[i].parent)));
    glVertex2d(px(i), py(i));
  }
  glEnd();
  for (std::size_t i = 0; i < n; ++i) {
    glColor3f(nodes[i].colour.r, nodes[i].colour.g, nodes[i].colour.b);
    glRectd(px(i) - size / 2, py(i) - size / 2, px(i) + size / 2, py(i) + size / 2);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!nodes[i].label.empty() && dx >= 8 * nodes[i].label.size())
      draw_text(int(px(i)) - 4 * int(nodes[i].label.size()),
                int(pixels.height - py(i) + size / 2 + 1), nodes[i].label, {1, 1, 1});
}

}  // namespace gllab

namespace gllab {

namespace {
const Rgb kInner{.8f, .8f, .8f}, kEmpty{.3f, .3f, .35f};
}

std::vector<DiagramNode> quadtree_diagram(const space::Quadtree& tree,
                                          const std::function<Rgb(int)>& colour,
                                          const std::function<std::string(int)>& name) {
  std::vector<DiagramNode> out;
  const std::function<void(int, int)> add = [&](int i, int parent) {
    const space::QuadNode& n = tree.nodes()[std::size_t(i)];
    const bool any = n.first_child < 0 && !n.objects.empty();
    out.push_back({parent, any ? name(n.objects[0]) : "",
                   n.first_child >= 0 ? kInner
                   : any              ? colour(n.objects[0])
                                      : kEmpty});
    const int me = int(out.size()) - 1;
    for (int c = 0; c < 4 && n.first_child >= 0; ++c) add(n.first_child + c, me);
  };
  if (!tree.nodes().empty()) add(0, -1);
  return out;
}

std::vector<DiagramNode> bsp_diagram(const space::BspTree& tree,
                                     const std::function<Rgb(int)>& colour,
                                     const std::function<std::string(int)>& name) {
  std::vector<DiagramNode> out;
  const std::function<void(int, int)> add = [&](int i, int parent) {
    const space::BspNode& n = tree.nodes()[std::size_t(i)];
    const int id = n.leaf && !n.on.empty() ? n.on[0].object : -1;
    out.push_back(
        {parent, id >= 0 ? name(id) : "", n.leaf ? id >= 0 ? colour(id) : kEmpty : kInner});
    const int me = int(out.size()) - 1;
    for (int child : {n.back, n.front})
      if (child >= 0) add(child, me);
  };
  if (!tree.nodes().empty()) add(0, -1);
  return out;
}

void draw_bsp_cuts(const space::BspTree& tree, const std::vector<Vec3>& root, Rgb colour) {
  if (tree.nodes().empty()) return;
  std::vector<space::Polygon3> region(tree.nodes().size());
  region[0].points = root;
  glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT);
  glDisable(GL_LIGHTING);
  glColor3f(colour.r, colour.g, colour.b);
  glBegin(GL_LINES);
  for (std::size_t i = 0; i < tree.nodes().size(); ++i) {  // parents come before children
    const space::BspNode& n = tree.nodes()[i];
    if (n.leaf || region[i].points.size() < 3) continue;
    const space::SplitResult r = space::split_polygon(region[i], n.plane);
    if (n.front >= 0 && r.side != space::SplitResult::kBack)
      region[std::size_t(n.front)] = r.side == space::SplitResult::kFront ? region[i] : r.front;
    if (n.back >= 0 && r.side != space::SplitResult::kFront)
      region[std::size_t(n.back)] = r.side == space::SplitResult::kBack ? region[i] : r.back;
    if (r.side != space::SplitResult::kSpanning) continue;
    for (const Vec3& q : r.front.points)  // the cut's two ends lie on the plane
      if (std::abs(n.plane.distance(q)) < 1e-9) glVertex3d(q.x, q.y, q.z);
  }
  glEnd();
  glPopAttrib();
}

}  // namespace gllab

namespace gllab {

void draw_piece_numbers(const std::vector<const space::Polygon3*>& pieces, std::size_t count,
                        Rgb colour) {
  for (std::size_t i = 0; i < pieces.size() && i < count; ++i) {
    Vec3 m{};
    for (const Vec3& q : pieces[i]->points) m += q / double(pieces[i]->points.size());
    draw_label(m.x, m.y, m.z, std::to_string(i + 1), colour);
  }
}

}  // namespace gllab

namespace gllab {

void draw_memory_plot(const State& s, const std::vector<std::array<double, 4>>& rows) {
  ortho_fit(s.width, s.height, 1.2, 1.2);
  const PlotFrame frame{-.85, -.45, 1.05, 1.05, 2, 8, 2, 26};  // log2 n, log2 bytes
  draw_plot_axes(frame, {.7f, .7f, .7f}, "log2 bytes (2 .. 26) against log2 n (2 .. 8)");
  for (int series = 1; series <= 3; ++series) {
    std::vector<Vec3> line;
    for (const auto& r : rows) line.push_back(frame.at(std::log2(r[0]), std::log2(r[series])));
    draw_polyline(line, series_colour(series), 2.f);
    draw_dots(line, series_colour(series), 6.f);
  }
  std::vector<std::string> lines;
  for (const auto& r : rows)
    lines.push_back(format_text("n = %3.0f: voxels %8s, %8s; octree %8s (%.1fx)", r[0],
                                bytes_text(std::size_t(r[1])).c_str(),
                                bytes_text(std::size_t(r[2])).c_str(),
                                bytes_text(std::size_t(r[3])).c_str(), r[1] / r[3]));
  draw_text_panel(8, s.height - 16 * int(lines.size()) - 12, lines, {1, 1, 1});
  draw_text_panel(8, 8, {"voxels, a byte each", "voxels, a bit each", "octree nodes"},
                  {series_colour(1), series_colour(2), series_colour(3)});
}

void draw_coverage_legend(int x, int y) {
  draw_text_panel(x, y, {"covered", "uncovered", "partly covered"},
                  {coverage_colour(space::Coverage::kCovered),
                   coverage_colour(space::Coverage::kUncovered),
                   coverage_colour(space::Coverage::kPartial)});
}

}  // namespace gllab

namespace gllab {

std::vector<space::Polygon3> in_plane(const std::vector<space::ConvexPolygon2>& objects) {
  std::vector<space::Polygon3> out;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    out.push_back({{}, int(i), int(i)});
    for (const spline::Vec2& p : objects[i]) out.back().points.push_back({p.x, p.y, 0});
  }
  return out;
}

void draw_convex_objects(const std::vector<space::ConvexPolygon2>& objects,
                         const std::function<Rgb(int)>& colour) {
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const Rgb c = colour(int(i));
    glColor3f(c.r, c.g, c.b);
    glBegin(GL_POLYGON);
    for (const spline::Vec2& p : objects[i]) glVertex2d(p.x, p.y);
    glEnd();
  }
}

std::vector<Vec3> elongated_cloud(int count) {
  std::vector<Vec3> P;
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (int i = 0; i < count; ++i) {
    const double t = (double(i) / (count - 1) - .5) * 1.8, w = .25 * std::sin(i * 2.39996);
    P.push_back({snap_to_grid(.1 + t * c - w * s), snap_to_grid(-.05 + t * s + w * c), 0});
  }
  return P;
}

}  // namespace gllab
