// RAY_CAST on pyramids against the exact CPU_ACCURATE path (issue 6: the ray
// caster renders every cell the other paths render). The ray caster takes a
// linear pyramid (14) as an order-1 Lagrange hexahedron whose top face is
// collapsed to the apex, and a quadratic pyramid (27) as an order-2 one (each
// vtkQuadraticPyramid function has degree <= 2 in r, s and t): the same map
// and field, with a singular Jacobian at the apex.
//  1. The unit cube split into 6 pyramids sharing the centre as apex, a
//     linear field: an oblique perspective view (64 x 64), and a parallel
//     view along -z at 33 x 33 whose centre ray passes exactly through the
//     apex (and whose diagonal rays lie in the faces shared by the side
//     pyramids).
//  2. Loose sheared pyramids: a linear one and a quadratic one carrying a
//     quadratic field.
// Compared: the float images at pixels either covers; the ray caster's
// tolerance is 1e-3 per channel and its error estimates must stay below it.
// Before the conversion, pyramids were skipped with a warning (image empty).
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPyramid.h"
#include "vtkQuadraticPyramid.h"

#include <algorithm>
#include <array>
#include <iostream>

using namespace hovTest;

namespace
{
double Field(double x, double y, double z)
{
  return 0.2 + 0.5 * x + 0.4 * y + 0.3 * z;
}

/// The unit cube as 6 pyramids with their apex at the centre (bases oriented
/// so that the apex lies on the side of their right-hand normal).
vtkSmartPointer<vtkUnstructuredGrid> CubeOfPyramids()
{
  MeshBuilder m;
  vtkIdType corner[8];
  for (int k = 0; k < 8; ++k)
  {
    const double x = k & 1, y = (k >> 1) & 1, z = (k >> 2) & 1;
    corner[k] = m.AddPoint(x, y, z, Field(x, y, z));
  }
  const vtkIdType apex = m.AddPoint(0.5, 0.5, 0.5, Field(0.5, 0.5, 0.5));
  // Cube faces as corner cycles (bits: x = 1, y = 2, z = 4).
  const int faces[6][4] = { { 0, 2, 6, 4 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 }, { 2, 3, 7, 6 },
    { 0, 1, 3, 2 }, { 4, 5, 7, 6 } };
  for (const auto& f : faces)
  {
    std::array<std::array<double, 3>, 4> p;
    for (int k = 0; k < 4; ++k)
    {
      p[k] = m.Points[corner[f[k]]];
    }
    double u[3], v[3], w[3];
    for (int r = 0; r < 3; ++r)
    {
      u[r] = p[1][r] - p[0][r];
      v[r] = p[3][r] - p[0][r];
      w[r] = 0.5 - p[0][r];
    }
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
      u[0] * v[1] - u[1] * v[0] };
    const bool flip = n[0] * w[0] + n[1] * w[1] + n[2] * w[2] < 0.0;
    std::vector<vtkIdType> ids;
    for (int k = 0; k < 4; ++k)
    {
      ids.push_back(corner[f[flip ? 3 - k : k]]);
    }
    ids.push_back(apex);
    m.AddCell(VTK_PYRAMID, ids);
  }
  return m.Grid();
}

