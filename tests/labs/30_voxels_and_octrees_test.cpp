// tests/labs/30_voxels_and_octrees_test.cpp — what lab 30 promises (lecture
// notes ch. 1, §1.8 Space partitioning, "Octrees"):
//  - voxels: n^3 voxels at one bit each, and the voxel volume tends to the
//    torus's 2 pi^2 R r^2 (Pappus) as n grows;
//  - octree: at equal depth the covered leaves hold exactly the voxels of the
//    grid (the property, on the lab's own torus);
//  - memory: voxels (a byte each) grow 8 times per doubling of n, the octree
//    about 4 times (its nodes lie on the surface), so the ratio grows with n;
//  - picking: the octree finds the brute-force hit and tests a small fraction
//    of the triangles; a ray above the torus hits nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "lab_test_support.h"

namespace {

using gllab::testing::numbers_after;
using gllab::testing::ScratchDir;
using gllab::testing::view_text;

const std::string kLab = "30_voxels_and_octrees";

TEST(VoxelsAndOctreesLab, VoxelCountMemoryAndVolume) {
  ScratchDir dir("lab30");
  const double torus = 2 * M_PI * M_PI * 1 * 0.45 * 0.45;  // the lab's R = 1, r = 0.45
  double previous = 1;
  for (const int n : {16, 32, 64}) {
    const std::vector<std::string> text =
        view_text(kLab, dir, "voxels", {"n=" + std::to_string(n)});
    double cells = 0, bytes = 0, volume = 0, exact = 0;
    for (const std::string& line : text) {
      std::sscanf(line.c_str(), "memory at 1 bit a voxel: %lf B", &bytes);
      std::sscanf(line.c_str(), "volume %lf (torus %lf", &volume, &exact);
      int m = 0;
      char count[64] = {};
      if (std::sscanf(line.c_str(), "n = %d: %63s voxels", &m, count) == 2) {
        std::string digits(count);
        digits.erase(std::remove(digits.begin(), digits.end(), ','), digits.end());
        cells = std::stod(digits);
      }
    }
    EXPECT_EQ(cells, double(n) * n * n) << n;
    if (n == 16) {  // n^3 bits in whole 64-bit words: 512 B (shown in bytes below 1 KB)
      EXPECT_EQ(bytes, std::ceil(double(n) * n * n / 64) * 8);
    }
    EXPECT_NEAR(exact, torus, 1e-4);
    // The mesh (96 x 48 quads) lies inside the torus by at most r (1 - cos(pi / 48)) = 1e-3,
    // a volume deficit below 0.5 %; the voxels' error falls about as 1 / n.
    const double error = std::abs(volume / torus - 1);
    if (n > 16) {
      EXPECT_LT(error, previous) << n;
    }
    previous = error;
  }
  EXPECT_LT(previous, 0.02);
}

TEST(VoxelsAndOctreesLab, CoveredLeavesHoldTheGridsVoxels) {
  ScratchDir dir("lab30");
  for (const int depth : {2, 3, 4, 5, 6}) {
    const std::vector<std::string> text =
        view_text(kLab, dir, "octree", {"depth=" + std::to_string(depth)});
    bool found = false;
    for (const std::string& line : text) {
      char held[64] = {}, grid[64] = {};
      if (std::sscanf(line.c_str(), "covered leaves hold %63s voxels; the grid has %63s", held,
                      grid) == 2) {
        found = true;
        EXPECT_EQ(std::string(held), std::string(grid)) << depth;
      }
    }
    EXPECT_TRUE(found) << depth;
  }
}

TEST(VoxelsAndOctreesLab, OctreeMemoryGrowsWithTheSurface) {
  ScratchDir dir("lab30");
  std::vector<double> n, ratio;
  for (const std::string& line : view_text(kLab, dir, "memory")) {
    double m = 0, r = 0;
    const std::size_t open = line.rfind('(');
    if (std::sscanf(line.c_str(), "n = %lf:", &m) == 1 && open != std::string::npos &&
        std::sscanf(line.c_str() + open, "(%lfx)", &r) == 1) {
      n.push_back(m);
      ratio.push_back(r);
    }
  }
  ASSERT_EQ(n.size(), 7u);  // n = 4 .. 256
  // Byte voxels grow by 8 per doubling, the octree by about 4 (surface cells): the ratio
  // (voxels at a byte / octree) grows by about 2 per doubling once the cells are small
  // against the tube (n >= 64 here), and the octree is the smaller from n = 64 on.
  for (std::size_t i = 4; i < n.size(); ++i) {
    EXPECT_GT(ratio[i] / ratio[i - 1], 1.6) << n[i];
    EXPECT_LT(ratio[i] / ratio[i - 1], 2.5) << n[i];
  }
  EXPECT_GT(ratio[4], 1);
}

TEST(VoxelsAndOctreesLab, PickRayTestsFewTrianglesAndFindsTheBruteForceHit) {
  ScratchDir dir("lab30");
  const std::vector<std::string> text = view_text(kLab, dir, "picking");
  const std::vector<double> tested = numbers_after(text, "octree: ");
  const std::vector<double> all = numbers_after(text, "brute force: ");
  ASSERT_EQ(tested.size(), 1u);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0], 20);  // "20,480": strtod stops at the comma; 160 x 64 x 2 triangles
  EXPECT_GT(tested[0], 0);
  EXPECT_LT(tested[0], 20480 / 50.0);
  unsigned a = 0, b = 1;
  double ta = 0, tb = 1;
  bool hit = false;
  for (const std::string& line : text)
    hit |= std::sscanf(line.c_str(), "hit %u at t = %lf; brute force: %u at %lf", &a, &ta, &b,
                       &tb) == 4;
  ASSERT_TRUE(hit);
  EXPECT_EQ(a, b);
  EXPECT_EQ(ta, tb);
  // The cross-hair high above the centre: seen from 30 degrees above the ring's plane the ray
  // sinks 0.58 per unit and is still 0.5 above the tube's top (z = 0.45) where it leaves
  // the ring (r < 1.45): no triangle on the ray, in either search.
  const std::vector<std::string> hole = view_text(kLab, dir, "picking", {"A[0]=0,0,1.5"});
  EXPECT_NE(std::find(hole.begin(), hole.end(), "no hit (both)"), hole.end());
}

}  // namespace
