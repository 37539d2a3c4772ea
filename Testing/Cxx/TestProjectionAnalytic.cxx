// OPENGL_PROJECTION mode (HIAC section 7) against the CPU path's float image
// on the analytic scenes of the foundation issue (acceptance 1 of issue 5):
//  - a single tetrahedron with a constant field;
//  - a 4x4x4 cube of Kuhn tetrahedra (384) with the linear field and the
//    transfer function of TestAnalyticCube (colour and opacity nodes at
//    different scalars, an opacity peak, clamping past both ends), so every
//    cell is cut into slabs and the colour varies along every ray;
// orthographic and perspective views, opacity semantics VTK-unstructured,
// raw extinction and GPU-compatible, Williams-Max emission (plus one
// Wilhelms-Van Gelder case), methods M0-M3, exact (Stein) order.
//
// Checks: at every pixel covered by either image, |M3 - CPU| <= 2/255 per
// channel; the projection covers the same pixels; on the cube (colour varying
// along rays) the maximum errors are ordered M0 >= M1 >= M2 >= M3. Every
// error is printed (max and mean over covered pixels, all channels).
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"

#include "hovTestReference.h" // MakeTetra, MakeCubeOfTetras

#include <cmath>
#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
constexpr int Width = 96;
constexpr int Height = 80;
constexpr double Tolerance = 2.0 / 255.0;

struct Errors
{
  double Max = 0, Mean = 0;
  size_t Covered = 0, CoverMismatch = 0;
};

/// |a - b| over pixels covered (alpha > 1e-6) in either image.
Errors Compare(const Image& proj, const Image& cpu)
{
  Errors e;
  double sum = 0;
  for (int j = 0; j < cpu.H; ++j)
  {
    for (int i = 0; i < cpu.W; ++i)
    {
      const bool cc = cpu.At(i, j, 3) > 1e-6, pc = proj.At(i, j, 3) > 1e-6;
      if (!cc && !pc)
      {
        continue;
      }
      ++e.Covered;
      e.CoverMismatch += cc != pc;
      for (int c = 0; c < 4; ++c)
      {
        const double d = std::fabs(proj.At(i, j, c) - cpu.At(i, j, c));
        e.Max = std::max(e.Max, d);
        sum += d;
      }
    }
  }
  e.Mean = e.Covered ? sum / (4.0 * e.Covered) : 0.0;
  return e;
}

void CubeTF(TF& tf)
{
  tf.Color->RemoveAllPoints();
  tf.Color->AddRGBPoint(0.0, 0.9, 0.2, 0.1);
  tf.Color->AddRGBPoint(0.3, 0.2, 0.8, 0.3);
  tf.Color->AddRGBPoint(0.55, 0.1, 0.3, 0.9);
  tf.Color->AddRGBPoint(1.0, 1.0, 1.0, 0.2);
  tf.Opacity->RemoveAllPoints();
  tf.Opacity->AddPoint(0.05, 0.02);
  tf.Opacity->AddPoint(0.25, 0.15);
  tf.Opacity->AddPoint(0.45, 0.85);
  tf.Opacity->AddPoint(0.62, 0.1);
  tf.Opacity->AddPoint(0.9, 0.4);
  tf.Opacity->AddPoint(1.1, 0.3);
  tf.Property->SetScalarOpacityUnitDistance(0.8);
}

struct Scene
{
  const char* Name;
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  bool ColorVariesAlongRays;
};
}

