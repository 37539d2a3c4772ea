// Our mapper against VTK's own unstructured ray caster on the bundled
// CalculiX bracket (56071 linear tets, point scalars "von_mises").
//
// Both render the same camera and vtkVolumeProperty on screen (300x300,
// black background, captured with vtkWindowToImageFilter): ours with
// VTK_UNSTRUCTURED semantics (extinction a/u, what VTK's unstructured
// integrators use) and PER_PIXEL_SORT (exact order on this non-convex mesh);
// VTK's vtkUnstructuredGridVolumeRayCastMapper (Bunyk) with
// vtkUnstructuredGridLinearRayIntegrator, image sample distance 1.
//
// Case A: every opacity node is also a colour node, where VTK's linear
// integrator is exact: VTK's 8-bit screen image must match our float image
// closely on average (VTK casts its rays at integer pixel positions, i.e.
// half a pixel off the pixel centres, and may drop a column, so the maximum
// difference at edges is large; mean, p99 and max are reported).
//
// Case B: an opacity peak (s = 10..30) between two colour nodes. VTK's linear
// integrator keeps only the first opacity node (its loop over the opacity
// nodes stops at the node whose position equals the function's range
// minimum, i.e. the first one), so the peak vanishes from VTK's image. The
// independent expectation is VTK itself given the same function with colour
// nodes added at the peak's nodes (colours unchanged, since the colour is
// linear there), where its integrator is exact again: our image of B must
// match VTK's image of that equivalent function, and must change appreciably
// when the peak is removed, while VTK's image of B does not.
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
double Seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Row
{
  std::string Name;
  DiffStats D[3];
};

void PrintTable(const std::vector<Row>& rows)
{
  std::cout << "\n  " << std::left << std::setw(46) << "comparison (x255, per channel R/G/B)"
            << std::right << std::setw(22) << "mean" << std::setw(22) << "p99" << std::setw(22)
            << "max" << "\n";
  for (const Row& r : rows)
  {
    auto three = [&](double DiffStats::*m) {
      std::ostringstream s;
      s << std::fixed << std::setprecision(2) << r.D[0].*m * 255 << "/" << r.D[1].*m * 255 << "/"
        << r.D[2].*m * 255;
      return s.str();
    };
    std::cout << "  " << std::left << std::setw(46) << r.Name << std::right << std::setw(22)
              << three(&DiffStats::Mean) << std::setw(22) << three(&DiffStats::P99)
              << std::setw(22) << three(&DiffStats::Max) << "\n";
  }
  std::cout << "\n";
}

Row Compare(const std::string& name, const Image& a, const Image& b)
{
  Row r;
  r.Name = name;
  for (int c = 0; c < 3; ++c)
  {
    r.D[c] = Diff(a, b, c, c + 1, 1.5 / 255);
  }
  return r;
}

double MaxOf(const Row& r, double DiffStats::*m)
{
  return std::max(r.D[0].*m, std::max(r.D[1].*m, r.D[2].*m));
}
}

