// HIAC's z-buffer witness and the two cell orderings.
//
// On the non-convex bracket (56071 tets) VISIBILITY_SORT with VTK's
// vtkCellCenterDepthSort (cell-centre depth, approximate; set explicitly, the
// default sort is the exact vtkSteinVisibilitySort) composites some
// pixels out of order in oblique views: the witness must report them (> 0),
// while PER_PIXEL_SORT (each pixel's segments sorted by entry distance) must
// report 0 (the mesh has no overlapping cells).
//
// What can be asserted robustly about the two images: both composite exactly
// the same segments at every pixel, only the order may differ.
//  - Opacity does not depend on the order (1 - prod T_i), so alpha must agree
//    everywhere (to round-off and the 1e-9 early termination).
//  - At a pixel the witness did not flag, the order was the per-pixel order,
//    so the colour agrees too: the number of pixels whose colour differs by
//    more than 1e-6 can not exceed the witness count.
//  - The colour differences themselves are bounded by the pixel's alpha;
//    their max and mean are reported.
// On a convex block of tets (vtkImageData -> vtkDataSetTriangleFilter) the
// same quantities are reported for axis-aligned and oblique views.
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellCenterDepthSort.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

using namespace hovTest;

namespace
{
struct OrderResult
{
  vtkIdType WitnessSort = 0, WitnessPixel = 0;
  double AlphaMax = 0, RgbMax = 0, RgbMean = 0, TimeSort = 0, TimePixel = 0;
  size_t RgbPixels = 0, Covered = 0;
};

OrderResult CompareOrders(vtkHighOrderVolumeMapper* mapper, vtkCamera* cam, vtkVolume* vol, int w,
  int h, Image* sortImage = nullptr)
{
  OrderResult r;
  mapper->SetCellOrderingToVisibilitySort();
  const Image v = Render(mapper, cam, vol, w, h);
  r.WitnessSort = mapper->GetWitnessViolations();
  r.TimeSort = mapper->GetLastImageTime();
  mapper->SetCellOrderingToPerPixelSort();
  const Image p = Render(mapper, cam, vol, w, h);
  r.WitnessPixel = mapper->GetWitnessViolations();
  r.TimePixel = mapper->GetLastImageTime();
  r.AlphaMax = Diff(v, p, 3, 4).Max;
  const DiffStats rgb = Diff(v, p, 0, 3, 1e-6);
  r.RgbMax = rgb.Max;
  r.RgbPixels = rgb.Above;
  r.Covered = CheckImage(p).Covered;
  // Mean over covered pixels.
  double sum = 0;
  for (size_t k = 0; k < p.Pixels(); ++k)
  {
    if (p.V[4 * k + 3] > 0)
    {
      for (int c = 0; c < 3; ++c)
      {
        sum += std::abs(v.V[4 * k + c] - p.V[4 * k + c]) / 3;
      }
    }
  }
  r.RgbMean = r.Covered ? sum / r.Covered : 0.0;
  if (sortImage)
  {
    *sortImage = v;
  }
  return r;
}

void PrintHeader()
{
  std::cout << "  " << std::left << std::setw(34) << "view" << std::right << std::setw(10)
            << "covered" << std::setw(12) << "witness VS" << std::setw(12) << "witness PP"
            << std::setw(14) << "rgb>1e-6 px" << std::setw(12) << "max|dA|" << std::setw(12)
            << "max|dRGB|" << std::setw(14) << "mean|dRGB|" << std::setw(16) << "time VS/PP s"
            << "\n";
}

void PrintRow(const std::string& name, const OrderResult& r)
{
  std::ostringstream t;
  t << std::fixed << std::setprecision(2) << r.TimeSort << "/" << r.TimePixel;
  std::cout << "  " << std::left << std::setw(34) << name << std::right << std::setw(10)
            << r.Covered << std::setw(12) << r.WitnessSort << std::setw(12) << r.WitnessPixel
            << std::setw(14) << r.RgbPixels << std::setw(12) << Fmt(r.AlphaMax) << std::setw(12)
            << Fmt(r.RgbMax) << std::setw(14) << Fmt(r.RgbMean) << std::setw(16) << t.str()
            << "\n";
}
}

