// Issue 4, acceptance 1(b): one trilinear hexahedron (VTK_HEXAHEDRON,
// type 12) against the independent reference (hovTestReferenceGeneral.h).
// (The file name carries the "TestQuadratic" prefix of the issue-4
// acceptance tests; the cell is trilinear.)
//
//  - "distorted": not a parallelepiped. The bottom face is a general convex
//    quadrilateral, the top is its image under a homothety of ratio 0.6 about
//    a point above it, so every face is planar (the cell is convex and its
//    boundary is unambiguous) while the trilinear map is not affine: along a
//    ray the interpolated scalar is NOT a polynomial. Nodal values make a
//    saddle-like field over the whole transfer-function range. Reference:
//    Newton inversion on vtkHexahedron's shape functions at every
//    quadrature node.
//  - "box": axis-aligned, nodal values of a trilinear f with an xyz term,
//    so the scalar along a ray is a cubic in t; the reference field is f
//    itself (and is checked against the shape-function field).
// Every pixel: |error| <= 1e-6 per channel; orthographic and perspective;
// box: GPU-compatible, VTK-unstructured and raw-extinction semantics
// (Williams-Max) and Wilhelms-Van Gelder with VTK-unstructured semantics;
// distorted: GPU-compatible Williams-Max and VTK-unstructured Wilhelms-Van
// Gelder (its Newton-based reference is slower).
#include "hovTestCellRuns.h"
#include "hovTestScenes.h"

#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <iostream>
#include <random>

using hovTestRef::Real;

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> OneHex(const double x[8][3], const double s[8])
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("s");
  for (int i = 0; i < 8; ++i)
  {
    points->InsertNextPoint(x[i]);
    scalars->InsertNextValue(s[i]);
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  const vtkIdType ids[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  grid->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
  grid->GetPointData()->SetScalars(scalars);
  return grid;
}

double Trilinear(const double* x)
{
  return 0.15 + 0.5 * x[0] + 0.2 * x[1] - 0.3 * x[2] + 0.6 * x[0] * x[1] - 0.7 * x[1] * x[2] +
    0.5 * x[0] * x[2] + 1.4 * x[0] * x[1] * x[2];
}

/// Runs both views and @p models for one hexahedron.
void RunHex(const char* name, const double x[8][3], const double s[8],
  const hovTestRef::CellScene& scene, vtkVolumeProperty* property,
  const std::vector<hovTestRef::Model>& models, int width, int height,
  hovTestRef::RunTotals& totals)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = OneHex(x, s);
  double focal[3] = { 0, 0, 0 };
  for (int i = 0; i < 8; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      focal[a] += x[i][a] / 8;
    }
  }
  const std::vector<hovTestRef::CellView> views = {
    { "orthographic", true, { 0.45, -0.8, 0.55 }, 5.0, { 0.0, 0.0, 1.0 }, 0.95 },
    { "perspective", false, { -0.6, -0.55, 0.75 }, 3.6, { 0.0, 1.0, 0.0 }, 34.0 },
  };
  hovTestRef::RunCellCases(name, grid, scene, focal, views, models, property, width, height, totals);
}
}