/// A linear and a quadratic pyramid, straight-edged, sheared.
vtkSmartPointer<vtkUnstructuredGrid> LoosePyramids()
{
  MeshBuilder m;
  vtkNew<vtkPyramid> p5;
  vtkNew<vtkQuadraticPyramid> p13;
  const double a[3][3] = { { 0.9, 0.18, 0.0 }, { 0.0, 0.9, 0.09 }, { 0.09, 0.0, 0.9 } };
  vtkCell* cells[2] = { p5, p13 };
  for (int c = 0; c < 2; ++c)
  {
    const double o[3] = { 1.4 * c, 0.0, 0.0 };
    const double* pc = cells[c]->GetParametricCoords();
    std::vector<vtkIdType> ids;
    for (int k = 0; k < cells[c]->GetNumberOfPoints(); ++k)
    {
      // The straight pyramid over the unit square with its apex at (0.5, 0.5,
      // 1) (every (r, s, 1) is the apex), sheared: a straight-edged cell.
      const double t = pc[3 * k + 2];
      const double q[3] = { (1.0 - t) * pc[3 * k] + 0.5 * t, (1.0 - t) * pc[3 * k + 1] + 0.5 * t,
        t };
      double x[3];
      for (int r = 0; r < 3; ++r)
      {
        x[r] = o[r] + a[r][0] * q[0] + a[r][1] * q[1] + a[r][2] * q[2];
      }
      const double u = x[0] - o[0], v = x[1] - o[1], w = x[2] - o[2];
      const double s = c == 0 ? Field(u, v, w) : 0.1 + 0.6 * u * u + 0.5 * v * w + 0.4 * w;
      ids.push_back(m.AddPoint(x[0], x[1], x[2], s));
    }
    m.AddCell(c == 0 ? VTK_PYRAMID : VTK_QUADRATIC_PYRAMID, ids);
  }
  return m.Grid();
}

/// CPU_ACCURATE vs RAY_CAST on @p grid; returns the RAY_CAST image.
Image Compare(Checker& ck, vtkUnstructuredGrid* grid, vtkCamera* cam, int w, int h,
  const std::string& name, vtkIdType cells)
{
  VolumeScene scene(grid);
  DefaultTF(scene.Tf, 0.5);
  const Image cpu = Render(scene.Mapper, cam, scene.Volume, w, h);
  const bool cpuClean = scene.NoMessages();
  scene.Mapper->SetRenderModeToRayCast();
  int status = 0;
  const Image ray = Render(scene.Mapper, cam, scene.Volume, w, h, &status);
  const Sanity s = CheckImage(ray), sc = CheckImage(cpu);
  const DiffStats d = Diff(cpu, ray, 0, 4, 1e-3);
  const double err = MaxRayCastError(scene.Mapper);
  std::cout << "[measured] " << name << ": RAY_CAST vs CPU_ACCURATE " << d.Str() << "; ray "
            << s.Str() << "; cpu covered " << sc.Covered << "; max error estimate " << err
            << std::endl;
  ck.Check(cpuClean && status == 1 && scene.NoMessages(),
    name + ": no error or warning ('" + Msg(scene.Observer->GetWarningMessage()) + "')");
  ck.Check(scene.Mapper->GetNumberOfSkippedCells() == 0 &&
      scene.Mapper->GetNumberOfRenderedCells() == cells,
    name + ": every pyramid rendered, none skipped");
  ck.Check(s.Ok() && s.Covered > 0 && s.Covered == sc.Covered, name + ": sane, same coverage");
  ck.Check(d.Count > 0 && d.Max < 1e-3, name + ": max difference below 1e-3");
  ck.Check(err >= 0.0 && err <= 1e-3, name + ": error estimate <= tolerance 1e-3");
  return ray;
}
}

int TestRayCastPyramid(int, char*[])
{
  Checker ck;
  vtkSmartPointer<vtkUnstructuredGrid> cube = CubeOfPyramids();
  vtkNew<vtkCamera> oblique;
  ObliqueCamera(oblique);
  Compare(ck, cube, oblique, 64, 64, "cube of 6 pyramids, oblique", 6);
  vtkNew<vtkCamera> axis;
  AxisOrthoCamera(axis);
  const Image apex = Compare(ck, cube, axis, 33, 33, "cube of 6 pyramids, ray through the apex", 6);
  // The centre pixel's ray crosses the whole cube (length 1) through the apex.
  ck.Check(apex.At(16, 16, 3) > 0.0, "the ray through the apex is drawn");

  vtkNew<vtkCamera> loose;
  loose->SetFocalPoint(1.2, 0.5, 0.5);
  loose->SetPosition(2.5, -2.0, 4.5);
  loose->SetViewUp(0, 1, 0);
  loose->SetViewAngle(35);
  loose->SetClippingRange(0.5, 30);
  Compare(ck, LoosePyramids(), loose, 96, 64, "sheared linear and quadratic pyramid", 2);
  return ck.Result();
}
