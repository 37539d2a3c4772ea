// VTK's vtkProjectedTetrahedraMapper (OpenGL, under xvfb) with our exact
// vtkSteinVisibilitySort plugged in through SetVisibilitySort(), against its
// own default vtkCellCenterDepthSort, on a non-convex mesh (a jittered block
// with a square hole, oblique view where the cell-centre order is wrong on
// many pixels). The reference is our accurate float image (VTK_UNSTRUCTURED
// semantics, extinction a/u like projected tetrahedra; PER_PIXEL_SORT).
// Projected tetrahedra keep their own approximations (8-bit colours, colour
// averaged per fragment), so neither image matches to round-off; with the
// exact order the image must be closer: mean |error| over the covered pixels
// (max over R, G, B) smaller than with the default sort. Max/mean errors per
// channel are printed, and the screen captures written to the -T directory.
#include "hovSortMeshes.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellCenterDepthSort.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
struct Err
{
  double Mean[3] = { 0, 0, 0 }, Max[3] = { 0, 0, 0 };
  double MeanMax() const { return std::max(Mean[0], std::max(Mean[1], Mean[2])); }
};

/// Errors of @p screen (RGB over black) against the premultiplied float
/// image @p ref, over the pixels @p ref covers.
Err Compare(const Image& ref, const Image& screen)
{
  Err e;
  size_t covered = 0;
  for (int j = 0; j < ref.H; ++j)
  {
    for (int i = 0; i < ref.W; ++i)
    {
      if (ref.At(i, j, 3) <= 1e-3)
      {
        continue;
      }
      ++covered;
      for (int c = 0; c < 3; ++c)
      {
        const double d = std::abs(std::min(1.0, ref.At(i, j, c)) - screen.At(i, j, c));
        e.Mean[c] += d;
        e.Max[c] = std::max(e.Max[c], d);
      }
    }
  }
  for (double& m : e.Mean)
  {
    m /= std::max<size_t>(covered, 1);
  }
  return e;
}

void Print(const std::string& name, const Err& e)
{
  std::cout << "  " << std::left << std::setw(40) << name << std::right << std::fixed
            << std::setprecision(4) << "mean R/G/B " << e.Mean[0] << "/" << e.Mean[1] << "/"
            << e.Mean[2] << "   max R/G/B " << e.Max[0] << "/" << e.Max[1] << "/" << e.Max[2]
            << "\n";
}
}

int TestSortProjectedTetrahedra(int argc, char* argv[])
{
  Checker ck;
  const std::string tmp = ArgAfter(argc, argv, "-T", ".");
  const int size = 200;
  vtkSmartPointer<vtkUnstructuredGrid> mesh = HoledBlock(8, 41);
  VolumeScene scene(mesh);
  DefaultTF(scene.Tf, 0.15);
  scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
  scene.Mapper->SetCellOrderingToPerPixelSort();
  vtkNew<vtkCamera> cam;
  cam->SetPosition(2.3, -1.0, 2.0);
  cam->SetFocalPoint(0.5, 0.5, 0.5);
  cam->SetViewUp(0, 0, 1);
  cam->SetViewAngle(32);
  cam->SetClippingRange(0.5, 10);
  const Image ref = Render(scene.Mapper, cam, scene.Volume, size, size);
  ck.Check(CheckImage(ref).Ok() && CheckImage(ref).Covered > 0.1 * size * size,
    "reference image sane (" + CheckImage(ref).Str() + ")");

  vtkNew<vtkProjectedTetrahedraMapper> pt;
  pt->SetInputData(mesh);
  vtkNew<vtkVolume> vol;
  vol->SetMapper(pt);
  vol->SetProperty(scene.Tf.Property);
  vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam);
  ren->AddVolume(vol);
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, size, size, 0);

  auto shot = [&](const std::string& tag) {
    win->Render();
    const Image img = Capture(win);
    WritePNG(img, tmp + "/TestSortProjectedTetrahedra_" + tag + ".png");
    return img;
  };
  const Image ccd = shot("default"); // PT's default: vtkCellCenterDepthSort
  vtkNew<vtkSteinVisibilitySort> stein;
  pt->SetVisibilitySort(stein);
  const Image exact = shot("stein");
  WritePNG(ref, tmp + "/TestSortProjectedTetrahedra_reference.png");

  const Err eDefault = Compare(ref, ccd);
  const Err eStein = Compare(ref, exact);
  std::cout << "== holed block (" << mesh->GetNumberOfCells() << " tets), " << size << "x" << size
            << ", errors against our float image (colour in [0,1]):\n";
  Print("projected tetrahedra, default sort", eDefault);
  Print("projected tetrahedra, Stein sort", eStein);
  double diffPT = 0;
  for (size_t k = 0; k < ccd.Pixels(); ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      diffPT = std::max(diffPT, std::abs(ccd.V[4 * k + c] - exact.V[4 * k + c]));
    }
  }
  std::cout << "  max |PT default - PT Stein| = " << Fmt(diffPT) << "\n";
  ck.Check(diffPT > 0.05, "the sort changes the projected-tetrahedra image");
  ck.Check(eStein.MeanMax() < eDefault.MeanMax(),
    "PT with the Stein sort is closer to the accurate image (mean " + Fmt(eStein.MeanMax()) +
      " < " + Fmt(eDefault.MeanMax()) + ")");
  ck.Check(scene.NoMessages(), "no messages from our mapper");
  return ck.Result();
}
