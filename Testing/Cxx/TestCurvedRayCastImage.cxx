// The CPU ray-cast path for curved Lagrange cells (vtkHighOrderRayCast, the
// adapter of the mapper's RAY_CAST mode) on the real order-4 plate with a hole
// (Testing/Data/platehole_lagrange_hex_q4.vtu), viewed along -z with a
// parallel camera:
//  - deterministic: a second adapter renders the same image bit for bit
//    (the parallel loop shares nothing between pixels);
//  - finite, 0 <= alpha <= 1, error estimates below ElVis's 1e-3, the plate
//    visible and the hole (radius 0.25 about the origin) exactly transparent;
//  - an opaque depth of 0 everywhere hides everything;
//  - a Lagrange pyramid (74) added to the grid is skipped with a message
//    naming its type, and the image is unchanged.
#include "hovRayCast.h"
#include "hovViewRays.h"

#include "hovTransferFunction.h"

#include "hovTestReferenceDatasets.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <iostream>
#include <vector>

using namespace hovTest;

namespace
{
constexpr int W = 16, H = 16;

hov::TransferFunction Table()
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::VTKUnstructured;
  spec.UnitDistance = 0.02;
  spec.Color = { { 1.8, 0.1, 0.2, 0.9 }, { 150.0, 0.2, 0.9, 0.2 }, { 361.0, 0.9, 0.1, 0.1 } };
  spec.Opacity = { { 1.8, 0.05 }, { 100.0, 0.2 }, { 250.0, 0.6 }, { 361.0, 1.0 } };
  hov::TransferFunction tf;
  tf.Build(spec);
  return tf;
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
  vtkHighOrderRayCast cast;
  std::string msg;
  ck.Check(cast.SetInput(grid, grid->GetPointData()->GetScalars(), 0, &msg) &&
      cast.GetNumberOfSkippedCells() == 0 && msg.empty(),
    "SetInput: 192 cells, none skipped " + msg);
  vtkNew<vtkCamera> camera;
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0.5, 0.5, 0.05);
  camera->SetPosition(0.5, 0.5, 3.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(0.5);
  camera->SetClippingRange(1.0, 5.0);
  vtkHighOrderViewRays rays;
  ck.Check(rays.Setup(camera, nullptr, W, H, 1.0), "pixel rays");
  const hov::TransferFunction tf = Table();
  const hov::CurvedSegmentSettings settings;
  std::vector<float> rgba(4 * W * H), error(W * H);
  ck.Check(cast.Render(rays, tf, settings, rgba.data(), error.data(), nullptr), "rendered");

  double worstDiff = 0.0, maxAlpha = 0.0, maxError = 0.0;
  bool finite = true, holeClear = true;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const float* c = &rgba[4 * (j * W + i)];
      finite = finite && std::isfinite(c[0]) && std::isfinite(c[3]) && c[3] >= 0.0f && c[3] <= 1.0f;
      maxAlpha = std::max(maxAlpha, static_cast<double>(c[3]));
      maxError = std::max(maxError, static_cast<double>(error[j * W + i]));
      double tMax = 0.0;
      const vtkHighOrderViewRays::Ray ray = rays.TracedPixelRay(i, j, 1.0, tMax);
      const double x = ray.Origin.x, y = ray.Origin.y;
      if (x * x + y * y < 0.2 * 0.2) // well inside the hole
      {
        holeClear = holeClear && c[3] == 0.0f;
      }
    }
  }
  // A second, independent adapter must render the same image bit for bit.
  vtkHighOrderRayCast second;
  second.SetInput(grid, grid->GetPointData()->GetScalars(), 0, nullptr);
  std::vector<float> rgba2(4 * W * H);
  second.Render(rays, tf, settings, rgba2.data(), nullptr, nullptr);
  for (size_t k = 0; k < rgba.size(); ++k)
  {
    worstDiff = std::max(worstDiff, std::abs(static_cast<double>(rgba[k]) - rgba2[k]));
  }
  std::cout << "[measured] platehole " << W << "x" << H << ": max alpha " << maxAlpha
            << ", max error estimate " << maxError << ", repeat difference " << worstDiff
            << std::endl;
  ck.Check(finite, "finite colours, alpha in [0, 1]");
  ck.Check(maxAlpha > 0.05, "the plate is visible");
  ck.Check(holeClear, "the hole is exactly transparent");
  ck.Check(maxError < 1e-3, "error estimates below 0.001");
  ck.Check(worstDiff == 0.0, "deterministic (a second adapter gives the same image)");

  // Opaque geometry at the near plane everywhere: nothing traced.
  std::vector<float> depth(W * H, 0.0f), hidden(4 * W * H, 1.0f);
  cast.Render(rays, tf, settings, hidden.data(), nullptr, depth.data());
  bool allZero = true;
  for (float v : hidden)
  {
    allZero = allZero && v == 0.0f;
  }
  ck.Check(allZero, "opaque depth 0 hides everything");

  // A Lagrange pyramid added (a type the ray caster does not handle): skipped
  // with a message, the image unchanged.
  vtkNew<vtkUnstructuredGrid> mixed;
  mixed->DeepCopy(grid);
  const vtkIdType pyramid[5] = { 0, 1, 2, 3, 4 };
  mixed->InsertNextCell(VTK_LAGRANGE_PYRAMID, 5, pyramid);
  vtkHighOrderRayCast third;
  std::string why;
  const bool built = third.SetInput(mixed, mixed->GetPointData()->GetScalars(), 0, &why);
  ck.Check(built && third.GetConversion().Unsupported == 1 &&
      why.find("first type: 74") != std::string::npos,
    "Lagrange pyramid skipped: " + why);
  std::vector<float> rgba3(4 * W * H);
  third.Render(rays, tf, settings, rgba3.data(), nullptr, nullptr);
  double diff3 = 0.0;
  for (size_t k = 0; k < rgba.size(); ++k)
  {
    diff3 = std::max(diff3, std::abs(static_cast<double>(rgba[k]) - rgba3[k]));
  }
  ck.Check(diff3 == 0.0, "the rest renders as before");
  return ck.Result();
}
