// tests/opencsg/opencsg_peer.cpp — OpenCSG as the peer of lab 33 (opencsg_peer.h).
// GLEW's header must come before any other GL header.
#include <GL/glew.h>
#include <opencsg.h>

#include "opencsg_peer.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "gl/csg_view.h"

namespace gllab {

namespace {

// A primitive of the tree as OpenCSG sees it: the same closed mesh lab 33 draws.
class Primitive : public OpenCSG::Primitive {
 public:
  Primitive(const space::CsgLeaf& leaf, bool complement)
      : OpenCSG::Primitive(complement ? OpenCSG::Subtraction : OpenCSG::Intersection, 1),
        leaf_(leaf) {}
  void render() override { draw_csg_primitive(leaf_); }

 private:
  space::CsgLeaf leaf_;
};

void shade(const space::CsgTree& tree, const space::Product& product, bool lit) {
  glDepthFunc(GL_EQUAL);
  glDisable(GL_CULL_FACE);
  if (lit) glEnable(GL_LIGHTING);
  else glDisable(GL_LIGHTING);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  for (const space::Literal& l : product) {
    const Rgb c = primitive_colour(l.primitive);
    glColor3f(c.r, c.g, c.b);
    draw_csg_primitive(tree.leaves()[std::size_t(l.primitive)]);
  }
  glDepthFunc(GL_LESS);
  glDisable(GL_LIGHTING);
}

}  // namespace

std::size_t draw_with_opencsg(const space::CsgTree& tree, OpenCsgAlgorithm algorithm, Rgb clear,
                              bool lit) {
  static const bool glew = glewInit() == GLEW_OK;
  (void)glew;
  OpenCSG::setOption(OpenCSG::AlgorithmSetting, algorithm == OpenCsgAlgorithm::kScs
                                                     ? OpenCSG::SCS
                                                     : OpenCSG::Goldfeather);
  OpenCSG::setOption(OpenCSG::DepthComplexitySetting, OpenCSG::NoDepthComplexitySampling);
  const std::vector<space::Product> sop = space::sum_of_products(tree);
  GLint v[4];
  glGetIntegerv(GL_VIEWPORT, v);
  const std::size_t pixels = std::size_t(v[2]) * v[3];
  std::vector<float> best_depth(pixels, 1.f), depth(pixels);
  std::vector<std::uint8_t> best_colour(pixels * 4), colour(pixels * 4);
  glEnable(GL_DEPTH_TEST);
  for (std::size_t k = 0; k < sop.size(); ++k) {
    std::vector<std::unique_ptr<Primitive>> owned;
    std::vector<OpenCSG::Primitive*> list;
    for (const space::Literal& l : sop[k]) {
      owned.push_back(std::make_unique<Primitive>(tree.leaves()[std::size_t(l.primitive)],
                                                  l.complement));
      list.push_back(owned.back().get());
    }
    glClearColor(clear.r, clear.g, clear.b, 1.f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    OpenCSG::render(list);
    shade(tree, sop[k], lit);
    if (sop.size() == 1) return 1;  // one product: the frame is done
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(v[0], v[1], v[2], v[3], GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    glReadPixels(v[0], v[1], v[2], v[3], GL_RGBA, GL_UNSIGNED_BYTE, colour.data());
    for (std::size_t p = 0; p < pixels; ++p)
      if (k == 0 || depth[p] < best_depth[p]) {
        best_depth[p] = depth[p];
        std::copy_n(&colour[4 * p], 4, &best_colour[4 * p]);
      }
  }
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_DEPTH_TEST);
  glWindowPos2i(v[0], v[1]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glDrawPixels(v[2], v[3], GL_RGBA, GL_UNSIGNED_BYTE, best_colour.data());
  glPopAttrib();
  return sop.size();
}

}  // namespace gllab
