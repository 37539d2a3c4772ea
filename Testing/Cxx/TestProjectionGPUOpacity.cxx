// OPENGL_PROJECTION in GPU-compatible semantics (the mapper's default): the
// extinction -ln(1 - a)/u is not linear in s, but the opacity a is between
// the property's nodes, so the projection cuts cells only at those nodes and
// each fragment takes the exact mean extinction of its segment from the
// opacities at its ends (hov::GPUAverageExtinction, ported to the fragment
// shader); M3's vertex colours integrate the refined table. Before, every
// cell was cut at the refined table's nodes too: 2.6M triangles for the
// bracket instead of 0.22M, 6x the frame time. Scenes on the 3^3 Kuhn cube,
// perspective, against the CPU path's float image (GPU-compatible, refined
// table at 1e-4):
//  1. a steep ramp to opacity 0.95 (strongly convex -ln(1 - a)): M3 within
//     2/255 (also with Wilhelms-Van Gelder emission and with the opacity
//     texture) with slabs within 3x VTK-unstructured semantics' (the coarse
//     refinement of vtkHighOrderTransferFunction::SlabTolerance 0.1; with
//     slabs at the property's nodes only, M3 was 2.2/255 off: vertex colours
//     interpolated over too large regions);
//  2. faint opacities (1e-7 .. 1e-6, where 1 - a in float is useless):
//     alpha within 1% of the CPU's (analytic lookup and texture);
//  3. opacity 1 over the top of the range (an opaque medium, a log
//     singularity where a reaches 1): finite, alpha <= 1, M3 within 2/255.
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
struct Result
{
  double MaxError = 0.0; ///< max |M3 - CPU| over every channel and pixel
  double MaxAlpha = 0.0; ///< of the CPU image
  double MaxRelativeAlpha = 0.0; ///< max |alpha - CPU alpha| / CPU alpha (CPU alpha > 1% of its max)
  double MaxAlphaError = 0.0;    ///< max |alpha - CPU alpha|
  vtkIdType Slabs = 0, Triangles = 0;
  bool Sane = false;
};

/// CPU image and M3 projection of @p scene in @p semantics.
Result Run(VolumeScene& scene, vtkRenderWindow* win, int semantics)
{
  Result r;
  scene.Mapper->SetOpacitySemantics(semantics);
  const CPUAndProjection images = RenderCPUAndProjectionM3(scene.Mapper, win);
  const Image &cpu = images.CPU, &proj = images.Projection;
  r.MaxError = Diff(proj, cpu).Max;
  r.MaxAlphaError = Diff(proj, cpu, 3, 4).Max;
  r.MaxAlpha = CheckImage(cpu).MaxA;
  for (size_t p = 0; p < cpu.Pixels(); ++p)
  {
    const double a = cpu.V[4 * p + 3];
    if (a > 0.01 * r.MaxAlpha)
    {
      const double rel = std::abs(proj.V[4 * p + 3] - a) / a;
      r.MaxRelativeAlpha = std::max(r.MaxRelativeAlpha, rel);
    }
  }
  r.Slabs = scene.Mapper->GetNumberOfProjectedSlabs();
  r.Triangles = scene.Mapper->GetNumberOfProjectedTriangles();
  // Finite, 0 <= alpha <= 1 (colour <= alpha does not hold for Wilhelms-Van Gelder glow).
  const Sanity sp = CheckImage(proj);
  r.Sane = sp.NonFinite == 0 && sp.AlphaOut == 0 && CheckImage(cpu).Covered > 2000;
  return r;
}
}

