// Opaque geometry clips the volume at its depth (UseDepthBuffer, default on).
//
// Orthographic view of the unit cube along -z (camera at z = 5), constant
// transfer function (GPU semantics: alpha = 1 - (1-a)^(L/u) for thickness L),
// three unlit opaque plates spanning the cube in y:
//   F: x in [-0.3, 0.25], z in [1.2, 1.4]   in front of the whole volume
//   M: x in [0.40, 0.60], z in [0.45, 0.55] inside it: rays stop at z = 0.55
//   B: x in [0.75, 1.30], z in [-0.4, -0.2] behind it
// Checked per pixel (1.5 pixel margin to the plate edges): float alpha 0
// under F; 1 - (1-a)^(0.45/u) under M (less than without the plate); equal
// to the image without plates under B and where there is no plate; the
// screen is float + (1 - alpha) x the plate's colour. With UseDepthBuffer off
// the plates do not clip. The same with the volume stretched by its matrix.
// A perspective oblique view with a slanted slab
// through the volume: alpha never grows, is unchanged where the slab is
// absent from the depth buffer, and drops where it cuts the rays.
#include "hovTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"

#include <cmath>
#include <iostream>
#include <vector>

using namespace hovTest;

int TestOpenGLDepth(int, char*[])
{
  Checker ck;
  VolumeScene scene(UnitBlock(2).Grid());
  const double a = 0.5, u = 0.5, orange[3] = { 0.9, 0.6, 0.3 };
  ConstantTF(scene.Tf, orange, a, u);

  const int n = 128;
  vtkNew<vtkCamera> cam;
  AxisOrthoCamera(cam, 1.0, AxisOrthoShift);
  vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam);
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, n, n);

  const double green[3] = { 0.1, 0.7, 0.2 };
  const double plateF[6] = { -0.3, 0.25, -0.3, 1.3, 1.2, 1.4 };
  const double plateM[6] = { 0.40, 0.60, -0.3, 1.3, 0.45, 0.55 };
  const double plateB[6] = { 0.75, 1.30, -0.3, 1.3, -0.4, -0.2 };
  auto F1 = BoxActor(plateF, green), M = BoxActor(plateM, green), B1 = BoxActor(plateB, green);
  // The same with the volume stretched to world z in [-0.5, 1.5] (SetScale(1,1,2),
  // SetPosition(0,0,-0.5)): F and B move out of its way; M's front face at
  // world z = 0.55 is data z = 0.525, and lengths are measured in dataset
  // coordinates, so the remaining thickness under M is 0.475.
  const double plateF2[6] = { -0.3, 0.25, -0.3, 1.3, 1.7, 1.8 };
  const double plateB2[6] = { 0.75, 1.30, -0.3, 1.3, -0.9, -0.7 };
  auto F2 = BoxActor(plateF2, green), B2 = BoxActor(plateB2, green);

  // MSAA off and on (a multisampled depth buffer must be read correctly
  // too), then the stretched volume.
  for (int config : { 0, 1, 2 })
  {
    const int samples = config == 1 ? 8 : 0;
    const bool stretched = config == 2;
    const double cutThickness = stretched ? 0.475 : 0.45;
    win->SetMultiSamples(samples);
    scene.Volume->SetScale(1, 1, stretched ? 2 : 1);
    scene.Volume->SetPosition(0, 0, stretched ? -0.5 : 0);
    vtkActor* F = stretched ? F2.Get() : F1.Get();
    vtkActor* B = stretched ? B2.Get() : B1.Get();
    ren->RemoveAllViewProps();
    std::cout << "== window multisamples " << samples
              << (stretched ? ", volume stretched x2 in z (world z in [-0.5, 1.5])" : "") << "\n";
    // References: volume alone (on screen and RenderImage), plates alone.
    ren->AddVolume(scene.Volume);
    scene.Observer->Clear();
    win->Render();
    const Image noPlates = FloatImage(scene.Mapper);
    ren->RemoveVolume(scene.Volume);
    ren->AddActor(F);
    ren->AddActor(M);
    ren->AddActor(B);
    win->Render();
    const Image platesOnly = Capture(win);
    ren->AddVolume(scene.Volume);
    win->Render();
    const Image withPlates = FloatImage(scene.Mapper);
    const Image screen = Capture(win);
    ck.Check(scene.NoMessages(), "no messages");

    const double alphaFull = 1.0 - std::pow(1.0 - a, 1.0 / u);
    const double alphaCut = 1.0 - std::pow(1.0 - a, cutThickness / u);
    const double margin = 1.5 * 2.0 / n; // 1.5 pixels in world units
    auto within = [&](double v, double lo, double hi) { return v > lo + margin && v < hi - margin; };
    auto outside = [&](double v, double lo, double hi) { return v < lo - margin || v > hi + margin; };
    size_t cntF = 0, cntM = 0, cntB = 0, cntNone = 0;
    double errF = 0, errM = 0, errB = 0, errNone = 0, errBlend = 0, errMvsFull = 0;
    for (int j = 0; j < n; ++j)
    {
      const double y = OrthoPixelCoord(j, n);
      const bool inY = within(y, 0.0, 1.0);
      for (int i = 0; i < n; ++i)
      {
        const double x = OrthoPixelCoord(i, n, 1.0, 1.0, AxisOrthoShift);
        const double aw = withPlates.At(i, j, 3);
        const double a0 = noPlates.At(i, j, 3);
        if (!inY)
        {
          continue;
        }
        if (within(x, plateF[0], plateF[1]))
        {
          ++cntF;
          errF = std::max(errF, std::abs(aw));
        }
        else if (within(x, plateM[0], plateM[1]))
        {
          ++cntM;
          errM = std::max(errM, std::abs(aw - alphaCut));
          errMvsFull = std::max(errMvsFull, std::abs(a0 - alphaFull));
          // Screen: float colour over the plate's colour.
          for (int c = 0; c < 3; ++c)
          {
            const double expect = withPlates.At(i, j, c) + (1 - aw) * platesOnly.At(i, j, c);
            errBlend = std::max(errBlend, std::abs(screen.At(i, j, c) - expect));
          }
        }
        else if (within(x, plateB[0], plateB[1]))
        {
          ++cntB;
          errB = std::max(errB, std::abs(aw - a0));
        }
        else if (outside(x, plateF[0], plateF[1]) && outside(x, plateM[0], plateM[1]) &&
          outside(x, plateB[0], plateB[1]))
        {
          ++cntNone;
          for (int c = 0; c < 4; ++c)
          {
            errNone = std::max(errNone, std::abs(withPlates.At(i, j, c) - noPlates.At(i, j, c)));
          }
        }
      }
    }
    std::cout << "== orthographic view " << n << "x" << n << ", alpha without plates " << alphaFull
              << ", expected under M " << alphaCut << "\n"
              << "  under F (in front):  " << cntF << " pixels, max float alpha " << errF << "\n"
              << "  under M (cuts rays): " << cntM << " pixels, max |alpha - " << alphaCut
              << "| = " << errM << " (without plates |alpha - " << alphaFull
              << "| = " << errMvsFull << ")\n"
              << "  under B (behind):    " << cntB << " pixels, max |alpha - alpha without plates| = "
              << errB << "\n"
              << "  no plate:            " << cntNone << " pixels, max |rgba - without plates| = "
              << errNone << "\n"
              << "  screen under M vs float over plate colour: max " << errBlend * 255 << "/255\n";
    ck.Check(cntF > 500 && cntM > 300 && cntB > 500 && cntNone > 300, "every region has pixels");
    ck.Check(errMvsFull <= 1e-6, "without plates the volume has the analytic full-thickness alpha");
    ck.Check(errF == 0.0, "plate in front of the volume: float alpha is exactly 0");
    ck.Check(errM <= 1e-4, "plate inside the volume: alpha of the remaining thickness " + Fmt(cutThickness));
    ck.Check(alphaCut < alphaFull - 0.1, "(the cut is visible: " + Fmt(alphaCut) + " vs " + Fmt(alphaFull) + ")");
    ck.Check(errB == 0.0, "plate behind the volume: float image unchanged");
    ck.Check(errNone == 0.0, "no plate: float image unchanged");
    ck.Check(errBlend <= 1.5 / 255, "screen = float over the plate within 1.5/255");
  }

  // UseDepthBuffer off: the plates do not clip.
  win->SetMultiSamples(0);
  scene.Volume->SetScale(1, 1, 1);
  scene.Volume->SetPosition(0, 0, 0);
  ren->RemoveAllViewProps();
  ren->AddVolume(scene.Volume);
  win->Render();
  const Image noPlates = FloatImage(scene.Mapper);
  ren->AddActor(F1);
  ren->AddActor(M);
  ren->AddActor(B1);
  scene.Mapper->UseDepthBufferOff();
  win->Render();
  const DiffStats off = Diff(FloatImage(scene.Mapper), noPlates);
  std::cout << "== UseDepthBuffer off, with plates vs no plates: " << off.Str() << "\n";
  ck.Check(off.Max == 0.0, "UseDepthBuffer off: the plates do not clip the float image");
  scene.Mapper->UseDepthBufferOn();

  // Perspective oblique view, a slanted slab through the volume.
  {
    vtkNew<vtkCamera> pcam;
    ObliqueCamera(pcam);
    vtkSmartPointer<vtkRenderer> pren = BlackRenderer(pcam);
    vtkSmartPointer<vtkRenderWindow> pwin = OffscreenWindow(pren, 200, 150, 0);
    const double slabBounds[6] = { -0.5, 0.5, -0.5, 0.5, -0.04, 0.04 };
    auto slab = BoxActor(slabBounds, green);
    vtkNew<vtkTransform> t;
    t->Translate(0.55, 0.45, 0.5);
    t->RotateX(35);
    t->RotateY(-20);
    slab->SetUserTransform(t);
    pren->AddVolume(scene.Volume);
    pwin->Render();
    const Image free = FloatImage(scene.Mapper);
    pren->RemoveVolume(scene.Volume);
    pren->AddActor(slab);
    pwin->Render();
    std::vector<float> z(200 * 150);
    pwin->GetZbufferData(0, 0, 199, 149, z.data());
    pren->AddVolume(scene.Volume);
    pwin->Render();
    const Image clipped = FloatImage(scene.Mapper);
    size_t slabPixels = 0, reduced = 0, grew = 0, changedNoSlab = 0;
    double maxDrop = 0;
    for (int j = 0; j < 150; ++j)
    {
      for (int i = 0; i < 200; ++i)
      {
        const double d = clipped.At(i, j, 3) - free.At(i, j, 3);
        const bool hasSlab = z[j * 200 + i] < 1.0f;
        slabPixels += hasSlab;
        grew += d > 1e-7;
        reduced += d < -1e-3;
        maxDrop = std::max(maxDrop, -d);
        if (!hasSlab)
        {
          for (int c = 0; c < 4; ++c)
          {
            changedNoSlab += clipped.At(i, j, c) != free.At(i, j, c);
          }
        }
      }
    }
    std::cout << "== perspective oblique 200x150, slanted slab: slab pixels " << slabPixels
              << ", alpha reduced by > 1e-3 at " << reduced << " pixels (max drop " << maxDrop
              << "), alpha grew at " << grew << ", values changed where no slab: " << changedNoSlab
              << "\n";
    ck.Check(slabPixels > 1000 && reduced > 500, "the slab cuts the volume at many pixels");
    ck.Check(grew == 0, "opaque geometry never increases the volume's alpha");
    ck.Check(changedNoSlab == 0, "pixels without geometry are unchanged");
    scene.Mapper->ReleaseGraphicsResources(pwin);
  }
  ck.Check(scene.NoMessages(), "no messages");
  scene.Mapper->ReleaseGraphicsResources(win);
  return ck.Result();
}
