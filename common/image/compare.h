// common/image · comparing a rendered image with its reference
// A headless run renders a lab view, and compare_images measures how far it is
// from reference_images/NN_*.png. Drivers differ in the last bit of a colour and
// in which pixels an edge covers, so a test passes within a Tolerance: a pixel
// counts as different only when a channel moves by more than channel_threshold,
// and a small share of different pixels is allowed. heat_map shows where they are.
//
// Lines are where renderers disagree most: softpipe and llvmpipe put a
// one-pixel line on neighbouring pixels (docs/platform.md). A shift_radius of 1
// excuses a differing pixel when each image has, within one pixel of it, a
// pixel matching the other image's colour there: a line drawn one pixel over
// is excused, a missing line, a moved vertex or a wrong colour is not.
//
// With an edge_contrast E > 0 a shift excuses a pixel only on a thin feature:
// where the pixel, in the reference or in the test, differs from one of its 8
// neighbours by at least E in some channel (a line, an edge, a glyph). On a
// smooth surface neighbours are alike, so a surface whose colour changed is
// never excused, however close the neighbouring shades are.
#pragma once

#include "image/image.h"

namespace gllab {

struct Tolerance {
  int channel_threshold = 0;       // a pixel differs when any channel (R,G,B,A) differs by more than this
  double max_differing_share = 0;  // pass when mismatched_pixels / total_pixels <= this (a fraction, 0.001 = 0.1 %)
  int shift_radius = 0;            // excuse differences explained by a shift of up to this many pixels
  int edge_contrast = 0;           // > 0: excuse only on a thin feature (a neighbour this different); 0: anywhere
  double max_shifted_share = 1;    // and pass only when shifted_pixels / total_pixels <= this
};

struct Comparison {
  long long total_pixels = 0;
  long long differing_pixels = 0;  // pixels with max channel delta > channel_threshold
  int max_delta = 0;               // largest absolute channel difference anywhere (0..255)
  double mean_abs_error = 0;       // mean over all channels of all pixels, in 0..255 units
  double psnr = 0;                 // dB over all channels, peak 255; +infinity when identical
  long long mismatched_pixels = 0; // differing pixels that no shift of <= shift_radius explains
  int channel_threshold = 0;       // the threshold compare_images counted differing_pixels with
  int shift_radius = 0;            // the shift radius compare_images excused differences with
  int edge_contrast = 0;           // the edge contrast a shift needed to be excused (0: none)

  long long shifted_pixels() const { return differing_pixels - mismatched_pixels; }  // excused by a shift
  double differing_share() const;   // differing_pixels / total_pixels
  double mismatched_share() const;  // mismatched_pixels / total_pixels: the metric passes() judges
  double shifted_share() const;     // shifted_pixels() / total_pixels
  /// The score in units of the limits: the larger of mismatched_share() /
  /// t.max_differing_share and shifted_share() / t.max_shifted_share; a render
  /// passes at <= 1. A zero limit counts any pixel over it as infinitely far.
  /// Throws std::invalid_argument when t's channel_threshold, shift_radius or
  /// edge_contrast is not what this Comparison was computed with, since the
  /// counts would then mean something else.
  double score(const Tolerance& t) const;
  /// Both shares within their limits (the comparison of score() with 1,
  /// without its rounding); throws like score().
  bool passes(const Tolerance& t) const;
};

/// Compares two images of the same size, channel by channel.
/// Throws ImageError on size mismatch: "compare: size mismatch: reference 512x512, test 256x256",
/// and std::invalid_argument for an empty or malformed image or a channel_threshold
/// outside 0..255 or a shift_radius outside 0..kMaxShiftRadius.
Comparison compare_images(const Image& reference, const Image& test, int channel_threshold,
                          int shift_radius = 0, int edge_contrast = 0);
/// The same with the Tolerance's threshold, radius and edge contrast.
Comparison compare_images(const Image& reference, const Image& test, const Tolerance& t);
inline constexpr int kMaxShiftRadius = 3;

/// A picture of the differences, same size as the inputs, fully opaque:
///  - where the max channel delta <= channel_threshold: the reference as dark grey
///    (luma/4), so the picture stays recognisable;
///  - where it exceeds the threshold but a shift of <= shift_radius explains it
///    (tolerated): blue (0,96,255);
///  - where it exceeds the threshold unexplained: a ramp from yellow (255,255,0)
///    just over the threshold to red (255,0,0) at a delta of 255.
/// Throws like compare_images.
Image heat_map(const Image& reference, const Image& test, int channel_threshold,
               int shift_radius = 0, int edge_contrast = 0);

}  // namespace gllab
