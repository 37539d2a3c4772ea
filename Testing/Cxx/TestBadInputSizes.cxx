// Image sizes: 1x1 and 4096x4096 through RenderImage, 1x1 on screen, and
// invalid sizes (0, negative, beyond the limit of 16384 x 16384 pixels). On
// the axis-aligned orthographic view of the unit cube with a constant
// transfer function every pixel is known analytically: inside the cube's
// footprint alpha = 1 - exp(-a/u) (VTK semantics, thickness 1), outside 0.
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>

using namespace hovTest;

int TestBadInputSizes(int, char*[])
{
  Checker ck;
  VolumeScene scene(UnitBlock(2).Grid());
  const double color[3] = { 0.9, 0.5, 0.2 };
  const double a = 0.5, u = 0.5;
  ConstantTF(scene.Tf, color, a, u);
  scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
  const double alphaIn = -std::expm1(-a / u);
  // Shifted so that no pixel centre lies in an interior face of the block
  // (TestBadInputFaceRays covers those rays). With an odd size (1x1) the
  // centre row would lie in the face y = 1/2, so that view is shifted in y too.
  vtkNew<vtkCamera> cam, cam1;
  AxisOrthoCamera(cam, 1.0, AxisOrthoShift);
  const double dy1 = 2 * AxisOrthoShift;
  AxisOrthoCamera(cam1, 1.0, AxisOrthoShift);
  cam1->SetFocalPoint(0.5 + AxisOrthoShift, 0.5 + dy1, 0.5);
  cam1->SetPosition(0.5 + AxisOrthoShift, 0.5 + dy1, 5.0);

  // Max error of an n x n axis image against the analytic one (read in place).
  auto axisError = [&](int n, size_t& inside, size_t& bad, double dy) {
    auto* arr =
      vtkFloatArray::SafeDownCast(scene.Mapper->GetFloatImage()->GetPointData()->GetScalars());
    int dims[3];
    scene.Mapper->GetFloatImage()->GetDimensions(dims);
    inside = bad = 0;
    if (!arr || dims[0] != n || dims[1] != n || arr->GetNumberOfTuples() != vtkIdType(n) * n)
    {
      std::cout << "  wrong image: " << dims[0] << "x" << dims[1] << "\n";
      return 1e300;
    }
    const float* p = arr->GetPointer(0);
    double worst = 0;
    for (int j = 0; j < n; ++j)
    {
      const double y = OrthoPixelCoord(j, n, 1.0, 1.0, dy);
      for (int i = 0; i < n; ++i)
      {
        const double x = OrthoPixelCoord(i, n, 1.0, 1.0, AxisOrthoShift);
        const bool in = x > 0 && x < 1 && y > 0 && y < 1;
        inside += in;
        const double alpha = in ? alphaIn : 0.0;
        const float* v = p + 4 * (size_t(j) * n + i);
        double e = std::abs(v[3] - alpha);
        for (int c = 0; c < 3; ++c)
        {
          e = std::max(e, std::abs(v[c] - color[c] * alpha));
        }
        if (!(e <= 1e-6))
        {
          ++bad;
        }
        worst = std::max(worst, std::isnan(e) ? 1e300 : e);
      }
    }
    return worst;
  };

  // ---- 1x1 through RenderImage: the one pixel centre is the view centre.
  {
    scene.Observer->Clear();
    const int st = scene.Mapper->RenderImage(cam1, scene.Volume, 1, 1);
    size_t inside, bad;
    const double err = axisError(1, inside, bad, dy1);
    const Image img = FloatImage(scene.Mapper);
    std::cout << "== RenderImage 1x1: status=" << st << " rgba=(" << (img.W ? img.At(0, 0, 0) : -1)
              << "," << (img.W ? img.At(0, 0, 1) : -1) << "," << (img.W ? img.At(0, 0, 2) : -1)
              << "," << (img.W ? img.At(0, 0, 3) : -1) << ") expected alpha " << alphaIn
              << " max error " << err << "\n";
    ck.Check(st == 1 && scene.NoMessages(), "1x1: renders without messages");
    ck.Check(inside == 1 && err <= 1e-6, "1x1: the pixel equals the analytic value within 1e-6");
  }

  // ---- 4096x4096 through RenderImage.
  {
    scene.Observer->Clear();
    const auto t0 = std::chrono::steady_clock::now();
    const int st = scene.Mapper->RenderImage(cam, scene.Volume, 4096, 4096);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    size_t inside, bad;
    const double err = axisError(4096, inside, bad, 0.0);
    std::cout << "== RenderImage 4096x4096: status=" << st << " time " << seconds << " s (image "
              << scene.Mapper->GetLastImageTime() << " s), pixels inside " << inside
              << " (expected 2048^2 = " << 2048 * 2048 << "), pixels off by > 1e-6: " << bad
              << ", max error " << err << "\n";
    ck.Check(st == 1 && scene.NoMessages(), "4096: renders without messages");
    ck.Check(inside == size_t(2048) * 2048, "4096: footprint of 2048x2048 pixels");
    ck.Check(err <= 1e-6, "4096: every pixel equals the analytic value within 1e-6");
  }

  // ---- Invalid sizes (0, negative, and beyond 16384 x 16384 pixels, which
  // would ask for tens of GB: refused before anything is allocated) in the
  // CPU and ray-cast paths: an error, status 0, an empty image, no crash.
  const std::pair<int, int> invalid[] = { { 0, 0 }, { -3, 5 }, { 7, -1 }, { 20000, 20000 },
    { 1 << 30, 2 }, { 65536, 65536 }, { 16385, 16384 } };
  for (int mode : { vtkHighOrderVolumeMapper::CPU_ACCURATE, vtkHighOrderVolumeMapper::RAY_CAST })
  {
    scene.Mapper->SetRenderMode(mode);
    for (const auto& wh : invalid)
    {
      const bool large = wh.first > 0 && wh.second > 0;
      const std::string label = std::to_string(wh.first) + "x" + std::to_string(wh.second) +
        (mode == vtkHighOrderVolumeMapper::RAY_CAST ? " RAY_CAST" : " CPU_ACCURATE");
      scene.Observer->Clear();
      const int st = scene.Mapper->RenderImage(cam, scene.Volume, wh.first, wh.second);
      int dims[3];
      scene.Mapper->GetFloatImage()->GetDimensions(dims);
      vtkDataArray* arr = scene.Mapper->GetFloatImage()->GetPointData()->GetScalars();
      vtkDataArray* err = scene.Mapper->GetRayCastErrorImage()->GetPointData()->GetScalars();
      const std::string message = scene.Observer->GetErrorMessage();
      std::cout << "== RenderImage " << label << ": status=" << st << " dims " << dims[0] << "x"
                << dims[1] << " tuples " << (arr ? arr->GetNumberOfTuples() : -1) << " error: '"
                << Msg(message) << "'\n";
      ck.Check(st == 0 && scene.Observer->GetError(), label + ": an error and status 0");
      ck.Check(!large || message.find("exceeds the limit") != std::string::npos,
        label + ": the error names the limit");
      ck.Check(!arr || arr->GetNumberOfTuples() == 0, label + ": an empty image");
      ck.Check(mode != vtkHighOrderVolumeMapper::RAY_CAST || !err || err->GetNumberOfTuples() == 0,
        label + ": an empty error image");
    }
  }
  scene.Mapper->SetRenderMode(vtkHighOrderVolumeMapper::CPU_ACCURATE);

  // ---- 1x1 on screen: the screen pixel equals the float pixel.
  {
    vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam1);
    ren->AddVolume(scene.Volume);
    vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, 1, 1, 0);
    scene.Observer->Clear();
    win->Render();
    const Image fl = FloatImage(scene.Mapper);
    const Image sc = Capture(win);
    std::cout << "== on screen 1x1: float image " << fl.W << "x" << fl.H << ", screen " << sc.W
              << "x" << sc.H << "\n";
    ck.Check(fl.W == 1 && fl.H == 1 && sc.W == 1 && sc.H == 1, "1x1 window: 1x1 float image");
    if (fl.W == 1 && sc.W == 1)
    {
      double e = 0;
      for (int c = 0; c < 3; ++c)
      {
        e = std::max(e, std::abs(fl.At(0, 0, c) - sc.At(0, 0, c)));
      }
      std::cout << "  float rgba (" << fl.At(0, 0, 0) << "," << fl.At(0, 0, 1) << ","
                << fl.At(0, 0, 2) << "," << fl.At(0, 0, 3) << ") screen rgb (" << sc.At(0, 0, 0)
                << "," << sc.At(0, 0, 1) << "," << sc.At(0, 0, 2) << ") max diff " << e * 255
                << "/255\n";
      ck.Check(std::abs(fl.At(0, 0, 3) - alphaIn) <= 1e-6, "1x1 window: float alpha is analytic");
      ck.Check(e <= 1.5 / 255, "1x1 window: screen = float image within 1.5/255");
    }
    ck.Check(scene.NoMessages(), "1x1 window: no messages");
    scene.Mapper->ReleaseGraphicsResources(win);
  }
  return ck.Result();
}
