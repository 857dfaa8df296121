// tests/field/vtk_grid.h — a Grid3 as VTK's vtkImageData, for the peer test
// (vtk_peer_test.cpp) and the benchmark (bench/iso_bench.cpp): the same floats,
// origin and spacing, no copy (VTK does not free them; keep the grid alive).
#pragma once

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include "field/grid.h"

namespace gllab::field::testing {

inline vtkSmartPointer<vtkImageData> vtk_image(const Grid3& g) {
  vtkNew<vtkFloatArray> scalars;
  scalars->SetNumberOfComponents(1);
  scalars->SetArray(const_cast<float*>(g.values.data()), vtkIdType(g.values.size()), 1);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(g.nx, g.ny, g.nz);
  image->SetOrigin(g.origin.x, g.origin.y, g.origin.z);
  image->SetSpacing(g.spacing.x, g.spacing.y, g.spacing.z);
  image->GetPointData()->SetScalars(scalars);
  return image;
}

}  // namespace gllab::field::testing
