// common/deform/faces.cpp — the two cartoon faces of faces.h.
//
// Each face is one function that names its numbers once and builds from them
// both the layers it is painted with and its feature points. The numbers are
// in units of 1/256 of the picture, y up (at size 256 a unit is a pixel), and
// whole or half. At a power-of-two size the samples are short binary
// fractions too (odd multiples of 1/8 unit at 256), so the inside tests below
// are sums of products that double precision holds exactly: no edge depends
// on rounding, on the compiler or on fused multiply-adds.
#include "deform/faces.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace gllab::deform {

namespace {

constexpr double kUnits = 256;  // units across the picture
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kSamples = 4;  // per pixel and axis

/// The points with (X - cx)^2 / a^2 + (Y - cy)^2 / b^2 <= 1; a = 0: none.
struct Ellipse {
  double cx = 0, cy = 0, a = 0, b = 0;
};

Ellipse circle(double cx, double cy, double r) { return {cx, cy, r, r}; }
/// e mirrored about the face's vertical centre line X = 128.
Ellipse mirrored(Ellipse e) { return {kUnits - e.cx, e.cy, e.a, e.b}; }

bool inside(const Ellipse& e, double X, double Y) {
  const double dx = X - e.cx, dy = Y - e.cy;
  const double a2 = e.a * e.a, b2 = e.b * e.b;
  return dx * dx * b2 + dy * dy * a2 <= a2 * b2;
}

/// Inside `in` (when given), inside `also_in` (when given), outside `not_in`
/// (when given), and within the box [x0, x1] x [y0, y1].
struct Region {
  Ellipse in, also_in, not_in;
  double x0 = -kInf, x1 = kInf, y0 = -kInf, y1 = kInf;

  bool contains(double X, double Y) const {
    if (X < x0 || X > x1 || Y < y0 || Y > y1) return false;
    if (in.a > 0 && !inside(in, X, Y)) return false;
    if (also_in.a > 0 && !inside(also_in, X, Y)) return false;
    return !(not_in.a > 0 && inside(not_in, X, Y));
  }
};

Region shape(Ellipse e) {
  Region r;
  r.in = e;
  return r;
}
Region box(double x0, double x1, double y0, double y1) {
  Region r;
  r.x0 = x0;
  r.x1 = x1;
  r.y0 = y0;
  r.y1 = y1;
  return r;
}
Region clip_y(Region r, double y0, double y1) {
  r.y0 = y0;
  r.y1 = y1;
  return r;
}
Region clip_x(Region r, double x0, double x1) {
  r.x0 = x0;
  r.x1 = x1;
  return r;
}
Region and_in(Region r, Ellipse e) {
  r.also_in = e;
  return r;
}
Region and_not_in(Region r, Ellipse e) {
  r.not_in = e;
  return r;
}

/// A region painted with one colour, and a box around it for culling.
struct Layer {
  Rgb8 colour;
  Region region;
  double bx0, bx1, by0, by1;
};

struct Drawing {
  FaceColours colours;
  double pupil_radius = 0;  // units
  std::vector<Layer> layers;  // back to front, on the background
  std::vector<Feature> features;

