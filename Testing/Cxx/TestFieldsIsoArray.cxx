// Three fields (issue 4, HIAC 5): isosurfaces of a third point array.
//
// s = z on [0,1]^3 as 2^3 Kuhn-split cubes is the extinction field (a
// non-absorbing transfer function), a colour array "c" is set (the
// three-field path), and the isosurfaces come from component 1 of the
// 3-component point array "v" = (5, x, -2) (SetIsosurfaceArrayName,
// SetIsosurfaceArrayComponent): one unshaded surface of opacity 0.3 at
// v1 = 0.5, i.e. the plane x = 0.5 (also the shared faces of the cubes).
// Oblique orthographic view (0.3, 0.2, 1): |cos| = 0.3/|(0.3, 0.2, 1)|, so
// every pixel whose ray crosses the plane inside the cube has
// alpha = 1 - 0.7^(1/|cos|), the others 0 (to 1e-12, away from the square's
// border by 1e-6), both orderings. The magnitude (component -1) of "v" is
// never 0.5 inside the cube (>= 5.38): no surface at all (an empty image,
// with the mapper's warning that it is empty). Also: a missing
// or non-numeric isosurface array is an error.
#include "hovTestMixed.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace hovTest;

namespace
{
constexpr int N = 48;
constexpr double Opacity = 0.3;
const double View[3] = { 0.3, 0.2, 1.0 };

double Height(double, double, double z)
{
  return z;
}

vtkSmartPointer<vtkUnstructuredGrid> Mesh(bool withVector)
{
  MeshBuilder m;
  const double o[3] = { 0, 0, 0 }, size[3] = { 1, 1, 1 };
  m.AddTetBlock(2, 2, 2, o, size, Height);
  auto grid = m.Grid();
  vtkNew<vtkDoubleArray> v, c;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(grid->GetNumberOfPoints());
  c->SetName("c");
  c->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    const auto& p = m.Points[i];
    v->SetTuple3(i, 5.0, p[0], -2.0);
    c->SetValue(i, p[1]);
  }
  if (withVector)
  {
    grid->GetPointData()->AddArray(v);
  }
  grid->GetPointData()->AddArray(c);
  return grid;
}

/// The plane x = level seen by pixel (i, j): where the ray crosses it (y, z in x, y).
void Crossing(vtkCamera* cam, int i, int j, double level, double& x, double& y)
{
  double p[3];
  hovTest::OrthoRayPlaneCrossing(cam, N, i, j, 0, level, p);
  x = p[1];
  y = p[2];
}
}

int TestFieldsIsoArray(int, char*[])
{
  Checker check;
  const double len = std::sqrt(View[0] * View[0] + View[1] * View[1] + View[2] * View[2]);
  const double expected = 1.0 - std::pow(1.0 - Opacity, len / View[0]);
  const auto grid = Mesh(true);
  for (int component : { 1, -1 })
  {
    for (bool perPixel : { false, true })
    {
      VolumeScene scene(grid);
      scene.Tf.Color->AddRGBPoint(0.0, 1, 1, 1);
      scene.Tf.Opacity->AddPoint(0.0, 0.0);
      scene.Mapper->SetCellOrdering(perPixel ? 1 : 0);
      scene.Mapper->SetColorArrayName("c");
      scene.Mapper->SetIsosurfaceArrayName("v");
      scene.Mapper->SetIsosurfaceArrayComponent(component);
      scene.Mapper->AddIsosurface(0.5, 1, 1, 1, Opacity);
      vtkNew<vtkCamera> cam;
      cam->ParallelProjectionOn();
      cam->SetFocalPoint(0.5, 0.5, 0.5);
      cam->SetPosition(0.5 + 4 * View[0], 0.5 + 4 * View[1], 0.5 + 4 * View[2]);
      cam->SetViewUp(0, 1, 0);
      cam->SetParallelScale(0.9);
      cam->SetClippingRange(1, 10);
      int status = 0;
      const Image img = RenderDouble(scene.Mapper, cam, scene.Volume, N, N, &status);
      double worst = 0.0;
      int inside = 0;
      for (int j = 0; j < N; ++j)
      {
        for (int i = 0; i < N; ++i)
        {
          double y, z;
          Crossing(cam, i, j, 0.5, y, z);
          const double margin = std::min(std::min(y, 1 - y), std::min(z, 1 - z));
          if (std::abs(margin) < 1e-6)
          {
            continue;
          }
          const double want = margin > 0 && component == 1 ? expected : 0.0;
          worst = std::max(worst, std::abs(img.At(i, j, 3) - want));
          inside += margin > 0;
        }
      }
      // No surface (the magnitude) leaves the image empty: one warning says so.
      const bool messagesOk = component == 1
        ? scene.NoMessages()
        : (!scene.Observer->GetError() &&
            scene.Observer->GetWarningMessage().find("image is empty") != std::string::npos);
      check.Check(status == 1 && messagesOk && inside > 150 && worst < 1e-12,
        "isosurface array 'v' component " + std::to_string(component) + ", " +
          (perPixel ? "per pixel" : "visibility order") + ": alpha " +
          Fmt(component == 1 ? expected : 0.0) + " expected, max error " + Fmt(worst) +
          " over " + std::to_string(inside) + " pixels");
    }
  }
  // Bad arrays: missing, non-numeric (a string array of that name): an error, nothing drawn.
  for (int bad = 0; bad < 2; ++bad)
  {
    auto input = Mesh(false);
    if (bad == 1)
    {
      vtkNew<vtkStringArray> names;
      names->SetName("v");
      names->SetNumberOfValues(input->GetNumberOfPoints());
      input->GetPointData()->AddArray(names);
    }
    VolumeScene scene(input);
    scene.Tf.Color->AddRGBPoint(0.0, 1, 1, 1);
    scene.Tf.Opacity->AddPoint(0.0, 0.1);
    scene.Mapper->SetIsosurfaceArrayName("v");
    scene.Mapper->AddIsosurface(0.5, 1, 1, 1, Opacity);
    vtkNew<vtkCamera> cam;
    cam->SetPosition(0.5, 0.5, 4);
    cam->SetFocalPoint(0.5, 0.5, 0.5);
    int status = -1;
    const Image img = RenderDouble(scene.Mapper, cam, scene.Volume, 16, 16, &status);
    double sum = 0;
    for (double x : img.V)
      sum += std::abs(x);
    check.Check(scene.Observer->GetError() && sum == 0.0,
      std::string(bad == 0 ? "missing" : "non-numeric") + " isosurface array: error '" +
        Msg(scene.Observer->GetErrorMessage()) + "', image sum " + Fmt(sum));
  }
  return check.Result();
}
