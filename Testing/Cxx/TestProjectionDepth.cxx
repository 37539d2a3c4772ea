// OPENGL_PROJECTION mode: opaque geometry clips the volume through the depth
// test against the scene depth (UseDepthBuffer, default on), as
// TestOpenGLDepth checks for the CPU path.
//
// Orthographic view of the unit tetrahedral block (2x2x2 cubes) along -z,
// constant transfer function (GPU semantics: alpha = 1 - (1-a)^(L/u)), three
// unlit opaque plates spanning the block in y:
//   F: x in [-0.3, 0.25], z in [1.2, 1.4]   in front of the whole volume
//   M: x in [0.40, 0.60], z in [0.45, 0.55] inside it
//   B: x in [0.75, 1.30], z in [-0.4, -0.2] behind it
// The projection keeps or drops whole cell fragments by the depth of their
// front face: under M the cells entered above z = 0.55 are drawn whole, so
// the remaining thickness is between 0.45 and 0.5 (no cell crosses the cube
// boundary z = 0.5). Checked per pixel (1.5 pixel margin): float alpha 0
// under F; between the alphas of 0.45 and 0.5 under M; equal to the image
// without plates under B and where there is no plate; the screen is float +
// (1 - alpha) x the plate's colour. Without and with multisampling; with
// UseDepthBuffer off the plates do not clip.
#include "hovTestScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <iostream>

using namespace hovTest;

namespace
{
/// Largest deviations per plate region of one configuration.
struct Regions
{
  size_t F = 0, M = 0, B = 0, None = 0;
  double ErrF = 0, BelowM = 0, AboveM = 0, ErrB = 0, ErrNone = 0, ErrBlend = 0;
};

const double PlateF[6] = { -0.3, 0.25, -0.3, 1.3, 1.2, 1.4 };
const double PlateM[6] = { 0.40, 0.60, -0.3, 1.3, 0.45, 0.55 };
const double PlateB[6] = { 0.75, 1.30, -0.3, 1.3, -0.4, -0.2 };

/// Compare the images pixel by pixel (see file doc).
Regions Measure(const Image& with, const Image& without, const Image& platesOnly,
  const Image& screen, int n, double alphaLow, double alphaHigh)
{
  Regions r;
  const double margin = 1.5 * 2.0 / n; // 1.5 pixels in world units
  auto within = [&](double v, double lo, double hi) { return v > lo + margin && v < hi - margin; };
  auto outside = [&](double v, double lo, double hi) { return v < lo - margin || v > hi + margin; };
  for (int j = 0; j < n; ++j)
  {
    if (!within(OrthoPixelCoord(j, n), 0.0, 1.0))
    {
      continue;
    }
    for (int i = 0; i < n; ++i)
    {
      const double x = OrthoPixelCoord(i, n, 1.0, 1.0, AxisOrthoShift);
      const double aw = with.At(i, j, 3);
      if (within(x, PlateF[0], PlateF[1]))
      {
        ++r.F;
        r.ErrF = std::max(r.ErrF, std::abs(aw));
      }
      else if (within(x, PlateM[0], PlateM[1]))
      {
        ++r.M;
        r.BelowM = std::max(r.BelowM, alphaLow - aw);
        r.AboveM = std::max(r.AboveM, aw - alphaHigh);
        for (int c = 0; c < 3; ++c)
        {
          const double expect = with.At(i, j, c) + (1 - aw) * platesOnly.At(i, j, c);
          r.ErrBlend = std::max(r.ErrBlend, std::abs(screen.At(i, j, c) - expect));
        }
      }
      else if (within(x, PlateB[0], PlateB[1]))
      {
        ++r.B;
        r.ErrB = std::max(r.ErrB, std::abs(aw - without.At(i, j, 3)));
      }
      else if (outside(x, PlateF[0], PlateF[1]) && outside(x, PlateM[0], PlateM[1]) &&
        outside(x, PlateB[0], PlateB[1]))
      {
        ++r.None;
        for (int c = 0; c < 4; ++c)
        {
          r.ErrNone = std::max(r.ErrNone, std::abs(with.At(i, j, c) - without.At(i, j, c)));
        }
      }
    }
  }
  return r;
}
}

