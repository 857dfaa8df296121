// common/deform/faces.h — two cartoon faces drawn in code: the pictures m1 and
// m2 of the morphing lab (lecture notes ch. 1, §1.7 Surface representations,
// "Morphing": m(t, x, y) with m(0) = m1, m(1) = m2; a deformation f2 maps
// picked feature points of m1 onto m2). examples/face_a.png and face_b.png are
// these pictures at 256 x 256 (`build/bin/make_faces 256 examples/face_a.png
// examples/face_b.png`; tests/deform/faces_test.cpp checks that they are).
//
// The faces differ where a cross-fade shows it: face A is round, its eyes high
// and close together, a small button nose, a smile high up, ginger hair with a
// fringe, ears and pink cheeks, on sky blue; face B is a long oval, its eyes
// lower and further apart, a long nose, a wider mouth lower down, a brown bob
// that hides the ears, on pale yellow. A plain cross-fade shows two pairs of
// eyes and two mouths (ghosting); a morph that moves the feature points
// below onto each other does not.
//
// Coordinates: a picture covers the unit square [0, 1]^2, x to the right and y
// UP (OpenGL's texture coordinates). Pixel (px, py) of an N x N picture, py
// counted from the top (gllab::Image's rows run top-down), has its centre at
//     x = (px + 0.5) / N,   y = 1 - (py + 0.5) / N,
// and the point (x, y) lies in pixel (floor(x N), floor((1 - y) N)).
//
// Drawing: flat colours, painted back to front; each pixel is the mean of a
// fixed 4 x 4 grid of samples at x = (px + (i + 0.5) / 4) / N (and so in y),
// rounded to the nearest byte in integers: 17 levels of anti-aliasing on
// every edge, alpha 255. Every shape is made of ellipses and boxes (inside,
// outside, intersected), its numbers whole or half 1/256ths of the picture,
// so at a power-of-two size (256 included) every sample's inside test is
// computed exactly: the picture does not depend on rounding, the compiler or
// fused multiply-adds, and is the same bytes on every run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "spline/vec.h"

namespace gllab::deform {

enum class Face { kA, kB };

/// A named point of a face in the unit square (above). "left" and "right"
/// are as seen in the picture: left is the smaller x.
struct Feature {
  std::string name;
  spline::Vec2 at;
};

/// The same 12 names in the same order for both faces, top to bottom, each
/// with what the picture promises at its pixel at size 256 (the test checks
/// these):
///   top_of_head              top of the hair: hair 2 px below, background 2 px above
///   left_brow, right_brow    middle of the eyebrow's arch: brow colour
///   left_eye, right_eye      centre of the pupil (a dark disc): pupil colour
///   face_left, face_right    edge of the face at its widest: skin 2 px inward, hair outward
///   nose_tip                 centre of the nose's round tip: nose colour
///   mouth_left, mouth_right  corners of the mouth (a small disc each): mouth colour
///   mouth_centre             middle of the open mouth, between teeth and tongue: mouth colour
///   chin                     bottom of the face: skin 2 px above, neck 2 px below
/// Every point is at least 0.1 from the picture's border.
const std::vector<Feature>& face_features(Face face);

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
};
constexpr bool operator==(Rgb8 p, Rgb8 q) { return p.r == q.r && p.g == q.g && p.b == q.b; }
constexpr bool operator!=(Rgb8 p, Rgb8 q) { return !(p == q); }

/// The flat colours a face is painted with. Only the pupils are dark (every
/// channel at most 40); every other colour has a channel of 90 or more, so
/// the pupils can be found by a threshold. Face B has no cheeks or ears
/// (`cheek` and `ear` are unused there).
struct FaceColours {
  Rgb8 background, hair, skin, ear, cheek, brow, eye_white, iris, pupil, nose, mouth, teeth,
      tongue, neck, shirt;
};
const FaceColours& face_colours(Face face);

/// Radius of the pupils in the unit square (A 5/256, B 4.5/256).
double pupil_radius(Face face);

/// The face as a size x size picture (coordinates and drawing above). Throws
/// std::invalid_argument naming size unless 16 <= size <= 4096.
Image face_picture(Face face, int size);

/// "A" or "B".
const char* face_letter(Face face);

}  // namespace gllab::deform
