// tests/opencsg/opencsg_peer.h — a CSG tree drawn by OpenCSG 1.5 (Kirsch and Döllner), the peer
// of lab 33's stencil rendering. OpenCSG links libGL and GLEW, so only programs with a GLX
// window use this (never an OSMesa program: docs/platform.md).
//
// OpenCSG::render draws one product (intersections and subtractions) into the depth buffer;
// the primitives are then shaded with glDepthFunc(GL_EQUAL). A tree with several products is
// drawn product by product, each product's depth and colour read back and kept where nearest.
#pragma once

#include <cstddef>

#include "gl/text.h"
#include "space/csg.h"

namespace gllab {

enum class OpenCsgAlgorithm { kGoldfeather, kScs };

/// Draws the tree into the current viewport with the current matrices, each primitive in
/// primitive_colour(id), unlit when lit is false (lab 33's flat colours), over `clear`.
/// Returns the number of products.
std::size_t draw_with_opencsg(const space::CsgTree& tree, OpenCsgAlgorithm algorithm, Rgb clear,
                              bool lit);

}  // namespace gllab