int TestProjectionGPUOpacity(int, char*[])
{
  Checker ck;
  VolumeScene scene(UnitBlock(3).Grid());
  vtkNew<vtkCamera> cam;
  ObliqueCamera(cam);
  vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam);
  ren->AddVolume(scene.Volume);
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, 96, 96, 0);
  scene.Tf.Color->AddRGBPoint(0.0, 0.1, 0.3, 0.9);
  scene.Tf.Color->AddRGBPoint(1.75, 0.9, 0.4, 0.1);
  scene.Tf.Property->SetScalarOpacityUnitDistance(0.4);

  // 1. Steep ramp.
  scene.Tf.Opacity->AddPoint(0.0, 0.05);
  scene.Tf.Opacity->AddPoint(1.75, 0.95);
  const Result gpu = Run(scene, win, vtkHighOrderVolumeMapper::GPU_COMPATIBLE);
  const Result vtk = Run(scene, win, vtkHighOrderVolumeMapper::VTK_UNSTRUCTURED);
  std::cout << "[measured] ramp to 0.95: GPU-compatible max |M3 - CPU| " << gpu.MaxError * 255
            << "/255, slabs " << gpu.Slabs << ", triangles " << gpu.Triangles
            << "; VTK-unstructured " << vtk.MaxError * 255 << "/255, slabs " << vtk.Slabs
            << ", triangles " << vtk.Triangles << std::endl;
  ck.Check(gpu.Sane && vtk.Sane, "ramp: sane images");
  ck.Check(gpu.Slabs < 3 * vtk.Slabs, "ramp: slabs within 3x VTK-unstructured semantics'");
  ck.Check(gpu.MaxError <= 2.0 / 255, "ramp: M3 within 2/255 of the CPU image");
  // The same with Wilhelms-Van Gelder emission (the glow divides by the exact
  // mean extinction) and with HIAC's opacity texture instead of the analytic
  // lookup.
  scene.Mapper->SetEmissionModelToWilhelmsVanGelder();
  const Result wvg = Run(scene, win, vtkHighOrderVolumeMapper::GPU_COMPATIBLE);
  scene.Mapper->SetEmissionModelToWilliamsMax();
  scene.Mapper->SetProjectionOpacityLookupToTexture();
  const Result texture = Run(scene, win, vtkHighOrderVolumeMapper::GPU_COMPATIBLE);
  scene.Mapper->SetProjectionOpacityLookupToAnalytic();
  std::cout << "[measured] ramp: Wilhelms-Van Gelder max |M3 - CPU| " << wvg.MaxError * 255
            << "/255; opacity texture " << texture.MaxError * 255 << "/255" << std::endl;
  ck.Check(wvg.Sane && wvg.MaxError <= 2.0 / 255, "ramp, Wilhelms-Van Gelder: M3 within 2/255");
  ck.Check(texture.Sane && texture.MaxError <= 2.0 / 255, "ramp, opacity texture: M3 within 2/255");

  // 2. Faint opacities: 1 - a is 1 in float below a = 6e-8, and off by up to
  // 30% at a = 1e-7 (its spacing near 1 is 6e-8): the fragment shader must
  // not form it (it takes -log1p(-a) from a).
  scene.Tf.Opacity->RemoveAllPoints();
  scene.Tf.Opacity->AddPoint(0.0, 1e-7);
  scene.Tf.Opacity->AddPoint(1.75, 1e-6);
  const Result faint = Run(scene, win, vtkHighOrderVolumeMapper::GPU_COMPATIBLE);
  const Result faintVTK = Run(scene, win, vtkHighOrderVolumeMapper::VTK_UNSTRUCTURED);
  std::cout << "[measured] faint (1e-7 .. 1e-6): max |alpha - CPU| " << faint.MaxAlphaError
            << ", max alpha " << faint.MaxAlpha << ", max relative alpha error "
            << faint.MaxRelativeAlpha << " (VTK-unstructured semantics, the same scene: "
            << faintVTK.MaxRelativeAlpha << ")" << std::endl;
  ck.Check(faint.MaxAlpha > 0.0 && faint.MaxAlphaError <= 1e-2 * faint.MaxAlpha &&
      faint.MaxRelativeAlpha <= 1e-2,
    "faint: alpha within 1% of the CPU's (of the largest alpha, and per pixel)");
  scene.Mapper->SetProjectionOpacityLookupToTexture();
  const Result faintTexture = Run(scene, win, vtkHighOrderVolumeMapper::GPU_COMPATIBLE);
  scene.Mapper->SetProjectionOpacityLookupToAnalytic();
  std::cout << "[measured] faint, opacity texture: max relative alpha error "
            << faintTexture.MaxRelativeAlpha << std::endl;
  ck.Check(faintTexture.MaxRelativeAlpha <= 1e-2, "faint, opacity texture: alpha within 1%");

  // 3. Opaque medium over the top of the range.
  scene.Tf.Opacity->RemoveAllPoints();
  scene.Tf.Opacity->AddPoint(0.0, 0.1);
  scene.Tf.Opacity->AddPoint(1.2, 1.0);
  scene.Tf.Opacity->AddPoint(1.75, 1.0);
  const Result opaque = Run(scene, win, vtkHighOrderVolumeMapper::GPU_COMPATIBLE);
  std::cout << "[measured] opaque medium: max |M3 - CPU| " << opaque.MaxError * 255
            << "/255, max alpha " << opaque.MaxAlpha << std::endl;
  ck.Check(opaque.Sane, "opaque medium: finite, alpha <= 1");
  ck.Check(opaque.MaxError <= 2.0 / 255, "opaque medium: M3 within 2/255 of the CPU image");
  ck.Check(scene.NoMessages(), "no messages");
  return ck.Result();
}
