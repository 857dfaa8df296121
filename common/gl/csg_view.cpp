// common/gl/csg_view.cpp — labs 32 and 33's drawing that is not their lesson (csg_view.h).
#include "gl/csg_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "gl/gl.h"
#include "gl/space_view.h"

namespace gllab {

namespace sp = space;
using spline::Vec3;

std::string literal_name(const sp::CsgTree& tree, const sp::Literal& l) {
  return (l.complement ? "−" : "") + tree.leaves()[std::size_t(l.primitive)].name;
}

Rgb primitive_colour(int id) {
  // Whole 8-bit values, so that GL's colour and the ray cast's agree exactly.
  static const int kPalette[8][3] = {{242, 158, 64},  {89, 166, 242}, {115, 217, 102},
                                     {230, 89, 115},  {204, 191, 77}, {166, 115, 230},
                                     {77, 204, 204},  {217, 140, 191}};
  const int* c = kPalette[((id % 8) + 8) % 8];
  return {c[0] / 255.f, c[1] / 255.f, c[2] / 255.f};
}

namespace {

constexpr int kAround = 48, kRings = 24;

// A ring of the surface of revolution about z: radius r at height z, its normals tilted by
// (nr, nz) (the profile's outward normal), as a quad strip to the next ring.
void revolution_band(double r0, double z0, double r1, double z1, double nr, double nz) {
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= kAround; ++i) {
    const double a = 2 * M_PI * (i % kAround) / kAround, c = std::cos(a), s = std::sin(a);
    glNormal3d(nr * c, nr * s, nz);
    glVertex3d(r1 * c, r1 * s, z1);  // counter-clockwise seen from outside
    glVertex3d(r0 * c, r0 * s, z0);
  }
  glEnd();
}

// A disk at height z facing +z (up = true) or -z.
void disk(double r, double z, bool up) {
  glNormal3d(0, 0, up ? 1 : -1);
  glBegin(GL_TRIANGLE_FAN);
  glVertex3d(0, 0, z);
  for (int i = 0; i <= kAround; ++i) {
    const double a = 2 * M_PI * (i % kAround) / kAround * (up ? 1 : -1);
    glVertex3d(r * std::cos(a), r * std::sin(a), z);
  }
  glEnd();
}

void sphere(double r) {
  for (int j = 0; j < kRings; ++j) {
    const double p0 = M_PI * j / kRings - M_PI / 2, p1 = M_PI * (j + 1) / kRings - M_PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= kAround; ++i) {
      const double a = 2 * M_PI * (i % kAround) / kAround, c = std::cos(a), s = std::sin(a);
      for (double p : {p1, p0}) {
        const Vec3 n{std::cos(p) * c, std::cos(p) * s, std::sin(p)};
        glNormal3d(n.x, n.y, n.z);
        glVertex3d(r * n.x, r * n.y, r * n.z);
      }
    }
    glEnd();
  }
}

