// common/deform/morph.h — image morphing as the lecture notes define it (ch. 1,
// §1.7 Surface representations, "Morphing"; after S. Lee et al. 1996, "Image
// morphing using deformation techniques"):
//   m(t, x, y) with m(0, ., .) = m1 and m(1, ., .) = m2. A deformation f2 maps
//   picked points of m1 onto m2 (plane.h fit_features); the geometry moves as
//   f(t, x) = (1 - t) x + t f2(x) while the colours blend.
// Both images are warped to the in-between geometry and blended:
//   m(t, y) = (1 - t) m1(x) + t m2(f2(x)),   x = f(t, .)^-1(y)  (Newton, plane.h),
// a backward warp: every output pixel asks where it came from. At t = 0 the
// inverse is x = y exactly and m = m1; at t = 1, f2(x) = y to 1e-13 and m = m2
// (byte for byte: the samples fall on pixel centres, or within 1e-10 of them).
// The plain cross-fade (1 - t) m1 + t m2 ignores the contours (ghosting).
//
// Pictures are sampled bilinearly, clamped at the border. Coordinates: the
// picture covers the unit square, x to the right and y up (OpenGL's texture
// coordinates); pixel (px, py) of a W x H image (py from the top) has its
// centre at ((px + 0.5) / W, 1 - (py + 0.5) / H).
#pragma once

#include "deform/plane.h"
#include "image/image.h"

namespace gllab::deform {

/// The colour of `image` at (x, y) of the unit square: bilinear between the
/// four nearest pixel centres, as floats 0..255 per channel (r, g, b, a).
std::array<float, 4> sample(const Image& image, Vec2 at);

/// (1 - t) m1 + t m2 per channel, rounded to the nearest byte. The images
/// must have the same size and t lie in [0, 1]; std::invalid_argument
/// naming them otherwise.
Image cross_fade(const Image& m1, const Image& m2, double t);

/// The morph m(t) above, the size of m1 (m2 the same size). Throws
/// std::invalid_argument when f2 folds (plane_fold_text), when the images
/// differ in size, t is outside [0, 1], or a pixel's inverse does not
/// converge (naming the pixel). One thread; deterministic.
Image morph(const Image& m1, const Image& m2, const PlaneDeformation& f2, double t);

}  // namespace gllab::deform