int TestQuadraticTrilinearHex(int, char*[])
{
  hovTest::Checker ck;
  hovTest::TF tf;
  const double colours[6][4] = { { 0.0, 0.1, 0.2, 0.9 }, { 0.25, 0.2, 0.8, 0.9 },
    { 0.45, 0.9, 0.9, 0.2 }, { 0.6, 1.0, 0.4, 0.1 }, { 0.85, 0.6, 0.1, 0.5 },
    { 1.5, 0.9, 0.8, 0.8 } };
  const double opacities[6][2] = { { 0.0, 0.05 }, { 0.2, 0.6 }, { 0.38, 0.15 }, { 0.52, 0.8 },
    { 0.75, 0.2 }, { 1.5, 0.5 } };
  for (const auto& c : colours)
  {
    tf.Color->AddRGBPoint(c[0], c[1], c[2], c[3]);
  }
  for (const auto& o : opacities)
  {
    tf.Opacity->AddPoint(o[0], o[1]);
  }
  tf.Property->SetScalarOpacityUnitDistance(0.5);
  hovTestRef::RunTotals totals;

  // Distorted hexahedron with planar faces.
  {
    const double bottom[4][3] = { { 0.0, 0.0, 0.0 }, { 1.3, 0.1, 0.0 }, { 1.1, 1.0, 0.0 },
      { -0.15, 0.8, 0.0 } };
    const double apex[3] = { 0.7, 0.3, 2.6 }, ratio = 0.6;
    double x[8][3];
    for (int i = 0; i < 4; ++i)
    {
      for (int a = 0; a < 3; ++a)
      {
        x[i][a] = bottom[i][a];
        x[i + 4][a] = apex[a] + ratio * (bottom[i][a] - apex[a]);
      }
    }
    const double s[8] = { 0.1, 0.95, 0.3, 1.2, 0.85, 0.15, 1.05, 0.4 };
    const hovTestRef::ConvexCell cell = hovTestRef::ConvexCell::Hexahedron(x);
    ck.Check(cell.MaxFaceNonPlanarity() < 1e-15,
      "distorted hexahedron: faces planar (" + hovTest::Fmt(double(cell.MaxFaceNonPlanarity())) + ")");
    const hovTestRef::HexahedronField field(x, s);
    hovTestRef::CellScene scene;
    scene.Intersect = [cell](const hovTestRef::Ray& r, Real& a, Real& b) {
      return hovTestRef::IntersectConvex(r, cell, a, b);
    };
    scene.EdgeDistance = [cell](const hovTestRef::Ray& r) {
      return hovTestRef::DistanceToCellEdges(r, cell);
    };
    scene.Field = [field](const hovTestRef::Vec3& p) { return field(p); };
    // Newton at every quadrature node makes this reference ~10x slower than
    // the box's: two models, 40 x 32 (test time).
    RunHex("distorted hex", x, s, scene, tf.Property, { { 0, 0, 1.0 }, { 1, 1, 0.6 } }, 40, 32,
      totals);
  }

  // Axis-aligned box with a trilinear field.
  {
    const double lo[3] = { -0.1, 0.0, 0.05 }, hi[3] = { 1.1, 0.9, 1.15 };
    double x[8][3], s[8];
    for (int i = 0; i < 8; ++i)
    {
      const int bx = (i == 1 || i == 2 || i == 5 || i == 6), by = (i == 2 || i == 3 || i == 6 || i == 7);
      x[i][0] = bx ? hi[0] : lo[0];
      x[i][1] = by ? hi[1] : lo[1];
      x[i][2] = i >= 4 ? hi[2] : lo[2];
      s[i] = Trilinear(x[i]);
    }
    const hovTestRef::HexahedronField field(x, s);
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    double worst = 0;
    for (int k = 0; k < 100; ++k)
    {
      const double p[3] = { lo[0] + (hi[0] - lo[0]) * u01(rng), lo[1] + (hi[1] - lo[1]) * u01(rng),
        lo[2] + (hi[2] - lo[2]) * u01(rng) };
      worst = std::max(worst, double(std::fabs(field({ p[0], p[1], p[2] }) - Trilinear(p))));
    }
    ck.Check(worst < 1e-13, "box: shape-function field == trilinear f (" + hovTest::Fmt(worst) + ")");
    const hovTestRef::ConvexCell cell = hovTestRef::ConvexCell::Hexahedron(x);
    hovTestRef::CellScene scene;
    scene.Intersect = [cell](const hovTestRef::Ray& r, Real& a, Real& b) {
      return hovTestRef::IntersectConvex(r, cell, a, b);
    };
    scene.EdgeDistance = [cell](const hovTestRef::Ray& r) {
      return hovTestRef::DistanceToCellEdges(r, cell);
    };
    scene.Field = [](const hovTestRef::Vec3& p) {
      // f in long double: the same polynomial, evaluated without rounding to double.
      const Real X = p[0], Y = p[1], Z = p[2];
      return Real(0.15) + Real(0.5) * X + Real(0.2) * Y - Real(0.3) * Z + Real(0.6) * X * Y -
        Real(0.7) * Y * Z + Real(0.5) * X * Z + Real(1.4) * X * Y * Z;
    };
    RunHex("box hex", x, s, scene, tf.Property,
      { { 0, 0, 1.0 }, { 1, 0, 1.0 }, { 2, 0, 1.0 }, { 1, 1, 0.6 } }, 48, 40, totals);
  }
  ck.Check(totals.Failures == 0,
    std::to_string(totals.Cases) + " cases against the reference, max error over all pixels " +
      hovTest::Fmt(totals.MaxError) + " (tolerance 1e-6)");
  return ck.Result();
}
