// The RAY_CAST render mode on curved Lagrange cells: the real order-4 plate
// with a hole (Testing/Data/platehole_lagrange_hex_q4.vtu), viewed along -z
// with a parallel camera, 16 x 16, through the public mapper:
//  - all 192 cells prepared, none skipped, no message;
//  - deterministic: a second mapper renders the same image bit for bit (the
//    parallel loop shares nothing between pixels);
//  - finite, 0 <= alpha <= 1, error estimates below ElVis's 1e-3, the plate
//    visible and the hole (radius 0.25 about the origin) exactly transparent;
//  - opaque geometry in front of the plate (a window) hides everything;
//  - a Lagrange pyramid (74) added to the grid is skipped with a warning
//    naming its type, and the image is unchanged.
#include "hovTestReferenceDatasets.h"
#include "hovTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <iostream>
#include <vector>

using namespace hovTest;

namespace
{
constexpr int W = 16, H = 16;

/// The plate's transfer function (VTK-unstructured semantics, unit distance 0.02).
void PlateTF(TF& tf)
{
  tf.Color->AddRGBPoint(1.8, 0.1, 0.2, 0.9);
  tf.Color->AddRGBPoint(150.0, 0.2, 0.9, 0.2);
  tf.Color->AddRGBPoint(361.0, 0.9, 0.1, 0.1);
  tf.Opacity->AddPoint(1.8, 0.05);
  tf.Opacity->AddPoint(100.0, 0.2);
  tf.Opacity->AddPoint(250.0, 0.6);
  tf.Opacity->AddPoint(361.0, 1.0);
  tf.Property->SetScalarOpacityUnitDistance(0.02);
}

/// A RAY_CAST scene of @p grid at the tolerance of the ray caster's kernel default (1e-9).
void Setup(VolumeScene& scene)
{
  PlateTF(scene.Tf);
  scene.Mapper->SetRenderModeToRayCast();
  scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
  scene.Mapper->SetRayCastTolerance(1e-9);
}

void PlateCamera(vtkCamera* camera)
{
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0.5, 0.5, 0.05);
  camera->SetPosition(0.5, 0.5, 3.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(0.5);
  camera->SetClippingRange(1.0, 5.0);
}

double MaxDifference(const Image& a, const Image& b)
{
  double worst = a.V.size() == b.V.size() ? 0.0 : 1e300;
  for (size_t k = 0; k < a.V.size() && k < b.V.size(); ++k)
  {
    worst = std::max(worst, std::abs(a.V[k] - b.V[k]));
  }
  return worst;
}
}

int TestCurvedRayCastImage(int argc, char* argv[])
{
  Checker ck;
  const std::string data = ArgAfter(argc, argv, "-D", ".");
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    hovTestRef::LoadDataset(data, "platehole_lagrange_hex_q4.vtu", "von_mises");
  if (!ck.Check(grid->GetNumberOfCells() == 192, "platehole loaded"))
  {
    return ck.Result();
  }
  vtkNew<vtkCamera> camera;
  PlateCamera(camera);
  VolumeScene scene(grid);
  Setup(scene);
  int status = 0;
  const Image rgba = Render(scene.Mapper, camera, scene.Volume, W, H, &status);
  ck.Check(status == 1 && scene.Mapper->GetNumberOfRenderedCells() == 192 &&
      scene.Mapper->GetNumberOfSkippedCells() == 0 && scene.NoMessages(),
    "192 cells, none skipped, no message");

  double maxAlpha = 0.0;
  bool finite = true, holeClear = true;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const double a = rgba.At(i, j, 3);
      finite = finite && std::isfinite(rgba.At(i, j, 0)) && std::isfinite(a) && a >= 0.0 && a <= 1.0;
      maxAlpha = std::max(maxAlpha, a);
      // The pixel centre in the plate's plane (the parallel view of [0, 1]^2).
      const double x = (i + 0.5) / W, y = (j + 0.5) / H;
      if (x * x + y * y < 0.2 * 0.2) // well inside the hole
      {
        holeClear = holeClear && a == 0.0;
      }
    }
  }
  const double maxError = MaxRayCastError(scene.Mapper);
  // A second, independent mapper must render the same image bit for bit.
  VolumeScene second(grid);
  Setup(second);
  const double repeat = MaxDifference(rgba, Render(second.Mapper, camera, second.Volume, W, H));
  std::cout << "[measured] platehole " << W << "x" << H << ": max alpha " << maxAlpha
            << ", max error estimate " << maxError << ", repeat difference " << repeat << std::endl;
  ck.Check(finite, "finite colours, alpha in [0, 1]");
  ck.Check(maxAlpha > 0.05, "the plate is visible");
  ck.Check(holeClear, "the hole is exactly transparent");
  ck.Check(maxError >= 0.0 && maxError < 1e-3, "error estimates below 0.001");
  ck.Check(repeat == 0.0, "deterministic (a second mapper gives the same image)");

  // Opaque geometry in front of the plate everywhere: nothing traced.
  vtkSmartPointer<vtkRenderer> ren = BlackRenderer(camera);
  const double wall[6] = { -1.0, 2.0, -1.0, 2.0, 1.4, 1.5 };
  const double grey[3] = { 0.5, 0.5, 0.5 };
  ren->AddActor(BoxActor(wall, grey));
  ren->AddVolume(scene.Volume);
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, W, H, 0);
  win->Render();
  const Image hidden = FloatImage(scene.Mapper);
  bool allZero = hidden.Pixels() == static_cast<size_t>(W) * H;
  for (double v : hidden.V)
  {
    allZero = allZero && v == 0.0;
  }
  ck.Check(allZero, "opaque geometry in front hides everything");
  scene.Mapper->ReleaseGraphicsResources(win);

  // A Lagrange pyramid added (a type the ray caster does not handle): skipped
  // with a warning naming it, the image unchanged.
  vtkNew<vtkUnstructuredGrid> mixed;
  mixed->DeepCopy(grid);
  const vtkIdType pyramid[5] = { 0, 1, 2, 3, 4 };
  mixed->InsertNextCell(VTK_LAGRANGE_PYRAMID, 5, pyramid);
  VolumeScene third(mixed);
  Setup(third);
  const Image withPyramid = Render(third.Mapper, camera, third.Volume, W, H, &status);
  const std::string why = Msg(third.Observer->GetWarningMessage());
  ck.Check(status == 1 && third.Mapper->GetNumberOfSkippedCells() == 1 &&
      why.find("first type: 74") != std::string::npos,
    "Lagrange pyramid skipped: " + why);
  ck.Check(MaxDifference(rgba, withPyramid) == 0.0, "the rest renders as before");
  return ck.Result();
}
