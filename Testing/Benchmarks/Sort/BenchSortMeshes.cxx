// Boundary-heavy tetrahedral meshes: see BenchSortMeshes.h.
#include "BenchSortMeshes.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <vector> // point index of every grid vertex

namespace hovBench
{
vtkSmartPointer<vtkUnstructuredGrid> Heatsink(
  int fins, int thickness, int gap, int ny, int base, int height)
{
  const int nx = fins * (thickness + gap), nz = base + height;
  auto solid = [&](int i, int j, int k) {
    (void)j;
    return k < base || (i % (thickness + gap)) < thickness;
  };
  // Vertices used by a solid cube get a point (index -1 otherwise).
  const auto vid = [&](int i, int j, int k) {
    return (static_cast<size_t>(k) * (ny + 1) + j) * (nx + 1) + i;
  };
  std::vector<vtkIdType> index(static_cast<size_t>(nx + 1) * (ny + 1) * (nz + 1), -1);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("temperature");
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        if (!solid(i, j, k))
        {
          continue;
        }
        for (int c = 0; c < 8; ++c)
        {
          const int a = i + (c & 1), b = j + ((c >> 1) & 1), z = k + ((c >> 2) & 1);
          vtkIdType& id = index[vid(a, b, z)];
          if (id < 0)
          {
            id = points->InsertNextPoint(a, b, z);
            scalars->InsertNextValue(100.0 - 2.0 * z + 0.1 * a);
          }
        }
      }
  vtkNew<vtkCellArray> cells;
  const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
    { 2, 1, 0 } };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        if (!solid(i, j, k))
        {
          continue;
        }
        for (const auto& p : perms)
        {
          // Corners 0, e_a, e_a + e_b, (1, 1, 1) of the cube at (i, j, k).
          int bits[4] = { 0, 1 << p[0], (1 << p[0]) | (1 << p[1]), 7 };
          vtkIdType ids[4];
          for (int v = 0; v < 4; ++v)
          {
            ids[v] = index[vid(i + (bits[v] & 1), j + ((bits[v] >> 1) & 1), k + ((bits[v] >> 2) & 1))];
          }
          cells->InsertNextCell(4, ids);
        }
      }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->SetCells(VTK_TETRA, cells);
  grid->GetPointData()->SetScalars(scalars);
  return grid;
}
}
