// common/mesh/level_of_detail.h — how many segments a curved surface needs
// for the size it has on screen (lecture notes ch. 1, §1.1 Overview,
// "Level-of-detail (LOD) techniques", and §1.2 Polygonal representation: what
// resolution makes the piecewise approximation appear smooth, and how the
// number of polygons relates to the size of the final display). No GL.
//
// A circle of radius r cut into n equal chords strays from each chord by at
// most the sagitta r (1 - cos(pi / n)), in the chord's middle. Seen from eye
// depth d through a perspective camera of focal length f pixels
// (f = (viewport height / 2) / tan(fovy / 2), gluPerspective), a length L
// near the view axis covers L f / d pixels. So a sphere or cylinder of radius r
// at depth d looks round to within e pixels when
//   (r f / d) (1 - cos(pi / n)) <= e,   i.e.  n >= pi / acos(1 - e d / (r f)).
// Near the silhouette the sagitta is seen edge on: that is where it shows.
#pragma once

namespace gllab {

/// r (1 - cos(pi / n)): the largest distance between a circle of radius r and
/// the regular n-gon inscribed in it. Throws std::invalid_argument unless
/// r >= 0 and n >= 2.
double chord_error(double radius, int segments);

/// The smallest n >= min_segments with chord_error(radius, n) <= max_error.
/// Throws unless radius >= 0, max_error > 0, min_segments >= 2, and when
/// n would exceed 10^9 (max_error / radius below about 5e-18).
int segments_for_chord_error(double radius, double max_error, int min_segments = 3);

/// length * focal_px / depth: the pixels a length covers at eye depth
/// `depth` > 0 (throws otherwise), focal_px as above.
double projected_length(double length, double depth, double focal_px);

/// (height_px / 2) / tan(fovy / 2) for gluPerspective's fovy in degrees, in
/// (0, 180); throws otherwise.
double focal_length_px(double fovy_degrees, int height_px);

}  // namespace gllab
