// common/gl/csg_view.h — what labs 32 (solid models) and 33 (CSG with the stencil buffer)
// draw that is not their lesson: the primitives as closed meshes, a full-screen quad, the
// tree as a diagram, the core's ray-cast image, and the buffers a pass leaves behind.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gl/panels.h"
#include "gl/text.h"
#include "image/compare.h"
#include "image/image.h"
#include "space/csg.h"

namespace gllab {

/// The passes of one frame, counted so that a view can stop after pass `limit`: an
/// algorithm calls next("what it did") after each pass and returns when it says false.
struct Passes {
  int limit = 1 << 30, done = 0;
  std::string what;  // what the last pass did
  bool next(const std::string& text) { return what = text, ++done < limit; }
};

/// "cyl x" for a literal of primitive "cyl x", "−cyl x" for its complement.
std::string literal_name(const space::CsgTree& tree, const space::Literal& literal);

/// The colour of primitive `id` (a palette of eight, repeated).
Rgb primitive_colour(int id);

/// The primitive as a closed convex mesh in world coordinates (its to_world transform on the
/// model-view stack), outward normals, faces counter-clockwise seen from outside (a mirroring
/// transform flips glFrontFace for the call). Spheres 48 × 24, cylinders and cones 48 around.
void draw_csg_primitive(const space::CsgLeaf& leaf);

/// A quad over the whole viewport at window depth `depth` (0 near, 1 far), never culled; the
/// matrices and the enables are left as they were.
void draw_screen_quad(double depth);

/// The tree as a diagram in window pixels (x from the left, y down from the top): operators
/// as ∪ ∩ − (transforms folded into their child), primitives in their colours and names.
void draw_csg_diagram(const space::CsgTree& tree, int x, int y, int w, int h);

/// The camera GL has now (projection, model-view, viewport) as the core's PixelCamera.
space::PixelCamera current_pixel_camera();

/// The core's ray-cast image of the tree under the current camera, in the panel's pixels:
/// each hit in its primitive's colour, flat (lit = false) or with a headlight (lit = true),
/// the background `clear`. Top-down like any Image.
Image ray_cast_picture(const space::CsgTree& tree, Rgb clear, bool lit);

/// A width x height picture, pixel (i, j) (j = 0 the bottom row) in colour(i, j).
Image make_picture(int width, int height, const std::function<Rgb(int, int)>& colour);

/// An image drawn into the current viewport at its lower left corner (glDrawPixels; depth
/// test off), and the current viewport read back as an Image.
void draw_image(const Image& image);
Image read_viewport();

/// The depth and stencil buffers of the current viewport as pictures: depth as grey (near
/// white, far dark grey, stretched over the depths drawn; the far plane dark blue), stencil
/// value v in primitive_colour(v - 1) (0 black).
Image depth_picture();
Image stencil_picture();

/// The tree's diagram and `lines` of text: the diagram in the window's top right corner and
/// the text at its bottom left, or both in the bottom right quarter (quarter = true).
void draw_csg_caption(const space::CsgTree& tree, const std::vector<std::string>& lines,
                      int width, int height, bool quarter = false);

/// Reads the depth and stencil buffers of panel `depth`, then draws them as depth_picture()
/// there and as stencil_picture() in panel `stencil`.
void show_depth_and_stencil(const Panel& depth, const Panel& stencil);

/// What panel `ours` shows against the core's ray cast of the tree under the current camera
/// in that panel (flat colours, background `clear`): the ray cast is drawn in panel `truth`,
/// the heat map (reference = ray cast; 1-pixel shifts excused, image/compare.h) in `heat`.
Comparison compare_with_ray_cast(const space::CsgTree& tree, Rgb clear, const Panel& ours,
                                 const Panel& truth, const Panel& heat);

}  // namespace gllab