void box(Vec3 size) {  // six quads, counter-clockwise from outside, in the current colour
  static constexpr int kFace[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                      {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  const Vec3 h = 0.5 * size;
  glBegin(GL_QUADS);
  for (int f = 0; f < 6; ++f) {
    const int axis = f / 2, sign = f % 2 ? 1 : -1;
    glNormal3d(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
    for (int c : kFace[f]) glVertex3d(c & 1 ? h.x : -h.x, c & 2 ? h.y : -h.y, c & 4 ? h.z : -h.z);
  }
  glEnd();
}

}  // namespace

void draw_csg_primitive(const sp::CsgLeaf& leaf) {
  GLint front = GL_CCW;
  glGetIntegerv(GL_FRONT_FACE, &front);
  if (leaf.to_world.determinant() < 0) glFrontFace(front == GL_CCW ? GL_CW : GL_CCW);
  glPushMatrix();
  glMultMatrixd(leaf.to_world.gl_matrix().data());
  const double r = leaf.radius, h = leaf.height / 2;
  switch (leaf.shape) {
    case sp::Shape::kSphere:
      sphere(r);
      break;
    case sp::Shape::kCylinder:
      revolution_band(r, -h, r, h, 1, 0);
      disk(r, h, true);
      disk(r, -h, false);
      break;
    case sp::Shape::kCone: {
      const double len = std::hypot(r, 2 * h);  // the slant's outward normal is (2h, r) / len
      revolution_band(r, -h, 0, h, 2 * h / len, r / len);
      disk(r, -h, false);
      break;
    }
    case sp::Shape::kBox:
      box(leaf.size);
      break;
  }
  glPopMatrix();
  glFrontFace(GLenum(front));
}

void draw_screen_quad(double depth) {
  glMatrixMode(GL_PROJECTION);
  glPushMatrix();
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glPushMatrix();
  glLoadIdentity();
  // At z = 0, mapped to exactly `depth` by the depth range: a quad at z = 1 would lie on
  // the far clipping plane, where clipping may drop it.
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_CULL_FACE);  // whichever faces the caller culls, the quad is drawn
  glDepthRange(depth, depth);
  glBegin(GL_QUADS);
  glVertex3d(-1, -1, 0);
  glVertex3d(1, -1, 0);
  glVertex3d(1, 1, 0);
  glVertex3d(-1, 1, 0);
  glEnd();
  glDepthRange(0, 1);
  glPopAttrib();
  glPopMatrix();
  glMatrixMode(GL_PROJECTION);
  glPopMatrix();
  glMatrixMode(GL_MODELVIEW);
}

void draw_csg_diagram(const sp::CsgTree& tree, int x, int y, int w, int h) {
  std::vector<DiagramNode> nodes;
  std::vector<int> leaf_of(tree.nodes().size(), -1);
  for (std::size_t i = 0; i < tree.leaves().size(); ++i)
    leaf_of[std::size_t(tree.leaves()[i].node)] = int(i);
  const std::function<void(int, int)> add = [&](int index, int parent) {
    const sp::CsgNode* n = &tree.nodes()[std::size_t(index)];
    while (n->op == sp::Op::kTransform) {  // a transform is drawn with its child
      index = n->left;
      n = &tree.nodes()[std::size_t(index)];
    }
    const int me = int(nodes.size());
    if (n->op == sp::Op::kPrimitive) {
      const int id = leaf_of[std::size_t(index)];
      nodes.push_back({parent, n->name.empty() ? sp::shape_name(n->shape) : n->name,
                       primitive_colour(id)});
      return;
    }
    nodes.push_back({parent, sp::op_name(n->op), {.75f, .75f, .8f}});
    add(n->left, me);
    add(n->right, me);
  };
  if (tree.root() >= 0) add(tree.root(), -1);
  draw_tree_diagram(nodes, x, y, w, h);
}

sp::PixelCamera current_pixel_camera() {
  std::array<double, 16> projection{}, modelview{};
  glGetDoublev(GL_PROJECTION_MATRIX, projection.data());
  glGetDoublev(GL_MODELVIEW_MATRIX, modelview.data());
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  sp::PixelCamera c;
  c.inverse_mvp = sp::inverse_mvp(projection, modelview);
  c.x = viewport[0];
  c.y = viewport[1];
  c.width = viewport[2];
  c.height = viewport[3];
  return c;
}

Image ray_cast_picture(const sp::CsgTree& tree, Rgb clear, bool lit) {
  const sp::PixelCamera camera = current_pixel_camera();
  const std::vector<sp::CastPixel> cast = sp::cast_image(tree, camera);
  // The headlight of enable_headlight (scene.cpp), in eye space, taken to world space.
  std::array<double, 16> mv{};
  glGetDoublev(GL_MODELVIEW_MATRIX, mv.data());
  const Vec3 light_eye = normalized(Vec3{-0.35, 0.45, 1});
  const Vec3 light{mv[0] * light_eye.x + mv[1] * light_eye.y + mv[2] * light_eye.z,
                   mv[4] * light_eye.x + mv[5] * light_eye.y + mv[6] * light_eye.z,
                   mv[8] * light_eye.x + mv[9] * light_eye.y + mv[10] * light_eye.z};
  std::vector<std::uint8_t> rows(cast.size() * 4);
  for (std::size_t p = 0; p < cast.size(); ++p) {
    Rgb c = clear;
    if (cast[p].primitive >= 0) {
      c = primitive_colour(cast[p].primitive);
      if (lit) {
        const double k = 0.2 + std::max(0.0, dot(normalized(light), cast[p].normal));
        c = {float(std::min(1.0, c.r * k)), float(std::min(1.0, c.g * k)),
             float(std::min(1.0, c.b * k))};
      }
    }
    rows[4 * p] = std::uint8_t(std::lround(255 * c.r));
    rows[4 * p + 1] = std::uint8_t(std::lround(255 * c.g));
    rows[4 * p + 2] = std::uint8_t(std::lround(255 * c.b));
    rows[4 * p + 3] = 255;
  }
  return image_from_bottom_up(rows.data(), camera.width, camera.height);
}

void draw_image(const Image& image) {
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  std::vector<std::uint8_t> rows(image.rgba.size());
  const std::size_t row = std::size_t(image.width) * 4;
  for (int j = 0; j < image.height; ++j)  // top-down -> bottom-up
    std::copy_n(&image.rgba[std::size_t(image.height - 1 - j) * row], row, &rows[j * row]);
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_LIGHTING);
  glWindowPos2i(viewport[0], viewport[1]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glDrawPixels(image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  glPopAttrib();
}

namespace {
template <class T>
std::vector<T> read_buffer(GLenum format, GLenum type, int& w, int& h) {
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  w = viewport[2];
  h = viewport[3];
  std::vector<T> v(std::size_t(w) * h * (format == GL_RGBA ? 4 : 1));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(viewport[0], viewport[1], w, h, format, type, v.data());
  return v;
}
Image picture(int w, int h, const std::function<Rgb(std::size_t)>& colour) {  // bottom-up
  std::vector<std::uint8_t> rows(std::size_t(w) * h * 4);
  for (std::size_t p = 0; p < std::size_t(w) * h; ++p) {
    const Rgb c = colour(p);
    rows[4 * p] = std::uint8_t(std::lround(255 * c.r));
    rows[4 * p + 1] = std::uint8_t(std::lround(255 * c.g));
    rows[4 * p + 2] = std::uint8_t(std::lround(255 * c.b));
    rows[4 * p + 3] = 255;
  }
  return image_from_bottom_up(rows.data(), w, h);
}
}  // namespace

Image make_picture(int width, int height, const std::function<Rgb(int, int)>& colour) {
  return picture(width, height, [&](std::size_t p) {
    return colour(int(p % std::size_t(width)), int(p / std::size_t(width)));
  });
}

Image read_viewport() {
  int w = 0, h = 0;
  const std::vector<std::uint8_t> v = read_buffer<std::uint8_t>(GL_RGBA, GL_UNSIGNED_BYTE, w, h);
  return image_from_bottom_up(v.data(), w, h);
}

Image depth_picture() {
  int w = 0, h = 0;
  const std::vector<float> d = read_buffer<float>(GL_DEPTH_COMPONENT, GL_FLOAT, w, h);
  float lo = 1, hi = 0;  // the depths drawn (not the far plane), stretched to the greys
  for (float z : d)
    if (z < 1.f) lo = std::min(lo, z), hi = std::max(hi, z);
  return picture(w, h, [&](std::size_t p) -> Rgb {
    if (d[p] >= 1.f) return {.08f, .1f, .25f};
    const float g = 1.f - 0.75f * (hi > lo ? (d[p] - lo) / (hi - lo) : 0.f);
    return {g, g, g};
  });
}

Image stencil_picture() {
  int w = 0, h = 0;
  const std::vector<std::uint8_t> s =
      read_buffer<std::uint8_t>(GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, w, h);
  return picture(w, h, [&](std::size_t p) -> Rgb {
    return s[p] == 0 ? Rgb{0, 0, 0} : primitive_colour(s[p] - 1);
  });
}

namespace {
void use_viewport(const Panel& p) {
  glViewport(p.x, p.y, p.width, p.height);
  glScissor(p.x, p.y, p.width, p.height);
}
}  // namespace

void draw_csg_caption(const sp::CsgTree& tree, const std::vector<std::string>& lines, int width,
                      int height, bool quarter) {
  const int text_height = 16 * int(lines.size());
  if (quarter) {
    draw_csg_diagram(tree, width / 2 + 8, height / 2 + 8, width / 2 - 16,
                     height / 2 - 24 - text_height);
    draw_text_panel(8, height - 8 - text_height, lines, {1, 1, 1});
  } else {
    draw_csg_diagram(tree, width - 200, 8, 192, 130);
    draw_text_panel(8, height - 8 - text_height, lines, {1, 1, 1});
  }
}

void show_depth_and_stencil(const Panel& panel, const Panel& stencil) {
  use_viewport(panel);
  const Image depth = depth_picture(), counts = stencil_picture();
  draw_image(depth);
  use_viewport(stencil);
  draw_image(counts);
}

Comparison compare_with_ray_cast(const sp::CsgTree& tree, Rgb clear, const Panel& panel,
                                 const Panel& truth, const Panel& heat) {
  use_viewport(panel);
  const Image ours = read_viewport(), cast = ray_cast_picture(tree, clear, false);
  const Comparison c = compare_images(cast, ours, 0, 1);
  use_viewport(truth);
  draw_image(cast);
  use_viewport(heat);
  draw_image(heat_map(cast, ours, 0, 1));
  return c;
}

}  // namespace gllab
