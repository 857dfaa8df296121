// tests/field/density_test.cpp — the blob densities against the conditions
// of lecture notes ch. 1, §1.5 Blobby objects: f(0) = a, f(b) = 0,
// f'(0) = f'(b) = 0, monotonically decreasing, 0 beyond b.
#include "field/density.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace gllab::field {
namespace {

using Fn = double (*)(double, double, double);

struct Compact {
  const char* name;
  Fn f, df;
};

const Compact kCompact[] = {{"hermite", hermite_density, hermite_density_derivative},
                            {"wyvill", wyvill_density, wyvill_density_derivative}};

constexpr double kA = 1.7, kB = 0.8;

TEST(Density, CompactOnesMeetTheNotesFourConditions) {
  for (const Compact& d : kCompact) {
    SCOPED_TRACE(d.name);
    EXPECT_DOUBLE_EQ(d.f(0, kA, kB), kA);     // f(0) = a
    EXPECT_NEAR(d.f(kB, kA, kB), 0, 1e-15);   // f(b) = 0
    EXPECT_NEAR(d.df(0, kA, kB), 0, 1e-15);   // f'(0) = 0
    EXPECT_NEAR(d.df(kB, kA, kB), 0, 1e-14);  // f'(b) = 0
    // The polynomial itself is 0 with slope 0 at s = 1 too, so f is C^1 at b.
    EXPECT_NEAR(d.f(kB * (1 - 1e-9), kA, kB), 0, 1e-15);
    double prev = d.f(0, kA, kB);
    for (int k = 1; k <= 10000; ++k) {  // monotonically decreasing on a fine sample
      const double t = kB * k / 10000.0, v = d.f(t, kA, kB);
      ASSERT_LE(v, prev) << "t=" << t;
      ASSERT_LE(d.df(t, kA, kB), 1e-15) << "t=" << t;
      prev = v;
    }
    for (double t : {kB, 1.0001 * kB, 2 * kB, 100 * kB}) {  // 0 beyond b
      EXPECT_EQ(d.f(t, kA, kB), 0) << t;
      EXPECT_EQ(d.df(t, kA, kB), 0) << t;
    }
  }
}

TEST(Density, DerivativesMatchCentralDifferences) {
  for (const Compact& d : kCompact)
    for (double t : {0.1, 0.3, 0.5, 0.77}) {
      const double e = 1e-6;
      EXPECT_NEAR(d.df(t, kA, kB), (d.f(t + e, kA, kB) - d.f(t - e, kA, kB)) / (2 * e), 1e-8)
          << d.name << " t=" << t;
    }
  for (double t : {0.1, 0.5, 1.3}) {
    const double e = 1e-6;
    EXPECT_NEAR(blinn_density_derivative(t, kA, kB),
                (blinn_density(t, kA, kB) - blinn_density(t - e, kA, kB) +
                 blinn_density(t + e, kA, kB) - blinn_density(t, kA, kB)) /
                    (2 * e),
                1e-8);
  }
}

TEST(Density, HermiteIsAH0) {
  // H0(s) = 1 - 3 s^2 + 2 s^3 (the cubic Hermite basis): H0(1/2) = 1/2.
  EXPECT_DOUBLE_EQ(hermite_density(kB / 2, kA, kB), kA / 2);
  EXPECT_DOUBLE_EQ(hermite_density(0.25 * kB, kA, kB), kA * (1 - 3 / 16.0 + 2 / 64.0));
}

TEST(Density, WyvillIsHalfAtHalfTheRadius) {
  // 1 - 4/9 / 64 + 17/9 / 16 - 22/9 / 4 = (576 - 4 + 68 - 352) / 576 = 1/2.
  EXPECT_NEAR(wyvill_density(kB / 2, kA, kB), kA / 2, 1e-15);
}

TEST(Density, BlinnFailsCompactSupport) {
  // a exp(-4 t^2 / b^2): f(b) = a e^-4 > 0 and positive beyond b.
  EXPECT_NEAR(blinn_density(kB, kA, kB), kA * std::exp(-4.0), 1e-15);
  EXPECT_GT(blinn_density(kB, kA, kB), 0);
  EXPECT_GT(blinn_density(2 * kB, kA, kB), 0);
  EXPECT_DOUBLE_EQ(blinn_density(0, kA, kB), kA);
  EXPECT_EQ(blinn_density_derivative(0, kA, kB), 0);
}

TEST(Density, Names) {
  EXPECT_STREQ(density_name(Density::kHermite), "hermite");
  EXPECT_STREQ(density_name(Density::kWyvill), "wyvill");
  EXPECT_STREQ(density_name(Density::kBlinn), "blinn");
}


TEST(Density, IsoRadiusSolvesFEqualsC) {
  for (Density d : {Density::kHermite, Density::kWyvill, Density::kBlinn})
    for (double q : {0.01, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99}) {
      const double c = q * kA, r = iso_radius(d, kA, kB, c);
      EXPECT_NEAR(density_value(d, r, kA, kB), c, 1e-12) << density_name(d) << " c=" << c;
    }
  // Exact values: H0(1/2) = 1/2; Wyvill's f(b/2) = a/2.
  EXPECT_NEAR(iso_radius(Density::kHermite, kA, kB, kA / 2), kB / 2, 1e-15);
  EXPECT_NEAR(iso_radius(Density::kWyvill, kA, kB, kA / 2), kB / 2, 1e-14);
}

TEST(Density, MergeDistanceMakesTheMidpointReachC) {
  // 2 f(d / 2) = c at d = merge_distance.
  for (Density d : {Density::kHermite, Density::kWyvill, Density::kBlinn}) {
    const double c = 0.5, dist = merge_distance(d, 1, 1, c);
    EXPECT_NEAR(2 * density_value(d, dist / 2, 1, 1), c, 1e-12) << density_name(d);
  }
}

TEST(BlobField, ValueIsTheSum) {
  BlobField field{{{Vec3{0, 0, 0}, 1, 1}, {Vec3{0.5, 0, 0}, 2, 0.8}}, Density::kHermite};
  const Vec3 x{0.2, 0.1, -0.05};
  EXPECT_DOUBLE_EQ(field.value(x), hermite_density(norm(x), 1, 1) +
                                       hermite_density(norm(x - Vec3{0.5, 0, 0}), 2, 0.8));
}

TEST(BlobField, GradientMatchesCentralDifferences) {
  for (Density d : {Density::kHermite, Density::kWyvill, Density::kBlinn}) {
    BlobField field{{{Vec3{0, 0, 0}, 1, 1}, {Vec3{0.6, 0.1, 0}, 1.5, 0.7}}, d};
    for (const Vec3& x : {Vec3{0.2, 0.1, -0.05}, Vec3{0.4, -0.2, 0.3}, Vec3{-0.5, 0.3, 0.1}}) {
      const double e = 1e-6;
      const Vec3 g = field.gradient(x);
      const Vec3 fd{(field.value(x + Vec3{e, 0, 0}) - field.value(x - Vec3{e, 0, 0})) / (2 * e),
                    (field.value(x + Vec3{0, e, 0}) - field.value(x - Vec3{0, e, 0})) / (2 * e),
                    (field.value(x + Vec3{0, 0, e}) - field.value(x - Vec3{0, 0, e})) / (2 * e)};
      EXPECT_NEAR(g.x, fd.x, 1e-8) << density_name(d);
      EXPECT_NEAR(g.y, fd.y, 1e-8) << density_name(d);
      EXPECT_NEAR(g.z, fd.z, 1e-8) << density_name(d);
    }
    // At a centre the gradient is 0 (f'(0) = 0; the other blob adds its own).
    BlobField one{{{Vec3{0, 0, 0}, 1, 1}}, d};
    EXPECT_EQ(norm(one.gradient(Vec3{0, 0, 0})), 0);
  }
}

}  // namespace
}  // namespace gllab::field
