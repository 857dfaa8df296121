// tests/labs/36_arc_length_and_plotting_test.cpp — what lab 36's views promise:
// the printed length is the limit of chord sums (the definition of arc length,
// lecture notes ch. 1, §1.6, "Parameter transformation"), the notes' loop
// "t += delta" stops short of t = 1 and leaves a gap at every joint for
// delta = 0.05 but not for 0.125, and the drift figures are the core's, with
// forward differences in float far behind Horner.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "image/image.h"
#include "lab_test_support.h"
#include "spline/bspline.h"
#include "spline/forward_differences.h"

namespace {

using gllab::testing::numbers_after;
using gllab::testing::numbers_before;
using gllab::testing::render_view;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;
namespace sp = gllab::spline;

const std::string kLab = "36_arc_length_and_plotting";
// The lab's control points (labs/36_arc_length_and_plotting, "Lab data").
const std::vector<sp::Vec3> kPoints = {{-4.2, 0.1, 0}, {-3.9, 2.5, 0}, {-3.2, 0.3, 0}, {-2.0, 2.9, 0},
                                       {0.5, -0.3, 0}, {2.5, 3.0, 0},  {4.2, 0.3, 0}};

double chord_sum(const sp::BsplineCurve& c, int chords) {
  double sum = 0;
  sp::Vec3 last = sp::curve_point(c, 0);
  for (int k = 1; k <= chords; ++k) {
    const sp::Vec3 x = sp::curve_point(c, double(k) / chords);
    sum += sp::norm(x - last);
    last = x;
  }
  return sum;
}

// Chord sums grow to the length from below, their error falling like h^2, so
// (4 S(h) - S(2h)) / 3 (Richardson) is within far less than the printed 1e-9.
TEST(ArcLengthLab, PrintedLengthIsTheLimitOfChordSums) {
  ScratchDir dir("lab36");
  const std::vector<double> L = numbers_after(view_text(kLab, dir, "arc_length"), "L = ");
  ASSERT_EQ(L.size(), 1u);
  const sp::BsplineCurve c = sp::clamped_curve(kPoints, 3, 2);
  const double fine = chord_sum(c, 1 << 15), coarse = chord_sum(c, 1 << 14);
  EXPECT_LT(fine, L[0]);
  EXPECT_NEAR((4 * fine - coarse) / 3, L[0], 1e-9);
}

// The loop as the notes write it: 20 points and t = 0.95... for delta = 0.05;
// for delta = 0.125 (exact in binary) all 9, the last at t = 1.
TEST(ArcLengthLab, BruteForceLoopStopsShortForOneTwentieth) {
  ScratchDir dir("lab36");
  const auto notes = view_text(kLab, dir, "brute_force");
  EXPECT_EQ(numbers_before(notes, " points per segment,"), std::vector<double>{20});
  EXPECT_EQ(numbers_after(notes, "  the last at t = "), std::vector<double>{0.95000000000000029});
  const auto exact = view_text(kLab, dir, "brute_force", {"delta=2"});
  EXPECT_EQ(numbers_before(exact, " points per segment,"), std::vector<double>{9});
  EXPECT_EQ(numbers_after(exact, "  the last at t = "), std::vector<double>{1});
}

// The gaps are in the picture: at the pixel of the middle of each missing piece
// (segment i from t = 0.95 to 1, before the joint; 0.05 x a speed of about 1
// unit, some 3 pixels long) the curve's colour is missing for delta = 0.05 and
// present for delta = 0.125 (which draws t up to exactly 1).
TEST(ArcLengthLab, BruteForceGapsShowAtTheJoints) {
  ScratchDir dir("lab36");
  const gllab::testing::Rgb8 curve{217, 217, 230};  // (.85, .85, .9)
  const auto count_near_gaps = [&](const gllab::Image& im) {
    long long n = 0;
    for (std::size_t i = 3; i + 1 < kPoints.size(); ++i) {
      const auto abcd = sp::uniform_cubic_coefficients(kPoints[i - 3], kPoints[i - 2], kPoints[i - 1], kPoints[i]);
      const double t = 0.975;
      const sp::Vec3 x = ((abcd[0] * t + abcd[1]) * t + abcd[2]) * t + abcd[3];
      // ortho_fit(4.5, 4.5) in 512 x 512: 512 / 9 px per unit, y down.
      const int px = static_cast<int>((x.x + 4.5) * 512 / 9), py = static_cast<int>((4.5 - x.y) * 512 / 9);
      n += gllab::testing::has_colour(im, px, py, {curve});
    }
    return n;
  };
  const long long notes = count_near_gaps(render_view(kLab, dir, "brute_force"));
  const long long exact = count_near_gaps(render_view(kLab, dir, "brute_force", {"delta=2"}));
  EXPECT_EQ(notes, 0);
  EXPECT_EQ(exact, 3);  // the 3 joints
}

// The legend's figures at n = 10^6 are the core's cubic_plot_error for segment
// P[2..5]; forward differences in float are far behind Horner in float (the
// drift), and Horner in double is at double's rounding.
TEST(ArcLengthLab, DriftFiguresAreTheCores) {
  ScratchDir dir("lab36");
  const auto lines = view_text(kLab, dir, "forward_differences");
  const auto abcd = sp::uniform_cubic_coefficients(kPoints[2], kPoints[3], kPoints[4], kPoints[5]);
  const std::vector<std::pair<std::string, sp::CubicMethod>> rows = {
      {"forward differences, float ", sp::CubicMethod::kForwardFloat},
      {"Horner, float ", sp::CubicMethod::kHornerFloat},
      {"forward differences, double ", sp::CubicMethod::kForwardDouble},
      {"Horner, double ", sp::CubicMethod::kHornerDouble}};
  std::vector<double> printed;
  for (const auto& [name, method] : rows) {
    std::vector<std::string> trimmed;  // the legend pads the names to one width
    for (const std::string& l : lines)
      if (l.rfind(name, 0) == 0) trimmed.push_back(name + l.substr(l.find_first_not_of(' ', name.size())));
    const std::vector<double> v = numbers_after(trimmed, name);
    ASSERT_EQ(v.size(), 1u) << name;
    const double core = sp::cubic_plot_error(abcd, 1000000, method);
    EXPECT_NEAR(v[0], core, 0.05 * core) << name;  // printed with 2 digits
    printed.push_back(v[0]);
  }
  EXPECT_GT(printed[0], 1000 * printed[1]);
  EXPECT_LT(printed[3], 1e-14);
}

}  // namespace
