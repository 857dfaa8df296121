// tests/gl/nurbs_summary.cpp — prints tests/gl/nurbs_comparison.md, the own
// spline core against GLU on the whole suite (nurbs_compare.h):
//
//   cmake --build build --target nurbs_summary
//   build/tests/gl/nurbs_summary > tests/gl/nurbs_comparison.md
//
// With --images DIR it also writes every case's two renders and heat map
// into DIR (<case>__glu.png, __own.png, __heat.png), for a look.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "harness/offscreen.h"
#include "nurbs_compare.h"

int main(int argc, char** argv) {
  using namespace gllab::testing;
  try {
    std::string images;
    for (int k = 1; k < argc; ++k) {
      if (std::strcmp(argv[k], "--images") == 0 && k + 1 < argc) {
        images = argv[++k];
      } else {
        std::fprintf(stderr, "usage: nurbs_summary [--images DIR] > tests/gl/nurbs_comparison.md\n");
        return 2;
      }
    }
    gllab::OffscreenContext context(kImageSize, kImageSize);
    if (!images.empty()) {
      for (const CurveCase& c : curve_suite())
        write_images(images, c.name, render_glu_curve(c.curve, c.curve), render_own_curve(c.curve, c.curve));
      for (const SurfaceCase& c : surface_suite())
        write_images(images, c.name, render_glu_surface(c.surface, c.surface), render_own_surface(c.surface, c.surface));
      const SurfaceCase coarse = coarse_trim_example();
      write_images(images, coarse.name, render_glu_surface(coarse.surface, coarse.surface),
                   render_own_surface(coarse.surface, coarse.surface));
    }
    std::fputs(comparison_summary().c_str(), stdout);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "nurbs_summary: %s\n", e.what());
    return 1;
  }
}