int TestProjectionAnalytic(int, char*[])
{
  Checker ck;
  const double origin[3] = { -1, -1, -1 }, gradient[3] = { 0.3, -0.2, 0.25 };
  const double tet[4][3] = { { -0.6, -0.5, -0.4 }, { 0.8, -0.4, -0.6 }, { -0.3, 0.8, -0.15 },
    { -0.2, -0.15, 0.9 } };
  const double constant[4] = { 0.37, 0.37, 0.37, 0.37 };
  const Scene scenes[] = {
    { "single tetra, constant field", hovTestRef::MakeTetra(tet, constant), false },
    { "4x4x4 Kuhn cube, linear field", hovTestRef::MakeCubeOfTetras(4, origin, 2.0, 6, 0.5, gradient),
      true },
  };
  vtkNew<vtkCamera> cam;
  vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam);
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, Width, Height, 0);
  for (const Scene& scene : scenes)
  {
    VolumeScene vs(scene.Grid);
    CubeTF(vs.Tf);
    ren->RemoveAllViewProps();
    ren->AddVolume(vs.Volume);
    for (int view = 0; view < 2; ++view)
    {
      const double focal[3] = { 0, 0, 0 };
      const double dir[2][3] = { { 1.3, 0.8, 1.7 }, { -1.1, 1.6, 0.9 } };
      double d[3] = { dir[view][0], dir[view][1], dir[view][2] };
      const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      const double dist = view == 0 ? 6.0 : 5.5;
      cam->SetFocalPoint(focal);
      cam->SetPosition(dist * d[0] / n, dist * d[1] / n, dist * d[2] / n);
      cam->SetViewUp(0, 0, 1);
      cam->SetParallelProjection(view == 0);
      cam->SetParallelScale(1.9);
      cam->SetViewAngle(40);
      cam->SetClippingRange(dist - 2.5, dist + 2.5);
      for (int sem : { 1, 2, 0 })
      {
        for (int em = 0; em < 2; ++em)
        {
          if (em == 1 && (sem != 1 || view != 1))
          {
            continue; // one Wilhelms-Van Gelder case per scene
          }
          vs.Mapper->SetOpacitySemantics(sem);
          vs.Mapper->SetEmissionModel(em);
          vs.Mapper->SetRenderModeToCPUAccurate();
          win->Render();
          const Image cpu = FloatImage(vs.Mapper);
          const std::string label = std::string(scene.Name) + (view ? " / perspective" : " / ortho") +
            " / semantics " + std::to_string(sem) + (em ? " / WVG" : " / WM");
          double maxErr[4];
          for (int m = 0; m < 4; ++m)
          {
            vs.Mapper->SetRenderModeToOpenGLProjection();
            vs.Mapper->SetProjectionColorMethod(m);
            vs.Mapper->SetProjectionOpacityLookupToTexture(); // HIAC's texture (the default is analytic)
            win->Render();
            const Image proj = FloatImage(vs.Mapper);
            const Errors e = Compare(proj, cpu);
            maxErr[m] = e.Max;
            std::cout << label << " M" << m << ": covered " << e.Covered << ", coverage mismatch "
                      << e.CoverMismatch << ", max |error| " << e.Max * 255 << "/255, mean "
                      << e.Mean * 255 << "/255, triangles "
                      << vs.Mapper->GetNumberOfProjectedTriangles() << "\n";
            if (m == 3)
            {
              ck.Check(e.Covered > 300, label + ": the volume covers pixels");
              ck.Check(e.Max <= Tolerance, label + ": M3 within 2/255 of the CPU image");
            }
            if (m == 1 || m == 3)
            {
              // The analytic opacity lookup: the same image up to the
              // texture's error (1.2e-5 in opacity), so within 2/255 for M3.
              vs.Mapper->SetProjectionOpacityLookupToAnalytic();
              win->Render();
              const Image analytic = FloatImage(vs.Mapper);
              vs.Mapper->SetProjectionOpacityLookupToTexture();
              const Errors ea = Compare(analytic, cpu);
              const Errors et = Compare(analytic, proj);
              std::cout << label << " M" << m << " analytic lookup: max |error| " << ea.Max * 255
                        << "/255, max |analytic - texture| " << et.Max << "\n";
              ck.Check(et.Max <= 1e-4,
                label + ": analytic and texture lookups agree to 1e-4");
              ck.Check(m != 3 || ea.Max <= Tolerance,
                label + ": M3 with the analytic lookup within 2/255 of the CPU image");
            }
          }
          if (scene.ColorVariesAlongRays && em == 0)
          {
            ck.Check(maxErr[0] >= maxErr[1] && maxErr[1] >= maxErr[2] && maxErr[2] >= maxErr[3],
              label + ": error order M0 >= M1 >= M2 >= M3");
          }
          vs.Mapper->SetRenderModeToCPUAccurate();
        }
      }
    }
    ck.Check(vs.NoMessages(), std::string(scene.Name) + ": no messages");
    ren->RemoveAllViewProps();
  }
  return ck.Result();
}