int TestWitness(int argc, char* argv[])
{
  Checker ck;

  // ---- The bracket.
  vtkSmartPointer<vtkUnstructuredGrid> bracket = LoadBracket(argc, argv);
  if (!ck.Check(bracket->GetNumberOfCells() == 56071, "bracket loaded (56071 cells)"))
  {
    return ck.Result();
  }
  VolumeScene scene(bracket);
  vtkNew<vtkCellCenterDepthSort> centerSort;
  scene.Mapper->SetVisibilitySort(centerSort);
  BracketTF(scene.Tf, 3.0);

  struct View
  {
    const char* Name;
    double Offset[3];
    double Up[3];
  };
  const View views[] = { { "oblique (+110,+90,+140)", { 110, 90, 140 }, { 0, 1, 0 } },
    { "oblique (-150,+60,+100)", { -150, 60, 100 }, { 0, 1, 0 } },
    { "oblique (+40,-160,+90)", { 40, -160, 90 }, { 0, 0, 1 } },
    { "oblique (+120,+130,-110)", { 120, 130, -110 }, { 0, 1, 0 } },
    { "axis -z (perspective)", { 0, 0, 230 }, { 0, 1, 0 } } };
  const int size = 300;
  std::cout << "== bracket, " << size << "x" << size << ", GPU-compatible semantics\n";
  PrintHeader();
  vtkIdType maxObliqueWitness = 0;
  int obliqueWithViolations = 0;
  scene.Observer->Clear();
  for (const View& v : views)
  {
    vtkNew<vtkCamera> cam;
    cam->SetFocalPoint(50, 30, 40);
    cam->SetPosition(50 + v.Offset[0], 30 + v.Offset[1], 40 + v.Offset[2]);
    cam->SetViewUp(v.Up);
    cam->SetViewAngle(40);
    cam->SetClippingRange(20, 600);
    const OrderResult r = CompareOrders(scene.Mapper, cam, scene.Volume, size, size);
    PrintRow(v.Name, r);
    const bool oblique = std::string(v.Name).rfind("oblique", 0) == 0;
    if (oblique)
    {
      maxObliqueWitness = std::max(maxObliqueWitness, r.WitnessSort);
      obliqueWithViolations += r.WitnessSort > 0;
    }
    ck.Check(r.Covered > 0.2 * size * size, std::string(v.Name) + ": the bracket covers > 20%");
    ck.Check(r.WitnessPixel == 0, std::string(v.Name) + ": PER_PIXEL_SORT witness is 0");
    ck.Check(r.AlphaMax <= 1e-6, std::string(v.Name) + ": alpha is the same in both orderings");
    ck.Check(r.RgbPixels <= static_cast<size_t>(r.WitnessSort),
      std::string(v.Name) + ": colour differs (> 1e-6) only at as many pixels as the witness flags");
    ck.Check(r.RgbMean <= 1e-3,
      std::string(v.Name) + ": mean colour difference over covered pixels <= 1e-3");
  }
  ck.Check(obliqueWithViolations >= 1 && maxObliqueWitness > 0,
    "VISIBILITY_SORT (cell centres) is wrong somewhere in some oblique view: witness > 0 in " +
      std::to_string(obliqueWithViolations) + " of 4 oblique views (max " +
      std::to_string(maxObliqueWitness) + ")");
  ck.Check(scene.NoMessages(), "no messages: '" + Msg(scene.Observer->GetWarningMessage()) + "'");

  // ---- A convex block: 12x12x12 voxels split by vtkDataSetTriangleFilter.
  vtkNew<vtkImageData> voxels;
  voxels->SetDimensions(13, 13, 13);
  voxels->SetSpacing(1.0 / 12, 1.0 / 12, 1.0 / 12);
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (vtkIdType i = 0; i < voxels->GetNumberOfPoints(); ++i)
  {
    double p[3];
    voxels->GetPoint(i, p);
    s->InsertNextValue(1.75 * (0.5 + 0.5 * std::sin(5 * p[0] + 3 * p[1] * p[2]) * std::cos(4 * p[2])));
  }
  voxels->GetPointData()->SetScalars(s);
  vtkNew<vtkDataSetTriangleFilter> tri;
  tri->SetInputData(voxels);
  tri->Update();
  vtkUnstructuredGrid* block = tri->GetOutput();
  scene.Mapper->SetInputData(block);
  TF btf;
  DefaultTF(btf, 0.3);
  scene.Volume->SetProperty(btf.Property);
  std::cout << "\n== convex block: " << block->GetNumberOfCells()
            << " tets (vtkDataSetTriangleFilter of 12^3 voxels), " << 240 << "x" << 240 << "\n";
  PrintHeader();
  struct BlockView
  {
    const char* Name;
    bool Ortho;
    double Pos[3], Focal[3];
  };
  // Axis views slightly off-centre so that no pixel ray lies exactly in an
  // interior face (TestBadInputFaceRays covers those rays).
  const double e = 0.0123, f = 0.0071;
  const BlockView bviews[] = {
    { "axis -z, perspective", false, { 0.5 + e, 0.5 + f, 3.2 }, { 0.5 + e, 0.5 + f, 0.5 } },
    { "axis -z, orthographic", true, { 0.5 + e, 0.5 + f, 3.2 }, { 0.5 + e, 0.5 + f, 0.5 } },
    { "axis -x, perspective", false, { 3.2, 0.5 + e, 0.5 + f }, { 0.5, 0.5 + e, 0.5 + f } },
    { "oblique, perspective", false, { 2.6, 1.9, 3.1 }, { 0.5, 0.5, 0.5 } },
    { "oblique, orthographic", true, { 2.6, 1.9, 3.1 }, { 0.5, 0.5, 0.5 } } };
  scene.Observer->Clear();
  for (const BlockView& v : bviews)
  {
    vtkNew<vtkCamera> cam;
    cam->SetPosition(v.Pos);
    cam->SetFocalPoint(v.Focal);
    cam->SetViewUp(0, 1, 0);
    cam->SetViewAngle(30);
    cam->SetParallelProjection(v.Ortho);
    cam->SetParallelScale(0.9);
    cam->SetClippingRange(0.5, 10);
    Image sortImage;
    const OrderResult r = CompareOrders(scene.Mapper, cam, scene.Volume, 240, 240, &sortImage);
    PrintRow(v.Name, r);
    ck.Check(r.WitnessPixel == 0, std::string(v.Name) + ": PER_PIXEL_SORT witness is 0");
    ck.Check(r.AlphaMax <= 1e-6, std::string(v.Name) + ": alpha is the same in both orderings");
    ck.Check(r.RgbPixels <= static_cast<size_t>(r.WitnessSort),
      std::string(v.Name) + ": colour differs only at pixels the witness flags");
    if (r.WitnessSort == 0)
    {
      ck.Check(r.RgbMax <= 1e-9,
        std::string(v.Name) + ": no violation -> the two orderings give the same image");
    }
  }
  ck.Check(scene.NoMessages(), "no messages");
  return ck.Result();
}
