// Issue 4, acceptance 1(a): one straight-edged quadratic tetrahedron
// (VTK_QUADRATIC_TETRA, type 24) with the nodal values of
//   f(x) = 0.12 + (x - c)^T M (x - c),   M symmetric positive definite,
// c inside the cell, so f along every ray through the cell is a quadratic
// with an interior minimum on the rays passing near c; the transfer function
// has 7 colour and 7 opacity nodes at different positions over f's range, so
// most rays cross several nodes twice (on both sides of the minimum).
//
// Every pixel of our float image (RenderImage + GetFloatImage) is compared
// with the independent reference of hovTestReferenceGeneral.h (quadratic
// field through vtkQuadraticTetra::InterpolationFunctions, exact ray/tet
// intersection, extremum and node crossings located in long double, adaptive
// Gauss-Kronrod with nested optical-depth quadrature): |error| <= 1e-6 per
// channel; orthographic and perspective; all three opacity semantics with
// Williams-Max emission and Wilhelms-Van Gelder with VTK-unstructured
// semantics. The reference's field is first checked against f itself.
#include "hovTestCellRuns.h"
#include "hovTestScenes.h"

#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <iostream>

using hovTestRef::Real;

namespace
{
const double TetPoints[4][3] = { { 0.0, 0.0, 0.0 }, { 1.2, 0.1, -0.2 }, { 0.3, 1.1, 0.25 },
  { 0.2, 0.35, 1.3 } };
const int Edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
const double Centre[3] = { 0.42, 0.38, 0.33 };
const double M[3][3] = { { 1.9, 0.3, -0.2 }, { 0.3, 1.4, 0.25 }, { -0.2, 0.25, 2.3 } };

double F(const double x[3])
{
  double d[3] = { x[0] - Centre[0], x[1] - Centre[1], x[2] - Centre[2] }, q = 0;
  for (int a = 0; a < 3; ++a)
  {
    for (int b = 0; b < 3; ++b)
    {
      q += d[a] * M[a][b] * d[b];
    }
  }
  return 0.12 + q;
}
}

int TestQuadraticTetra(int, char*[])
{
  hovTest::Checker ck;
  // The cell: corners, mid-edge nodes, nodal values of f.
  double nodes[10][3], s[10];
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("s");
  for (int i = 0; i < 10; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      nodes[i][a] =
        i < 4 ? TetPoints[i][a] : (TetPoints[Edges[i - 4][0]][a] + TetPoints[Edges[i - 4][1]][a]) / 2;
    }
    s[i] = F(nodes[i]);
    points->InsertNextPoint(nodes[i]);
    scalars->InsertNextValue(s[i]);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  const vtkIdType ids[10] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 };
  grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, ids);
  grid->GetPointData()->SetScalars(scalars);
  double range[2];
  scalars->GetRange(range);
  std::cout << "nodal range of f: [" << range[0] << ", " << range[1] << "], minimum 0.12 at c\n";

  const hovTestRef::QuadraticTetraField field(TetPoints, s);
  ck.Check(std::fabs(field({ Centre[0], Centre[1], Centre[2] }) - 0.12) < 1e-14,
    "the reference field (VTK shape functions) reproduces f at its minimum");

  hovTest::TF tf;
  const double colours[7][4] = { { 0.10, 0.1, 0.2, 0.9 }, { 0.18, 0.2, 0.8, 0.9 },
    { 0.27, 0.9, 0.9, 0.2 }, { 0.4, 1.0, 0.4, 0.1 }, { 0.55, 0.6, 0.1, 0.5 },
    { 0.8, 0.9, 0.8, 0.8 }, { 1.6, 0.2, 0.6, 0.3 } };
  const double opacities[7][2] = { { 0.10, 0.05 }, { 0.15, 0.7 }, { 0.22, 0.2 }, { 0.33, 0.85 },
    { 0.47, 0.1 }, { 0.7, 0.6 }, { 1.6, 0.3 } };
  for (const auto& c : colours)
  {
    tf.Color->AddRGBPoint(c[0], c[1], c[2], c[3]);
  }
  for (const auto& o : opacities)
  {
    tf.Opacity->AddPoint(o[0], o[1]);
  }
  tf.Property->SetScalarOpacityUnitDistance(0.4);

  const hovTestRef::ConvexCell cell = [] {
    hovTestRef::ConvexCell c;
    for (const auto& p : TetPoints)
    {
      c.Corners.push_back({ p[0], p[1], p[2] });
    }
    c.Faces = { { 0, 1, 2 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 2, 3 } };
    return c;
  }();
  hovTestRef::CellScene scene;
  scene.Intersect = [](const hovTestRef::Ray& r, Real& a, Real& b) {
    return hovTestRef::IntersectTetra(r, TetPoints, a, b);
  };
  scene.EdgeDistance = [](const hovTestRef::Ray& r) {
    return hovTestRef::DistanceToTetraEdges(r, TetPoints);
  };
  scene.Field = [field](const hovTestRef::Vec3& x) { return field(x); };

  // Sanity of the scene: rays through c have an interior minimum and cross nodes.
  {
    hovTestRef::Ray r;
    r.Origin = { Centre[0], Centre[1], Centre[2] - 3 };
    r.Direction = { 0.1, -0.05, 1 };
    r.TFar = 10;
    Real tIn, tOut;
    hovTestRef::GeneralStats st;
    if (hovTestRef::IntersectConvex(r, cell, tIn, tOut))
    {
      hovTestRef::BreakTimes([&](Real t) { return field(r.At(tIn + t)); }, tOut - tIn,
        hovTestRef::TransferFunctionNodes(tf.Property), 64, &st);
    }
    ck.Check(st.Extrema == 1 && st.Crossings >= 4,
      "a ray near c: " + std::to_string(st.Extrema) + " interior extremum, " +
        std::to_string(st.Crossings) + " node crossings (want 1 and >= 4)");
  }

  const double focal[3] = { 0.42, 0.4, 0.28 };
  const std::vector<hovTestRef::CellView> views = {
    { "orthographic", true, { 0.4, -0.9, 0.5 }, 5.0, { 0.0, 0.0, 1.0 }, 0.75 },
    { "perspective", false, { -0.7, -0.5, 0.8 }, 3.0, { 0.0, 1.0, 0.0 }, 30.0 },
  };
  const std::vector<hovTestRef::Model> models = { { 0, 0, 1.0 }, { 1, 0, 1.0 }, { 2, 0, 1.0 },
    { 1, 1, 0.6 } };
  hovTestRef::RunTotals totals;
  hovTestRef::RunCellCases(
    "quadratic tet", grid, scene, focal, views, models, tf.Property, 64, 48, totals);
  ck.Check(totals.Failures == 0,
    std::to_string(totals.Cases) + " cases against the reference, max error over all pixels " +
      hovTest::Fmt(totals.MaxError) + " (tolerance 1e-6)");
  return ck.Result();
}