  void paint(Rgb8 colour, const Region& r) {
    Layer l{colour, r, r.x0, r.x1, r.y0, r.y1};
    for (const Ellipse* e : {&r.in, &r.also_in}) {
      if (e->a <= 0) continue;
      l.bx0 = std::max(l.bx0, e->cx - e->a);
      l.bx1 = std::min(l.bx1, e->cx + e->a);
      l.by0 = std::max(l.by0, e->cy - e->b);
      l.by1 = std::min(l.by1, e->cy + e->b);
    }
    layers.push_back(l);
  }
  /// Paints r and its mirror image about X = 128.
  void paint_pair(Rgb8 colour, Region r) {
    paint(colour, r);
    r.in = mirrored(r.in);
    r.also_in = mirrored(r.also_in);
    r.not_in = mirrored(r.not_in);
    const double x0 = r.x0;
    r.x0 = kUnits - r.x1;
    r.x1 = kUnits - x0;
    paint(colour, r);
  }
  void feature(const char* name, double X, double Y) {
    features.push_back({name, {X / kUnits, Y / kUnits}});
  }
  void feature_pair(const char* left, const char* right, double X, double Y) {
    feature(left, X, Y);
    feature(right, kUnits - X, Y);
  }
};

/// An eyebrow: the arch of the ellipse `top` above the same ellipse moved
/// down by `thickness` (a crescent, thickest in the middle, tapering to
/// nothing at the ends).
Region brow(Ellipse top, double thickness) {
  Ellipse below = top;
  below.cy -= thickness;
  return and_not_in(shape(top), below);
}

// What both faces have, in the same order: the neck and shirt, the head, the
// eyes, the nose and the open mouth, and the features (faces.h) they define.
struct Common {
  Ellipse head, shirt;
  double neck_half_width = 0;
  Ellipse eye_white;  // the left eye; the right one is its mirror image
  double iris = 0, pupil = 0;
  Ellipse brow;
  double brow_thickness = 0;
  Ellipse nose_bridge;
  double nose_tip_y = 0, nose_tip_r = 0;  // the round tip, at X = 128
  // The open mouth: the lower half of `mouth` below the arc of `upper_lip`,
  // which passes through both corners (mouth.cx +- mouth.a, mouth.cy) and
  // dips `lip_dip` below them in the middle; a small disc rounds each corner.
  // The teeth are the band of depth teeth_depth under the lip.
  Ellipse mouth, upper_lip;
  double lip_dip = 0, corner_r = 0, teeth_depth = 0, teeth_half_width = 0;
  Ellipse tongue;
};

void paint_neck_and_head(Drawing& d, const Common& c) {
  const FaceColours& k = d.colours;
  d.paint(k.neck, box(128 - c.neck_half_width, 128 + c.neck_half_width, -kInf, c.head.cy));
  d.paint(k.shirt, shape(c.shirt));
  d.paint(k.skin, shape(c.head));
}

void paint_features(Drawing& d, const Common& c) {
  const FaceColours& k = d.colours;
  const Ellipse& e = c.eye_white;
  d.paint_pair(k.brow, brow(c.brow, c.brow_thickness));
  d.paint_pair(k.eye_white, shape(e));
  d.paint_pair(k.iris, shape(circle(e.cx, e.cy, c.iris)));
  d.paint_pair(k.pupil, shape(circle(e.cx, e.cy, c.pupil)));
  d.pupil_radius = c.pupil;
  d.paint(k.nose, shape(c.nose_bridge));
  d.paint(k.nose, shape(circle(128, c.nose_tip_y, c.nose_tip_r)));
  const Ellipse& m = c.mouth;
  const Region open = and_not_in(clip_y(shape(m), -kInf, m.cy), c.upper_lip);
  d.paint(k.mouth, open);
  Ellipse teeth_edge = c.upper_lip;
  teeth_edge.cy -= c.teeth_depth;
  d.paint(k.teeth, clip_x(and_in(open, teeth_edge), m.cx - c.teeth_half_width,
                          m.cx + c.teeth_half_width));
  d.paint(k.tongue, and_in(clip_y(shape(c.tongue), -kInf, m.cy), m));
  d.paint_pair(k.mouth, shape(circle(m.cx - m.a, m.cy, c.corner_r)));
}

/// The features, top to bottom (faces.h), from the numbers that draw them.
void add_features(Drawing& d, const Common& c, double top_of_head) {
  d.feature("top_of_head", 128, top_of_head);
  d.feature_pair("left_brow", "right_brow", c.brow.cx,
                 c.brow.cy + c.brow.b - c.brow_thickness / 2);
  d.feature_pair("left_eye", "right_eye", c.eye_white.cx, c.eye_white.cy);
  d.feature_pair("face_left", "face_right", c.head.cx - c.head.a, c.head.cy);
  d.feature("nose_tip", 128, c.nose_tip_y);
  d.feature_pair("mouth_left", "mouth_right", c.mouth.cx - c.mouth.a, c.mouth.cy);
  // halfway between the upper lip and the bottom of the mouth
  d.feature("mouth_centre", c.mouth.cx, c.mouth.cy - (c.lip_dip + c.mouth.b) / 2);
  d.feature("chin", 128, c.head.cy - c.head.b);
}

// Face A: round, eyes high and close together, a button nose, a smile high
// up; ginger hair cut short with a scalloped fringe, ears, pink cheeks.
Drawing face_a() {
  Drawing d;
  d.colours.background = {178, 216, 242};  // sky blue
  d.colours.hair = {214, 112, 42};         // ginger
  d.colours.skin = {252, 218, 186};
  d.colours.ear = {236, 172, 142};
  d.colours.cheek = {246, 166, 160};
  d.colours.brow = {170, 84, 32};
  d.colours.eye_white = {252, 252, 248};
  d.colours.iris = {66, 132, 206};  // blue
  d.colours.pupil = {22, 20, 30};
  d.colours.nose = {240, 176, 146};
  d.colours.mouth = {150, 36, 52};
  d.colours.teeth = {255, 255, 255};
  d.colours.tongue = {232, 110, 120};
  d.colours.neck = {232, 190, 160};
  d.colours.shirt = {72, 160, 96};  // green
  Common c;
  c.head = circle(128, 120, 86);
  c.shirt = {128, -20, 104, 46};
  c.neck_half_width = 20;
  c.eye_white = {106, 156, 13, 15};
  c.iris = 9;
  c.pupil = 5;
  c.brow = {106, 166, 14, 12};
  c.brow_thickness = 5;
  c.nose_bridge = {128, 140, 4, 9};
  c.nose_tip_y = 128;
  c.nose_tip_r = 8;
  c.mouth = {128, 100, 24, 20};
  c.upper_lip = {128, 116, 40, 20};  // (24/40)^2 + (16/20)^2 = 1: through the corners
  c.lip_dip = 4;                     // 116 - 20 = 100 - 4
  c.corner_r = 2.5;
  c.teeth_depth = 4;
  c.teeth_half_width = 16;
  c.tongue = {128, 80, 12, 4};  // top at 84, 4 below mouth_centre's 88
  const Ellipse hair = {128, 134, 96, 90};  // behind the head, cut at Y = 96
  const Ellipse ear = circle(44, 148, 12);
  const double fringe = 192;  // the fringe's straight edge; scallops hang below it

  d.paint(d.colours.hair, clip_y(shape(hair), 96, kInf));
  d.paint_pair(d.colours.skin, shape(ear));
  d.paint_pair(d.colours.ear, shape(circle(ear.cx + 2, ear.cy, 6)));
  paint_neck_and_head(d, c);
  d.paint(d.colours.hair, clip_y(shape(c.head), fringe, kInf));
  for (double x = 88; x <= 168; x += 16)
    d.paint(d.colours.hair, and_in(shape(circle(x, fringe, 8)), c.head));
  d.paint_pair(d.colours.cheek, shape(circle(92, 120, 11)));
  paint_features(d, c);
  add_features(d, c, hair.cy + hair.b);
  return d;
}

// Face B: a long oval, eyes lower and further apart, a long nose, a wide
// mouth lower down; a brown bob that frames the forehead and hides the ears.
Drawing face_b() {
  Drawing d;
  d.colours.background = {246, 228, 170};  // pale yellow
  d.colours.hair = {104, 66, 40};          // brown
  d.colours.skin = {204, 148, 108};
  d.colours.ear = d.colours.skin;    // unused: the hair hides the ears
  d.colours.cheek = d.colours.skin;  // unused: no cheeks
  d.colours.brow = {92, 58, 36};
  d.colours.eye_white = {250, 250, 244};
  d.colours.iris = {92, 132, 60};  // green
  d.colours.pupil = {22, 20, 30};
  d.colours.nose = {184, 124, 88};
  d.colours.mouth = {128, 30, 44};
  d.colours.teeth = {255, 255, 250};
  d.colours.tongue = {214, 96, 104};
  d.colours.neck = {176, 122, 86};
  d.colours.shirt = {120, 84, 170};  // purple
  Common c;
  c.head = {128, 124, 70, 94};
  c.shirt = {128, -24, 112, 44};
  c.neck_half_width = 22;
  c.eye_white = {88, 126, 15, 11};
  c.iris = 8;
  c.pupil = 4.5;
  c.brow = {88, 136, 18, 14};
  c.brow_thickness = 6;
  c.nose_bridge = {128, 112, 5, 20};
  c.nose_tip_y = 92;
  c.nose_tip_r = 10;
  c.mouth = {128, 66, 36, 14};
  c.upper_lip = {128, 78, 60, 15};  // (36/60)^2 + (12/15)^2 = 1: through the corners
  c.lip_dip = 3;                    // 78 - 15 = 66 - 3
  c.corner_r = 2.5;
  c.teeth_depth = 3;
  c.teeth_half_width = 24;
  c.tongue = {128, 52, 18, 3};  // top at 55, 2.5 below mouth_centre's 57.5
  const Ellipse crown = {128, 130, 88, 98};             // the bob: this ellipse
  const double bob_x0 = 40, bob_y0 = 56, bob_y1 = 130;  // and this box below it
  const Ellipse forehead = {128, 150, 56, 52};          // the hairline's arch,
                                                        // hair beside it above Y = 150

  d.paint(d.colours.hair, shape(crown));
  d.paint(d.colours.hair, box(bob_x0, kUnits - bob_x0, bob_y0, bob_y1));
  paint_neck_and_head(d, c);
  d.paint(d.colours.hair, clip_y(and_not_in(shape(c.head), forehead), forehead.cy, kInf));
  paint_features(d, c);
  add_features(d, c, crown.cy + crown.b);
  return d;
}

const Drawing& drawing(Face face) {
  static const Drawing a = face_a(), b = face_b();
  switch (face) {
    case Face::kA: return a;
    case Face::kB: return b;
  }
  throw std::invalid_argument("faces: no face " + std::to_string(static_cast<int>(face)));
}

}  // namespace

