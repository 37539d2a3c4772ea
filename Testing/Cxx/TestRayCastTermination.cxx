// RAY_CAST honours TerminationTransmittance (issue 17; before, the ray caster
// stopped at a hard-coded 1e-12). A constant-field block of 8^3 Kuhn cubes
// (3072 linear tetrahedra) of optical depth 10 per unit length, seen along
// -z (orthographic): every ray crosses many cells, and both the CPU projector
// and the ray caster stop a pixel after the first cell interval that takes
// its transmittance to TerminationTransmittance or below. Checks, per setting
// T in { 0.05, 1e-3, 0 }:
//  - RAY_CAST equals CPU_ACCURATE at every pixel (1e-6: both exact for a
//    constant field, and they stop at the same interval);
//  - the centre pixel stopped where it should: its transmittance 1 - alpha is
//    <= T and above T x exp(-10 x the longest interval) (it stopped after the
//    first interval that crossed T), or the whole block (T = 0);
//  - T = 0.05 leaves visibly more light through than T = 0 (by more than 0.02
//    in alpha: the setting changes the image, as it did not before).
#include "hovTestScenes.h"

#include "vtkCamera.h"

#include <cmath>
#include <iostream>

using namespace hovTest;

namespace
{
constexpr int N = 32;   // image side (pixels)
constexpr int Cells = 8; // cubes per axis
constexpr double Tau = 10.0;

/// The image of @p scene in @p mode with TerminationTransmittance @p t.
Image RenderWith(VolumeScene& scene, vtkCamera* cam, int mode, double t, int& status)
{
  scene.Mapper->SetRenderMode(mode);
  scene.Mapper->SetTerminationTransmittance(t);
  return Render(scene.Mapper, cam, scene.Volume, N, N, &status);
}
}

int TestRayCastTermination(int, char*[])
{
  Checker ck;
  MeshBuilder mb;
  const double o[3] = { 0.0, 0.0, 0.0 }, size[3] = { 1.0, 1.0, 1.0 };
  mb.AddTetBlock(Cells, Cells, Cells, o, size, [](double, double, double) { return 0.5; });
  VolumeScene scene(mb.Grid());
  const double white[3] = { 1.0, 1.0, 1.0 };
  ConstantTF(scene.Tf, white, 1.0, 0.1); // VTK-unstructured: tau = a / u = 10
  scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
  vtkNew<vtkCamera> cam;
  AxisOrthoCamera(cam, 1.0, AxisOrthoShift);

  const double settings[3] = { 0.05, 1e-3, 0.0 };
  double centreAlpha[3] = { 0.0, 0.0, 0.0 };
  for (int k = 0; k < 3; ++k)
  {
    const double t = settings[k];
    int cpuStatus = 0, rayStatus = 0;
    const Image cpu = RenderWith(scene, cam, vtkHighOrderVolumeMapper::CPU_ACCURATE, t, cpuStatus);
    const Image ray = RenderWith(scene, cam, vtkHighOrderVolumeMapper::RAY_CAST, t, rayStatus);
    const DiffStats d = Diff(cpu, ray, 0, 4, 1e-6);
    const double a = ray.At(N / 2, N / 2, 3);
    centreAlpha[k] = a;
    std::cout << "[measured] TerminationTransmittance " << t << ": RAY_CAST vs CPU_ACCURATE "
              << d.Str() << "; centre alpha " << Fmt(a) << " (transmittance " << Fmt(1.0 - a)
              << ")\n";
    ck.Check(cpuStatus == 1 && rayStatus == 1 && scene.NoMessages(),
      "T " + Fmt(t) + ": rendered without messages");
    ck.Check(d.Count > 0 && d.Max < 1e-6, "T " + Fmt(t) + ": RAY_CAST equals CPU_ACCURATE");
    // The longest interval of a ray along z through a Kuhn cube is its height.
    const double lastInterval = std::exp(-Tau / Cells);
    // T = 0: the whole block, exp(-Tau), to the float image's precision near
    // alpha 1 (half a float ulp there is 3e-8).
    const bool stopped = t > 0.0 ? (1.0 - a <= t && 1.0 - a > t * lastInterval - 1e-12)
                                 : std::abs((1.0 - a) - std::exp(-Tau)) < 6e-8;
    ck.Check(stopped, "T " + Fmt(t) + ": the centre ray stopped at the first interval below T");
  }
  ck.Check(centreAlpha[2] - centreAlpha[0] > 0.02,
    "T 0.05 leaves more light through than T 0 (" + Fmt(centreAlpha[0]) + " < " +
      Fmt(centreAlpha[2]) + ")");
  return ck.Result();
}
