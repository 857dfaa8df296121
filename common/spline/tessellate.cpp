// common/spline/tessellate.cpp — see tessellate.h. Start reading here.
//
// The tessellator in parts, in reading order (each file's first lines say what
// it holds and which paper or book section it follows):
//   tessellate_curve.cpp   curve flattening (flatten_curve)
//   triangulate.cpp        ear clipping with hole bridging (triangulate_polygon)
//   tessellate.cpp         this file: tessellate_surface, and the steps of the
//                          patch tessellator in order (PatchTessellator::run)
//   patch_tessellator.h    the patch tessellator's class and data (internal)
//   patch_quadtree.cpp     S on the (u, v) lattice; the grid or restricted
//                          quadtree; patch-edge samples; cell lines, vertices
//   patch_trims.cpp        trims: flattening on the surface, trim-edge
//                          refinement, cutting at the cell lines
//   patch_leaves.cpp       each leaf's part of the trimmed region, triangulated
//   patch_mesh.cpp         the mesh output: points and normals, sliver flips
//   weld.cpp               the welding of patch edges (tessellate_patches)
//   mesh_measures.cpp      mesh_area, boundary_edges, contour_segments,
//                          surface_area, mesh_fidelity
//   tessellate_detail.h    the helpers two parts share (internal)
#include "spline/tessellate.h"

#include <cmath>
#include <string>
#include <vector>

#include "spline/errors.h"
#include "spline/patch_tessellator.h"

namespace gllab::spline {

namespace detail {

/// The steps of tessellate_surface (tessellate.h), in order; each step's
/// comment names the file that holds it.
Mesh PatchTessellator::run(const std::vector<TrimLoop>& trims) {
  check_input();
  nu_ = nv_ = Index{1} << opt_.max_depth;
  if (!adaptive_) nu_ = opt_.u_steps, nv_ = opt_.v_steps;
  // 1. Trims: validate, flatten curve pieces on the surface, refine edges
  //    (patch_trims.cpp).
  if (!trims.empty()) prepare_trims(trims);
  // 2. Cells: a fixed grid, or a quadtree refined until flat (and until no
  //    leaf holds many trim points), with patch edges sampled from the edge
  //    alone (patch_quadtree.cpp).
  if (adaptive_) {
    grow_quadtree();
  } else {
    build_grid();
  }
  for (int pass = 0;; ++pass) {
    if (adaptive_) finish_quadtree();  // restricted, leaves listed
    collect_lines();
    if (trimmed_) cut_trims();
    // 3. Each leaf's part of the trimmed region, merged along edge segments
    //    where leaves are finer than the edge samples; then triangles
    //    (patch_leaves.cpp).
    triangulate_leaves();
    // Verify and refine: ear-clipped triangles (cut cells) were never
    // tested against the surface. Where one misses the tolerance, split its
    // leaves and cut again.
    if (!adaptive_ || !split_leaves_of_failing_triangles()) break;
    reset_pass();
  }
  // 4. Points and normals on the surface; then slivers flipped away
  //    (patch_mesh.cpp).
  Mesh mesh = assemble();
  if (adaptive_) flip_slivers(mesh);
  return mesh;
}

void PatchTessellator::check_input() const {
  const std::string what = "tessellate_surface";
  if (!surface_) fail(ErrorCode::kEmptyInput, what + ": no surface evaluator given");
  if (!std::isfinite(dom_.u0) || !std::isfinite(dom_.u1) || !std::isfinite(dom_.v0) || !std::isfinite(dom_.v1) ||
      !(dom_.u0 < dom_.u1) || !(dom_.v0 < dom_.v1))
    fail(std::isfinite(dom_.u0) && std::isfinite(dom_.u1) && std::isfinite(dom_.v0) && std::isfinite(dom_.v1)
             ? ErrorCode::kEmptyDomain
             : ErrorCode::kNotFinite,
         what + ": domain " + to_string(dom_) + " is empty or not finite",
         {{"u0", dom_.u0}, {"u1", dom_.u1}, {"v0", dom_.v0}, {"v1", dom_.v1}});
  if (adaptive_) {
    if (!(opt_.tolerance > 0) || !std::isfinite(opt_.tolerance))
      fail(ErrorCode::kToleranceNotPositive, what + ": tolerance=" + num(opt_.tolerance) + " must be > 0",
           {{"tolerance", opt_.tolerance}});
    if (opt_.min_depth < 0 || opt_.min_depth > opt_.max_depth || opt_.max_depth > kMaxQuadtreeDepthLimit)
      fail(ErrorCode::kOutOfRange,
           what + ": need 0 <= min_depth=" + std::to_string(opt_.min_depth) +
               " <= max_depth=" + std::to_string(opt_.max_depth) + " <= " + std::to_string(kMaxQuadtreeDepthLimit),
           {{"min_depth", opt_.min_depth}, {"max_depth", opt_.max_depth}});
  } else if (opt_.u_steps < 1 || opt_.v_steps < 1 || opt_.u_steps > (1 << 20) || opt_.v_steps > (1 << 20)) {
    fail(ErrorCode::kOutOfRange,
         what + ": u_steps=" + std::to_string(opt_.u_steps) + ", v_steps=" + std::to_string(opt_.v_steps) +
             " (each must be 1..1048576)",
         {{"u_steps", opt_.u_steps}, {"v_steps", opt_.v_steps}});
  }
}

/// Forgets everything a pass built from the leaves (not the tree, the
/// trims or the surface samples).
void PatchTessellator::reset_pass() {
  leaves_.clear();
  line_i_.clear(), line_j_.clear(), line_u_.clear(), line_v_.clear();
  corners_on_vline_.clear(), corners_on_hline_.clear();
  verts_.clear(), vertex_id_.clear();
  leaf_trims_.clear(), trim_on_vline_.clear(), trim_on_hline_.clear(), row_segments_.clear();
  triangles_.clear(), clipped_.clear();
}

}  // namespace detail

TessellationOptions TessellationOptions::adaptive(double tolerance) {
  TessellationOptions o;
  o.sampling = Sampling::Adaptive;
  o.tolerance = tolerance;
  return o;
}

TessellationOptions TessellationOptions::fixed_steps(int u_steps, int v_steps) {
  TessellationOptions o;
  o.sampling = Sampling::FixedSteps;
  o.u_steps = u_steps;
  o.v_steps = v_steps;
  return o;
}

Mesh tessellate_surface(const SurfaceEvaluator& surface, UvDomain domain, const TessellationOptions& options,
                        const std::vector<TrimLoop>& trims) {
  return detail::PatchTessellator(surface, domain, options).run(trims);
}

}  // namespace gllab::spline
