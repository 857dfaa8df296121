// tests/labs/09_glut_shapes_test.cpp — what lab 09 promises about its views:
// the freeglut call each cell names (the lab's table kCalls) is the call
// gllab::draw_glut_shape makes, and in glu_vs_glut_sphere GLU's and freeglut's
// wires lie on each other only when the slices are a multiple of 4.
#include <gtest/gtest.h>

#include <iterator>
#include <string>
#include <vector>

#include "gl/glut_shapes.h"
#include "image/image.h"
#include "lab_test_support.h"

namespace {

using gllab::testing::ScratchDir;

const std::string kLab = "09_glut_shapes";

// glut_solid and glut_wire caption each cell with the lab's table: the name
// after glutSolid/glutWire, then the arguments. Joined again they must be the
// call draw_glut_shape makes (common/gl/glut_shapes.cpp, glut_call_text: the
// argument sets recorded from freeglut), cell by cell in kGlutShapes order, so
// the page cannot name a call the picture does not show.
TEST(GlutShapesLab, EachCellNamesTheCallDrawGlutShapeMakes) {
  ScratchDir dir("lab09");
  for (const bool solid : {true, false}) {
    const std::string view = solid ? "glut_solid" : "glut_wire";
    const std::string prefix = solid ? "glutSolid" : "glutWire";
    const std::vector<std::string> text = gllab::testing::view_text(kLab, dir, view);
    const std::size_t n = std::size(gllab::kGlutShapes);
    ASSERT_EQ(text.size(), 2 * n + 1) << view;  // name and arguments per cell, then the title
    for (std::size_t i = 0; i < n; ++i)
      EXPECT_EQ(prefix + text[2 * i] + text[2 * i + 1], gllab::glut_call_text(gllab::kGlutShapes[i], solid))
          << view << ", cell " << i;
    EXPECT_EQ(text.back(), prefix + "<Shape>(arguments)");
  }
}

// Lecture notes ch. 1, §1.3 Polygon rendering with OpenGL, list the convenience function
// glutWiredTetrahedron; freeglut declares glutWireTetrahedron(void) (GL/freeglut_std.h), and
// that is the name the glut_wire view captions its tetrahedron with.
TEST(GlutShapesLab, WireTetrahedronIsGlutWireTetrahedronNotesSlip) {
  EXPECT_EQ(gllab::glut_call_text(gllab::GlutShape::kTetrahedron, false), "glutWireTetrahedron()");
}

// Both spheres are drawn with slices = 2 x glut_stacks; the captions give the
// arguments: (radius, slices, stacks).
TEST(GlutShapesLab, SphereCaptionsGiveTheSlicesAndStacks) {
  ScratchDir dir("lab09");
  const std::vector<std::string> text =
      gllab::testing::view_text(kLab, dir, "glu_vs_glut_sphere", {"glut_stacks=6"});
  ASSERT_GE(text.size(), 4u);
  EXPECT_EQ(text[0], "gluSphere");
  EXPECT_EQ(text[1], "(1, 12, 6)");
  EXPECT_EQ(text[2], "glutSolidSphere");
  EXPECT_EQ(text[3], "(1, 12, 6)");
}

// The middle cell of row 2 draws GLU's wire (orange, 1, 0.6, 0.2) and glut's
// (cyan, 0.3, 0.85, 1) on top of each other; glut's wins every depth tie.
// GLU's slice 0 points along +y and glut's along +x, so their meridians meet
// only when a quarter turn is a whole number of slices (slices % 4 == 0).
// Then every GLU edge is also a glut edge (glut only adds each quad's
// diagonal), and the lab's depth range makes glut's wire win each tie, so no
// orange is left. Measured (512 x 512): 1308 orange pixels in the cell at 10
// slices, 1580 at 14, none at 12 and 16.
long long orange_in_middle_cell(const gllab::Image& im) {
  // Cell centre (0, -0.75) in ortho_fit(512, 512, 3.3, 3.3): pixel (256, 314);
  // the sphere's radius 0.85 is 66 pixels.
  const gllab::Image mask = gllab::testing::colour_mask(im, {{255, 153, 51}}, 186, 244, 326, 384);
  return gllab::testing::mask_count(mask);
}

TEST(GlutShapesLab, WiresCoincideOnlyWhenSlicesAreAMultipleOfFour) {
  constexpr long long kMany = 500;  // well below the 1308 and 1580 measured
  ScratchDir dir("lab09");
  for (const int stacks : {5, 6, 7, 8}) {
    const gllab::Image im = gllab::testing::render_view(
        kLab, dir, "glu_vs_glut_sphere", {"glut_stacks=" + std::to_string(stacks)});
    const long long orange = orange_in_middle_cell(im);
    if ((2 * stacks) % 4 == 0) EXPECT_EQ(orange, 0) << 2 * stacks << " slices";
    else EXPECT_GT(orange, kMany) << 2 * stacks << " slices";
  }
}

}  // namespace