const char* face_letter(Face face) { return face == Face::kA ? "A" : "B"; }

const std::vector<Feature>& face_features(Face face) { return drawing(face).features; }

const FaceColours& face_colours(Face face) { return drawing(face).colours; }

double pupil_radius(Face face) { return drawing(face).pupil_radius / kUnits; }

Image face_picture(Face face, int size) {
  if (size < 16 || size > 4096)
    throw std::invalid_argument("face_picture: size " + std::to_string(size) +
                                " (must be 16..4096)");
  const Drawing& d = drawing(face);
  Image image(size, size);
  const double n = size;
  // Sample i of a pixel's 4 x 4 is at X = (8 px + 2 i + 1) * 32 / size units:
  // the whole numbers are exact, and the one division is exact when size is
  // a power of two.
  constexpr int kSub = 2 * kSamples;  // 1/8ths of a pixel
  const double scale = kUnits / kSub;   // 32
  std::vector<const Layer*> row, here;
  for (int py = 0; py < size; ++py) {
    const int top = kSub * (size - py);  // the row's top edge, in 1/8ths of a pixel
    const double y_lo = (top - kSub) * scale / n, y_hi = top * scale / n;
    double Y[kSamples];
    for (int j = 0; j < kSamples; ++j) Y[j] = (top - 2 * j - 1) * scale / n;
    row.clear();
    for (const Layer& l : d.layers)
      if (l.by0 <= y_hi && l.by1 >= y_lo) row.push_back(&l);
    for (int px = 0; px < size; ++px) {
      const int left = kSub * px;
      const double x_lo = left * scale / n, x_hi = (left + kSub) * scale / n;
      here.clear();
      for (const Layer* l : row)
        if (l->bx0 <= x_hi && l->bx1 >= x_lo) here.push_back(l);
      int sum[3] = {0, 0, 0};
      for (int j = 0; j < kSamples; ++j)
        for (int i = 0; i < kSamples; ++i) {
          const double X = (left + 2 * i + 1) * scale / n;
          Rgb8 c = d.colours.background;
          for (auto l = here.rbegin(); l != here.rend(); ++l)
            if ((*l)->region.contains(X, Y[j])) {
              c = (*l)->colour;
              break;
            }
          sum[0] += c.r;
          sum[1] += c.g;
          sum[2] += c.b;
        }
      std::uint8_t* p = image.pixel(px, py);
      const int count = kSamples * kSamples;  // the mean, rounded half up
      for (int ch = 0; ch < 3; ++ch)
        p[ch] = static_cast<std::uint8_t>((sum[ch] + count / 2) / count);
      p[3] = 255;
    }
  }
  return image;
}

}  // namespace gllab::deform