int TestProjectionDepth(int, char*[])
{
  Checker ck;
  VolumeScene scene(UnitBlock(2).Grid());
  const double a = 0.5, u = 0.5, orange[3] = { 0.9, 0.6, 0.3 };
  ConstantTF(scene.Tf, orange, a, u);
  scene.Mapper->SetRenderModeToOpenGLProjection();
  scene.Mapper->SetProjectionColorMethod(3);

  const int n = 128;
  vtkNew<vtkCamera> cam;
  AxisOrthoCamera(cam, 1.0, AxisOrthoShift);
  vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam);
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, n, n);
  const double green[3] = { 0.1, 0.7, 0.2 };
  auto F = BoxActor(PlateF, green), M = BoxActor(PlateM, green), B = BoxActor(PlateB, green);
  const double alphaFull = 1.0 - std::pow(1.0 - a, 1.0 / u);
  const double alphaLow = 1.0 - std::pow(1.0 - a, 0.45 / u);
  const double alphaHigh = 1.0 - std::pow(1.0 - a, 0.5 / u);
  for (int samples : { 0, 8 })
  {
    win->SetMultiSamples(samples);
    ren->RemoveAllViewProps();
    ren->AddVolume(scene.Volume);
    scene.Observer->Clear();
    win->Render();
    const Image without = FloatImage(scene.Mapper);
    ren->RemoveVolume(scene.Volume);
    ren->AddActor(F);
    ren->AddActor(M);
    ren->AddActor(B);
    win->Render();
    const Image platesOnly = Capture(win);
    ren->AddVolume(scene.Volume);
    win->Render();
    const Image with = FloatImage(scene.Mapper);
    const Regions r = Measure(with, without, platesOnly, Capture(win), n, alphaLow, alphaHigh);
    const std::string tag = "multisamples " + std::to_string(samples) + ": ";
    std::cout << "== " << tag << "alpha without plates " << alphaFull << ", under M expected in ["
              << alphaLow << ", " << alphaHigh << "]\n"
              << "  under F (in front):  " << r.F << " pixels, max float alpha " << r.ErrF << "\n"
              << "  under M (cuts rays): " << r.M << " pixels, max below " << r.BelowM
              << ", max above " << r.AboveM << "\n"
              << "  under B (behind):    " << r.B << " pixels, max |alpha change| " << r.ErrB << "\n"
              << "  no plate:            " << r.None << " pixels, max |rgba change| " << r.ErrNone
              << "\n  screen under M vs float over plate colour: max " << r.ErrBlend * 255
              << "/255\n";
    ck.Check(scene.NoMessages(), tag + "no messages");
    ck.Check(r.F > 500 && r.M > 300 && r.B > 500 && r.None > 300, tag + "every region has pixels");
    ck.Check(r.ErrF == 0.0, tag + "plate in front of the volume: float alpha is exactly 0");
    ck.Check(r.BelowM <= 1e-4 && r.AboveM <= 1e-4,
      tag + "plate inside the volume: alpha of a remaining thickness in [0.45, 0.5]");
    ck.Check(alphaHigh < alphaFull - 0.1, tag + "(the cut is visible)");
    ck.Check(r.ErrB == 0.0, tag + "plate behind the volume: float image unchanged");
    ck.Check(r.ErrNone == 0.0, tag + "no plate: float image unchanged");
    ck.Check(r.ErrBlend <= 1.5 / 255, tag + "screen = float over the plate within 1.5/255");
  }
  // UseDepthBuffer off: the plates do not clip.
  win->SetMultiSamples(0);
  ren->RemoveAllViewProps();
  ren->AddVolume(scene.Volume);
  win->Render();
  const Image without = FloatImage(scene.Mapper);
  ren->AddActor(F);
  ren->AddActor(M);
  ren->AddActor(B);
  scene.Mapper->UseDepthBufferOff();
  win->Render();
  const DiffStats off = Diff(FloatImage(scene.Mapper), without);
  std::cout << "== UseDepthBuffer off, with plates vs no plates: " << off.Str() << "\n";
  ck.Check(off.Max == 0.0, "UseDepthBuffer off: the plates do not clip the float image");
  ck.Check(scene.NoMessages(), "no messages");
  return ck.Result();
}
