// tests/space/csg_test.cpp — CSG trees (lecture notes, "3-D Graphics", "Solid Representation",
// "Constructive Solid Geometry"): classification against an independent evaluation, Roth's
// ray spans against classification, volumes against analytic values, and the sum of products
// against the tree.
#include "space/csg.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace {

namespace sp = gllab::space;
using sp::Vec3;

// Each primitive's implicit function written here again (negative inside, not a distance):
// the independent evaluation, combined with min (∪), max (∩) and max(a, −b) (−).
double implicit(const sp::CsgLeaf& l, Vec3 w) {
  const Vec3 p = l.to_local.apply(w);
  const double h = l.height / 2, rho2 = p.x * p.x + p.y * p.y;
  switch (l.shape) {
    case sp::Shape::kSphere: return std::sqrt(dot(p, p)) - l.radius;
    case sp::Shape::kBox:
      return std::max({std::abs(p.x) - l.size.x / 2, std::abs(p.y) - l.size.y / 2,
                       std::abs(p.z) - l.size.z / 2});
    case sp::Shape::kCylinder: return std::max(std::sqrt(rho2) - l.radius, std::abs(p.z) - h);
    case sp::Shape::kCone:  // radius r (h - z) / 2h at height z
      return std::max(std::sqrt(rho2) - l.radius * (h - p.z) / (2 * h), std::abs(p.z) - h);
  }
  return 0;
}
double evaluate(const sp::CsgTree& t, int node, Vec3 w) {
  const sp::CsgNode& n = t.nodes()[std::size_t(node)];
  if (n.op == sp::Op::kPrimitive)
    for (const sp::CsgLeaf& l : t.leaves())
      if (l.node == node) return implicit(l, w);
  if (n.op == sp::Op::kTransform) return evaluate(t, n.left, w);
  const double a = evaluate(t, n.left, w), b = evaluate(t, n.right, w);
  return n.op == sp::Op::kUnion ? std::min(a, b) : n.op == sp::Op::kIntersection ? std::max(a, b)
                                                                               : std::max(a, -b);
}

TEST(Csg, ClassificationAgreesWithMinMaxOfTheImplicitFunctions) {
  for (const sp::NamedTree& named : sp::csg_catalogue()) {
    std::size_t checked = 0, inside = 0;
    const int n = 31;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          const Vec3 p{-1.3 + 2.6 * i / (n - 1), -1.3 + 2.6 * j / (n - 1), -1.3 + 2.6 * k / (n - 1)};
          const double f = evaluate(named.tree, named.tree.root(), p);
          if (std::abs(f) < 0.02) continue;  // near the boundary the two may differ by design
          const sp::Where w = sp::classify(named.tree, p, 1e-9);
          EXPECT_EQ(w, f < 0 ? sp::Where::kInside : sp::Where::kOutside) << named.name;
          ++checked;
          inside += f < 0;
        }
    EXPECT_GT(checked, std::size_t(0.8 * n * n * n)) << named.name;
    EXPECT_GT(inside, 0u) << named.name;
  }
}

TEST(Csg, RaySpansAreInsideAndTheGapsOutside) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::size_t spans = 0;
  for (const sp::NamedTree& named : sp::csg_catalogue())
    for (int r = 0; r < 200; ++r) {
      const Vec3 o{3 * u(rng), 3 * u(rng), 3 * u(rng)};
      const Vec3 aim{0.5 * u(rng), 0.5 * u(rng), 0.5 * u(rng)};
      const std::vector<sp::Span> s = sp::ray_spans(named.tree, o, aim - o);
      double last = 0;
      for (const sp::Span& x : s) {
        ASSERT_LT(x.in.t, x.out.t);
        ASSERT_GE(x.in.t, last);
        const Vec3 mid = o + 0.5 * (x.in.t + x.out.t) * (aim - o);
        if (x.out.t - x.in.t > 1e-6) {
          EXPECT_NE(sp::classify(named.tree, mid, 0), sp::Where::kOutside) << named.name;
        }
        const Vec3 gap = o + 0.5 * (last + x.in.t) * (aim - o);
        if (x.in.t - last > 1e-6) {
          EXPECT_NE(sp::classify(named.tree, gap, 0), sp::Where::kInside) << named.name;
        }
        if (x.in.primitive >= 0) {  // (-1: the ray starts inside, the span at t = 0)
          EXPECT_NEAR(norm(x.in.normal), 1, 1e-9);
          EXPECT_LT(dot(x.in.normal, aim - o), 0) << named.name;  // entering: against the ray
        }
        last = x.out.t;
        ++spans;
      }
      const sp::CsgHit hit = sp::first_hit(named.tree, o, aim - o);
      EXPECT_EQ(hit.hit, !s.empty());
      if (hit.hit) {
        EXPECT_DOUBLE_EQ(hit.t, s[0].in.primitive >= 0 ? s[0].in.t : s[0].out.t);
      }
    }
  EXPECT_GT(spans, 1000u);
}

