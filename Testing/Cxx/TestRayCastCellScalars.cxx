// RAY_CAST renders cell scalars (issue 19): a piecewise-constant field, one
// value per cell, whose segment integral is the constant-field closed form
// in both CPU modes. Scenes: [-1,1]^3 as 3x3x3 Kuhn cubes of linear
// tetrahedra and a 2x2x2 block of linear hexahedra
// (vtkHexahedron, converted to order-1 Lagrange cells by RAY_CAST), each
// cell's value a function of its centroid; an oblique perspective view.
// Expected: RAY_CAST's float image equals CPU_ACCURATE's within 1e-6 per
// channel, composite and every blend mode, no message; the image covers
// pixels. Max and mean differences per channel are printed.
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>

namespace
{
/// RAY_CAST against CPU_ACCURATE on the same constant-per-cell field: both
/// closed forms in double, compared in float; measured max 0 (identical images).
constexpr double CellScalarTolerance = 1e-6;
constexpr int W = 36, H = 32;

/// @p grid with its point scalars replaced by one value per cell.
void ToCellScalars(vtkUnstructuredGrid* grid)
{
  vtkNew<vtkDoubleArray> values;
  values->SetName("cells");
  values->SetNumberOfTuples(grid->GetNumberOfCells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    double centre[3] = { 0, 0, 0 };
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      grid->GetPoint(ids[i], x);
      for (int k = 0; k < 3; ++k)
      {
        centre[k] += x[k] / n;
      }
    }
    values->SetValue(c, 0.7 + 0.4 * centre[0] - 0.3 * centre[1] * centre[2] + 0.2 * centre[2]);
  }
  grid->GetPointData()->SetScalars(nullptr);
  grid->GetCellData()->SetScalars(values);
}

vtkSmartPointer<vtkUnstructuredGrid> HexBlock()
{
  hovTest::MeshBuilder m;
  vtkIdType id[3][3][3];
  for (int k = 0; k < 3; ++k)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int i = 0; i < 3; ++i)
      {
        id[i][j][k] = m.AddPoint(-1.0 + i, -1.0 + j, -1.0 + k, 0.0);
      }
    }
  }
  for (int k = 0; k < 2; ++k)
  {
    for (int j = 0; j < 2; ++j)
    {
      for (int i = 0; i < 2; ++i)
      {
        m.AddCell(VTK_HEXAHEDRON, { id[i][j][k], id[i + 1][j][k], id[i + 1][j + 1][k],
                                    id[i][j + 1][k], id[i][j][k + 1], id[i + 1][j][k + 1],
                                    id[i + 1][j + 1][k + 1], id[i][j + 1][k + 1] });
      }
    }
  }
  return m.Grid();
}
}

int TestRayCastCellScalars(int, char*[])
{
  hovTest::Checker check;
  vtkNew<vtkCamera> cam;
  cam->SetPosition(2.9, 2.2, 4.6);
  cam->SetFocalPoint(0.02, 0.01, -0.03);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(32);
  cam->SetClippingRange(1.0, 20.0);
  hovTest::MeshBuilder tets;
  const double o[3] = { -1, -1, -1 }, size[3] = { 2, 2, 2 };
  tets.AddTetBlock(3, 3, 3, o, size, hovTest::DefaultField);
  const vtkSmartPointer<vtkUnstructuredGrid> grids[2] = { tets.Grid(), HexBlock() };
  const char* names[2] = { "tetrahedra", "hexahedra" };
  for (int g = 0; g < 2; ++g)
  {
    ToCellScalars(grids[g]);
    hovTest::VolumeScene scene(grids[g]);
    hovTest::DefaultTF(scene.Tf, 0.5);
    vtkHighOrderVolumeMapper* mapper = scene.Mapper;
    for (int blend = 0; blend <= 3; ++blend)
    {
      mapper->SetBlendMode(blend);
      mapper->SetRenderModeToCPUAccurate();
      const hovTest::Image cpu = hovTest::Render(mapper, cam, scene.Volume, W, H);
      mapper->SetRenderModeToRayCast();
      int status = 0;
      const hovTest::Image ray = hovTest::Render(mapper, cam, scene.Volume, W, H, &status);
      const hovTest::DiffStats d = hovTest::Diff(ray, cpu);
      const hovTest::Sanity s = hovTest::CheckImage(ray);
      const std::string what = std::string(names[g]) + ", blend mode " + std::to_string(blend);
      std::cout << "[measured] " << what << ": RAY_CAST - CPU_ACCURATE " << d.Str() << "\n";
      check.Check(status == 1 && s.Ok() && s.Covered > static_cast<size_t>(W * H / 10),
        what + ": RAY_CAST renders the cell scalars (" + s.Str() + ")");
      check.Check(d.Count > 0 && d.Max <= CellScalarTolerance,
        what + ": RAY_CAST equals CPU_ACCURATE within " + hovTest::Fmt(CellScalarTolerance));
    }
    check.Check(scene.NoMessages(), std::string(names[g]) + ": no message");
  }
  return check.Result();
}
