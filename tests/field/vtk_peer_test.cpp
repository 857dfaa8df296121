// tests/field/vtk_peer_test.cpp — field::marching_cubes against VTK 9.1's
// vtkMarchingCubes and vtkFlyingEdges3D on the same grids (peer_support.h:
// the 64^3 and 256^3 two-blob fields, a sphere, a torus, a noise field).
//
// What must agree: the vertices. Every peer puts one vertex on each grid edge
// whose ends lie on different sides of c, at the linear interpolation, so the
// vertex sets are equal up to rounding (1e-6), whatever the triangulation.
// What may differ: the triangles, in cells with a saddle face only. VTK's
// table is Lorensen and Cline's (the case alone decides), the own core's
// FaceRule::kDecider decides each saddle face by its own values: a cell with a
// saddle face can have other triangles, no other cell can. The test asserts
// that, and prints the counts (triangles per peer, cells whose counts differ,
// ambiguous cells) for bench/README.md.
//
// Built only when CMake finds VTK (tests/field/CMakeLists.txt); without it the
// one test below skips, with the reason.
#include <gtest/gtest.h>

#ifdef GLLAB_HAVE_VTK

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkMarchingCubes.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "peer_support.h"
#include "vtk_grid.h"

namespace gllab::field::peer {
namespace {

struct PeerMesh {
  std::vector<P3> vertices;
  std::vector<std::array<vtkIdType, 3>> triangles;
};

PeerMesh mesh_of(vtkPolyData* out) {
  PeerMesh m;
  vtkPoints* points = out->GetPoints();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  m.vertices.resize(std::size_t(n));
  for (vtkIdType k = 0; k < n; ++k) points->GetPoint(k, m.vertices[std::size_t(k)].data());
  vtkCellArray* polys = out->GetPolys();
  polys->InitTraversal();
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  while (polys->GetNextCell(npts, pts)) {
    EXPECT_EQ(npts, 3);
    if (npts == 3) m.triangles.push_back({pts[0], pts[1], pts[2]});
  }
  return m;
}

template <class Filter>
PeerMesh run_vtk(const Grid3& g, double c) {
  vtkSmartPointer<vtkImageData> image = gllab::field::testing::vtk_image(g);
  vtkNew<Filter> filter;
  filter->SetInputData(image);
  filter->SetValue(0, c);
  filter->ComputeNormalsOff();
  filter->ComputeGradientsOff();
  filter->ComputeScalarsOff();
  filter->Update();
  return mesh_of(filter->GetOutput());
}

// Triangles per cell (the cell's lowest corner, as a flat index): a
// triangle's vertices lie on its cell's edges, so its centroid lies in the cell.
std::map<std::size_t, std::uint32_t> peer_cell_counts(const Grid3& g, const PeerMesh& m) {
  std::map<std::size_t, std::uint32_t> counts;
  const double o[3] = {g.origin.x, g.origin.y, g.origin.z},
               h[3] = {g.spacing.x, g.spacing.y, g.spacing.z};
  const int n[3] = {g.nx, g.ny, g.nz};
  for (const auto& t : m.triangles) {
    int cell[3];
    for (int a = 0; a < 3; ++a) {
      const double centroid = (m.vertices[t[0]][a] + m.vertices[t[1]][a] + m.vertices[t[2]][a]) / 3;
      cell[a] = std::clamp(int(std::floor((centroid - o[a]) / h[a])), 0, n[a] - 2);
    }
    ++counts[(std::size_t(cell[2]) * g.ny + cell[1]) * g.nx + cell[0]];
  }
  return counts;
}

struct CellDiff {
  std::size_t differing = 0, differing_with_saddle = 0;
};

CellDiff compare_cells(const Grid3& g, const McResult& own,
                       const std::map<std::size_t, std::uint32_t>& peer) {
  std::map<std::size_t, std::pair<std::uint32_t, bool>> own_counts;  // triangles, has a saddle face
  for (const McCell& c : own.cells)
    own_counts[(std::size_t(c.k) * g.ny + c.j) * g.nx + c.i] = {c.triangle_count,
                                                                c.saddle_faces != 0};
  CellDiff d;
  auto count = [&](bool saddle) {
    ++d.differing;
    if (saddle) ++d.differing_with_saddle;
  };
  for (const auto& [cell, v] : own_counts) {
    const auto it = peer.find(cell);
    if ((it == peer.end() ? 0u : it->second) != v.first) count(v.second);
  }
  for (const auto& [cell, n] : peer)
    if (!own_counts.count(cell) && n != 0) count(false);  // a cell the own core does not cross
  return d;
}

class VtkPeer : public ::testing::TestWithParam<int> {
 protected:
  static void SetUpTestSuite() { vtkSMPTools::Initialize(1); }
};

TEST_P(VtkPeer, SameVerticesTrianglesDifferOnlyInSaddleCells) {
  const PeerCase pc = peer_case(GetParam());
  const Grid3& g = pc.grid;
  ASSERT_EQ(values_equal_to(g, pc.c), 0u)
      << pc.name << ": VTK calls f >= c inside, the own core f > c";

  McOptions decider;
  decider.normals = false;
  decider.record_cells = true;
  McOptions lc = decider;
  lc.faces = FaceRule::kLorensenCline;
  const McResult own = marching_cubes(g, pc.c, decider);
  const McResult own_lc = marching_cubes(g, pc.c, lc);
  const PeerMesh mc = run_vtk<vtkMarchingCubes>(g, pc.c);
  const PeerMesh fe = run_vtk<vtkFlyingEdges3D>(g, pc.c);

  const std::vector<P3> own_v = positions(own.mesh);
  const SetComparison vs_mc = compare_sets(own_v, mc.vertices);
  const SetComparison vs_fe = compare_sets(own_v, fe.vertices);
  EXPECT_TRUE(vs_mc.agree()) << pc.name << ": " << describe(vs_mc, "own", "vtkMarchingCubes");
  EXPECT_TRUE(vs_fe.agree()) << pc.name << ": " << describe(vs_fe, "own", "vtkFlyingEdges3D");
  // The own core's kLorensenCline rule puts the same vertices (only the triangles, and
  // so the order in which the vertices are numbered, differ).
  const SetComparison lc_vs_decider = compare_sets(positions(own_lc.mesh), own_v, 0.0);
  EXPECT_TRUE(lc_vs_decider.agree(0.0))
      << pc.name << ": " << describe(lc_vs_decider, "own LC", "own");

  const auto mc_cells = peer_cell_counts(g, mc);
  const CellDiff d_decider = compare_cells(g, own, mc_cells);
  const CellDiff d_lc = compare_cells(g, own_lc, mc_cells);
  EXPECT_EQ(d_decider.differing_with_saddle, d_decider.differing)
      << pc.name << ": a cell without a saddle face has other triangles than vtkMarchingCubes'";
  EXPECT_EQ(d_lc.differing_with_saddle, d_lc.differing) << pc.name << " (kLorensenCline)";
  // Flying edges uses vtkMarchingCubes' case table.
  EXPECT_EQ(fe.triangles.size(), mc.triangles.size()) << pc.name;

  std::printf(
      "[ peer     ] %s (%d x %d x %d, c = %g): vertices own %zu, vtkMarchingCubes %zu, "
      "vtkFlyingEdges3D %zu;"
      " max distance own<->MC %.2e/%.2e, own<->FE %.2e/%.2e\n",
      pc.name.c_str(), g.nx, g.ny, g.nz, pc.c, own_v.size(), mc.vertices.size(), fe.vertices.size(),
      vs_mc.a_to_b, vs_mc.b_to_a, vs_fe.a_to_b, vs_fe.b_to_a);
  std::printf(
      "[ peer     ]   triangles own decider %zu, own Lorensen-Cline %zu, vtkMarchingCubes %zu, "
      "vtkFlyingEdges3D %zu; crossed cells %zu, with a saddle face %zu; cells whose triangle count "
      "differs from VTK's: decider %zu (all with a saddle face: %s), Lorensen-Cline %zu\n",
      own.mesh.triangle_count(), own_lc.mesh.triangle_count(), mc.triangles.size(),
      fe.triangles.size(), own.cells.size(), ambiguous_cells(own), d_decider.differing,
      d_decider.differing == d_decider.differing_with_saddle ? "yes" : "no", d_lc.differing);
  RecordProperty("own_triangles", int(own.mesh.triangle_count()));
  RecordProperty("vtk_mc_triangles", int(mc.triangles.size()));
  RecordProperty("ambiguous_cells", int(ambiguous_cells(own)));
}

INSTANTIATE_TEST_SUITE_P(Grids, VtkPeer, ::testing::Range(0, kPeerCases),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return peer_case_name(info.param);
                         });

}  // namespace
}  // namespace gllab::field::peer

#else  // no VTK

#include "field_peer_config.h"

TEST(VtkPeer, Skipped) { GTEST_SKIP() << GLLAB_VTK_MISSING; }

#endif