int TestCompareVTK(int argc, char* argv[])
{
  Checker ck;
  std::string file;
  vtkSmartPointer<vtkUnstructuredGrid> grid = LoadBracket(argc, argv, &file);
  const std::string tmp = ArgAfter(argc, argv, "-T", ".");
  double range[2] = { 0, 0 };
  if (grid->GetPointData()->GetScalars())
  {
    grid->GetPointData()->GetScalars()->GetRange(range);
  }
  std::cout << "== " << file << ": " << grid->GetNumberOfCells() << " cells, "
            << grid->GetNumberOfPoints() << " points, von_mises range [" << range[0] << ", "
            << range[1] << "]\n";
  if (!ck.Check(grid->GetNumberOfCells() == 56071 && range[1] > 100, "bracket loaded"))
  {
    return ck.Result();
  }

  const int size = 300;
  vtkNew<vtkCamera> cam;
  cam->SetFocalPoint(50, 30, 40);
  cam->SetPosition(50 + 110, 30 + 90, 40 + 140);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(40);
  cam->SetClippingRange(50, 500);

  // Our mapper.
  VolumeScene scene;
  vtkHighOrderVolumeMapper* ours = scene.Mapper;
  ours->SetInputData(grid);
  ours->SetOpacitySemanticsToVTKUnstructured();
  ours->SetCellOrderingToPerPixelSort();
  vtkSmartPointer<vtkRenderer> ourRen = BlackRenderer(cam);
  ourRen->AddVolume(scene.Volume);
  vtkSmartPointer<vtkRenderWindow> ourWin = OffscreenWindow(ourRen, size, size, 0);

  // VTK's ray caster with the linear integrator.
  vtkNew<vtkUnstructuredGridVolumeRayCastMapper> vtkMapper;
  vtkMapper->SetInputData(grid);
  vtkNew<vtkUnstructuredGridLinearRayIntegrator> integrator;
  vtkMapper->SetRayIntegrator(integrator);
  vtkMapper->AutoAdjustSampleDistancesOff();
  vtkMapper->SetImageSampleDistance(1.0);
  vtkNew<vtkVolume> vtkVol;
  vtkVol->SetMapper(vtkMapper);
  vtkSmartPointer<vtkRenderer> vtkRen = BlackRenderer(cam);
  vtkRen->AddVolume(vtkVol);
  vtkSmartPointer<vtkRenderWindow> vtkWin = OffscreenWindow(vtkRen, size, size, 0);

  const double u = 3.0;
  struct Result
  {
    Image OurFloat, OurScreen, VtkScreen;
    double OurTime = 0, VtkTime = 0;
  };
  auto renderBoth = [&](const std::string& name, const std::string& tag, TF& tf) {
    Result r;
    scene.Volume->SetProperty(tf.Property);
    vtkVol->SetProperty(tf.Property);
    scene.Observer->Clear();
    auto t0 = std::chrono::steady_clock::now();
    ourWin->Render();
    r.OurTime = Seconds(t0);
    r.OurFloat = FloatImage(ours);
    r.OurScreen = Capture(ourWin);
    t0 = std::chrono::steady_clock::now();
    vtkWin->Render();
    r.VtkTime = Seconds(t0);
    r.VtkScreen = Capture(vtkWin);
    WritePNG(r.OurFloat, tmp + "/TestCompareVTK_" + tag + "_ours.png");
    WritePNG(r.VtkScreen, tmp + "/TestCompareVTK_" + tag + "_vtk.png");
    const Sanity s = CheckImage(r.OurFloat);
    std::cout << "== " << name << ": ours " << r.OurTime << " s (image " << ours->GetLastImageTime()
              << " s, " << ours->GetNumberOfSegments() << " segments, witness "
              << ours->GetWitnessViolations() << "), VTK " << r.VtkTime << " s\n  ours: " << s.Str()
              << "\n  mean intensity (r+g+b)/3: ours float " << MeanIntensity(r.OurFloat)
              << ", ours screen " << MeanIntensity(r.OurScreen) << ", VTK screen "
              << MeanIntensity(r.VtkScreen) << "\n";
    ck.Check(scene.NoMessages(), name + ": no messages from our mapper");
    ck.Check(s.Ok() && s.Covered > 0.2 * size * size, name + ": our image is sane and covers > 20%");
    ck.Check(ours->GetWitnessViolations() == 0,
      name + ": no overlapping cells on any ray (per-pixel witness 0)");
    return r;
  };

  // ---- Case A: opacity nodes = colour nodes.
  TF a;
  BracketTF(a, u);
  const Result ra = renderBoth("Case A (opacity nodes are colour nodes)", "A", a);

  // ---- Case B: an opacity peak inside one colour interval.
  auto caseB = [&](TF& tf, bool peak, bool colourAtPeakNodes) {
    const double c0[3] = { 0.2, 0.4, 1.0 }, c1[3] = { 1.0, 0.5, 0.2 };
    const double s0 = 0.0, s1 = 170.0;
    tf.Color->AddRGBPoint(s0, c0[0], c0[1], c0[2]);
    tf.Color->AddRGBPoint(s1, c1[0], c1[1], c1[2]);
    const double peakNodes[3][2] = { { 10.0, 0.03 }, { 20.0, 0.8 }, { 30.0, 0.03 } };
    tf.Opacity->AddPoint(s0, 0.03);
    if (peak)
    {
      for (const auto& p : peakNodes)
      {
        tf.Opacity->AddPoint(p[0], p[1]);
      }
    }
    tf.Opacity->AddPoint(s1, 0.03);
    if (colourAtPeakNodes)
    {
      for (const auto& p : peakNodes)
      {
        const double w = (p[0] - s0) / (s1 - s0);
        tf.Color->AddRGBPoint(p[0], c0[0] + w * (c1[0] - c0[0]), c0[1] + w * (c1[1] - c0[1]),
          c0[2] + w * (c1[2] - c0[2]));
      }
    }
    tf.Property->SetScalarOpacityUnitDistance(u);
  };
  TF b, bNoPeak, bColourNodes;
  caseB(b, true, false);
  caseB(bNoPeak, false, false);
  caseB(bColourNodes, true, true);
  const Result rb = renderBoth("Case B (opacity peak s=10..30 inside the colour interval [0,170])", "B", b);
  const Result rb0 = renderBoth("Case B without the peak", "Bnopeak", bNoPeak);
  const Result rb2 =
    renderBoth("Case B with colour nodes at the peak's nodes (same function)", "Bcolournodes", bColourNodes);

  // ---- Our images with the rays through pixel corners instead of centres.
  // The ray caster casts through integer pixel positions (pixel corners), our
  // mapper through pixel centres (where OpenGL rasterises). Shifting our
  // projection by half a pixel (vtkCamera::SetWindowCenter, 1 pixel = 2/size
  // in normalised coordinates) shows how much of the difference that is.
  vtkNew<vtkCamera> shifted;
  auto shiftedImage = [&](TF& tf, double sx, double sy) {
    shifted->DeepCopy(cam);
    shifted->SetWindowCenter(2.0 * sx / size, 2.0 * sy / size);
    scene.Volume->SetProperty(tf.Property);
    ours->RenderImage(shifted, scene.Volume, size, size);
    return FloatImage(ours);
  };
  std::cout << "\n  our float (rays shifted by (sx,sy) pixels) vs VTK screen, mean |diff| x255 R/G/B:\n";
  Image cornersA, cornersB;
  for (const auto& sh : { std::array<double, 2>{ 0, 0 }, std::array<double, 2>{ -0.5, -0.5 },
         std::array<double, 2>{ -0.5, 0.5 }, std::array<double, 2>{ 0.5, -0.5 },
         std::array<double, 2>{ 0.5, 0.5 } })
  {
    const Image ia = shiftedImage(a, sh[0], sh[1]);
    const Image ib = shiftedImage(b, sh[0], sh[1]);
    const Row r1 = Compare("", ra.VtkScreen, ia), r2 = Compare("", rb2.VtkScreen, ib);
    std::cout << std::fixed << std::setprecision(2) << "    (" << std::setw(5) << sh[0] << ","
              << std::setw(5) << sh[1] << "): A " << r1.D[0].Mean * 255 << "/"
              << r1.D[1].Mean * 255 << "/" << r1.D[2].Mean * 255 << "   B vs VTK(B + colour nodes) "
              << r2.D[0].Mean * 255 << "/" << r2.D[1].Mean * 255 << "/" << r2.D[2].Mean * 255
              << std::defaultfloat << "\n";
    if (sh[0] < 0 && sh[1] < 0)
    {
      cornersA = ia;
      cornersB = ib;
      WritePNG(ia, tmp + "/TestCompareVTK_A_ours_corners.png");
    }
  }

  // ---- Table.
  std::vector<Row> rows;
  rows.push_back(Compare("A: VTK screen vs our float", ra.VtkScreen, ra.OurFloat));
  rows.push_back(Compare("A: VTK screen vs our float, corner rays", ra.VtkScreen, cornersA));
  rows.push_back(Compare("A: VTK screen vs our screen", ra.VtkScreen, ra.OurScreen));
  rows.push_back(Compare("A: our screen vs our float", ra.OurScreen, ra.OurFloat));
  rows.push_back(Compare("B: VTK screen vs our float", rb.VtkScreen, rb.OurFloat));
  rows.push_back(Compare("B: VTK(B) vs VTK(B without peak)", rb.VtkScreen, rb0.VtkScreen));
  rows.push_back(Compare("B: our float B vs B without peak", rb.OurFloat, rb0.OurFloat));
  rows.push_back(Compare("B: VTK(B + colour nodes) vs our float B", rb2.VtkScreen, rb.OurFloat));
  rows.push_back(Compare("B: VTK(B + colour nodes) vs ours, corner rays", rb2.VtkScreen, cornersB));
  rows.push_back(Compare("B: our float B + colour nodes vs B", rb2.OurFloat, rb.OurFloat));
  rows.push_back(Compare("B no peak: VTK screen vs our float", rb0.VtkScreen, rb0.OurFloat));
  PrintTable(rows);
  std::cout << "  mean intensity x255     ours(float)   VTK(screen)\n";
  auto line = [&](const char* n, const Result& r) {
    std::cout << "  " << std::left << std::setw(22) << n << std::right << std::fixed
              << std::setprecision(3) << std::setw(12) << MeanIntensity(r.OurFloat) * 255
              << std::setw(14) << MeanIntensity(r.VtkScreen) * 255 << "\n"
              << std::defaultfloat;
  };
  line("A", ra);
  line("B", rb);
  line("B without peak", rb0);
  line("B + colour nodes", rb2);
  std::cout << "  our mean alpha: A " << MeanChannel(ra.OurFloat, 3) << ", B "
            << MeanChannel(rb.OurFloat, 3) << ", B without peak " << MeanChannel(rb0.OurFloat, 3)
            << "\n\n";

  // ---- Assertions. Thresholds: measured values (see the table) with margin.
  auto worst = [&](int row, double DiffStats::*m) { return MaxOf(rows[row], m) * 255; };
  ck.Check(worst(3, &DiffStats::Max) <= 1.5, "A: our screen = our float within 1.5/255");
  ck.Check(worst(0, &DiffStats::Mean) <= 1.25,
    "A: mean |VTK - ours| per channel <= 1.25/255 (measured " + Fmt(worst(0, &DiffStats::Mean)) + ")");
  ck.Check(worst(0, &DiffStats::P99) <= 16,
    "A: p99 |VTK - ours| per channel <= 16/255 (measured " + Fmt(worst(0, &DiffStats::P99)) + ")");
  ck.Check(worst(1, &DiffStats::Mean) <= 0.5,
    "A, our rays at VTK's pixel corners: mean <= 0.5/255 (measured " + Fmt(worst(1, &DiffStats::Mean)) + ")");
  ck.Check(worst(1, &DiffStats::P99) <= 5,
    "A, our rays at VTK's pixel corners: p99 <= 5/255 (measured " + Fmt(worst(1, &DiffStats::P99)) + ")");
  ck.Check(worst(5, &DiffStats::Max) <= 0.5,
    "B: VTK's image does not see the peak at all (max change " + Fmt(worst(5, &DiffStats::Max)) + "/255)");
  ck.Check(worst(6, &DiffStats::Mean) >= 5,
    "B: our image changes appreciably with the peak (mean change " + Fmt(worst(6, &DiffStats::Mean)) + "/255)");
  ck.Check(MeanIntensity(rb.VtkScreen) < 0.6 * MeanIntensity(rb.OurFloat),
    "B: VTK's mean intensity is far below ours (the peak's contribution is missing)");
  ck.Check(worst(7, &DiffStats::Mean) <= 2.0,
    "B: ours matches VTK given the equivalent function with colour nodes at the peak: mean <= 2/255 (measured " +
      Fmt(worst(7, &DiffStats::Mean)) + ")");
  ck.Check(worst(8, &DiffStats::Mean) <= 0.6,
    "B, corner rays: mean <= 0.6/255 (measured " + Fmt(worst(8, &DiffStats::Mean)) + ")");
  ck.Check(worst(9, &DiffStats::Max) <= 1e-6 * 255,
    "B: adding colour nodes on the linear colour function does not change our image");
  ck.Check(worst(10, &DiffStats::Mean) <= 1.0,
    "B without peak (all opacity nodes are colour nodes): mean <= 1/255 (measured " +
      Fmt(worst(10, &DiffStats::Mean)) + ")");
  ours->ReleaseGraphicsResources(ourWin);
  return ck.Result();
}