TEST(Csg, VolumesConvergeToTheAnalyticValues) {
  sp::CsgTree shell;  // a sphere minus a concentric sphere: 4/3 pi (R^3 - r^3)
  shell.subtract(shell.sphere(1.0), shell.sphere(0.6));
  const double exact_shell = 4.0 / 3 * M_PI * (1 - 0.216);
  sp::CsgTree boxes;  // two axis-aligned boxes overlapping in 0.6 x 0.8 x 1.0
  boxes.intersect(boxes.box({1, 1, 1}),
                  boxes.transform(sp::Affine::translate({0.4, 0.2, 0}), boxes.box({1, 1, 1.2})));
  const double exact_boxes = 0.6 * 0.8 * 1.0;
  sp::CsgTree cone;
  cone.cone(0.5, 1.2);
  const double exact_cone = M_PI * 0.25 * 1.2 / 3;
  for (auto [tree, exact] : {std::pair{&shell, exact_shell}, {&boxes, exact_boxes}, {&cone, exact_cone}}) {
    double previous = 1e300;
    for (int n : {16, 64, 256}) {
      const sp::VolumeEstimate v = sp::volume_by_rays(*tree, n);
      const double error = std::abs(v.value - exact);
      EXPECT_LE(error, previous + 1e-12) << n;  // (the boxes fill their bounds: exact at once)
      previous = error;
    }
    EXPECT_LT(previous, 2e-3 * exact);
    const sp::VolumeEstimate small = sp::volume_monte_carlo(*tree, 20000, 7);
    const sp::VolumeEstimate large = sp::volume_monte_carlo(*tree, 320000, 7);
    EXPECT_LE(std::abs(large.value - exact), large.error);  // within 3 standard errors
    if (large.error > 0) {
      EXPECT_NEAR(small.error / large.error, 4, 0.4);  // 16x the samples: a quarter
    } else {
      EXPECT_NEAR(large.value, exact, 1e-12);  // every sample inside: the bounds' volume
    }
  }
}

TEST(Csg, SumOfProductsHoldsTheSamePoints) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.3, 1.3);
  for (const sp::NamedTree& named : sp::csg_catalogue()) {
    const std::vector<sp::Product> sop = sp::sum_of_products(named.tree);
    ASSERT_FALSE(sop.empty());
    for (int k = 0; k < 3000; ++k) {
      const Vec3 p{u(rng), u(rng), u(rng)};
      const sp::Where w = sp::classify(named.tree, p, 1e-6);
      if (w == sp::Where::kOn) continue;
      bool in_some = false;
      for (const sp::Product& prod : sop) {
        bool all = true;
        for (const sp::Literal& l : prod)
          all &= (sp::leaf_distance(named.tree.leaves()[std::size_t(l.primitive)], p) < 0) != l.complement;
        in_some |= all;
      }
      EXPECT_EQ(in_some, w == sp::Where::kInside) << named.name;
    }
  }
  sp::CsgTree t;  // A − (B − C) = (A − B) ∪ (A ∩ C): the products {A, −B} and {A, C}
  t.subtract(t.sphere(1), t.subtract(t.sphere(0.5), t.sphere(0.2)));
  const std::vector<sp::Product> sop = sp::sum_of_products(t);
  ASSERT_EQ(sop.size(), 2u);
  EXPECT_TRUE(sop[0].size() == 2 && sop[0][0].primitive == 0 && sop[0][1].primitive == 1 &&
              sop[0][1].complement);
  EXPECT_TRUE(sop[1].size() == 2 && sop[1][1].primitive == 2 && !sop[1][1].complement);
}

TEST(Csg, BadInputIsOneLineNamingTheValue) {
  const auto message = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  sp::CsgTree t;
  EXPECT_EQ(message([&] { t.sphere(-1); }), "csg: sphere radius -1 (must be > 0)");
  EXPECT_NE(message([&] { sp::Affine::scale({1, 0, 1}); }).find("(1, 0, 1)"), std::string::npos);
  t.sphere(1);
  EXPECT_NE(message([&] { t.unite(0, 7); }).find("child 7"), std::string::npos);
  EXPECT_NE(message([&] { sp::classify(t, {NAN, 0, 0}); }).find("nan"), std::string::npos);
}

}  // namespace
