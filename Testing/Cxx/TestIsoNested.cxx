// Isosurfaces (issue 4): two nested semitransparent isosurfaces composite in
// the right order.
//
// s = x^2 + y^2 + z^2 on [-1,1]^3 (4^3 triquadratic hexahedra: exact), a
// non-absorbing volume, two unshaded surfaces (vtkVolumeProperty Shade off:
// ambient 1, diffuse 0) at radii 0.4 (red, opacity 0.35) and 0.8 (green,
// opacity 0.5). Orthographic view along -z: a ray at distance rho from the
// axis crosses, front to back, the outer sphere, the inner one (if
// rho < 0.4), the inner one again and the outer one, each with the edge-on
// opacity 1 - (1 - a)^(1 / |cos|), |cos| = sqrt(r^2 - rho^2) / r. The closed
// form composites these layers front to back in long double; every pixel
// with rho < 0.97 r_outer (away from the silhouette, where the edge-on cap
// applies) must match to 1e-12, in both orderings. Swapping the order of the
// surfaces (inner in front) would change the colour by up to ~0.2.
#include "hovTestMixed.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace hovTest;

namespace
{
constexpr int N = 48;
constexpr double Scale = 1.05;
struct Layer
{
  double R;
  double Rgb[3];
  double Opacity;
};
const Layer Inner = { 0.4, { 1, 0, 0 }, 0.35 };
const Layer Outer = { 0.8, { 0, 1, 0 }, 0.5 };

double Sphere(double x, double y, double z)
{
  return x * x + y * y + z * z;
}

/// Front-to-back composite of the layers a ray at distance rho meets.
void ClosedForm(double rho, long double out[4])
{
  out[0] = out[1] = out[2] = out[3] = 0.0L;
  auto over = [&](const Layer& l) {
    if (rho >= l.R)
    {
      return;
    }
    const long double c = std::sqrt((long double)l.R * l.R - (long double)rho * rho) / l.R;
    const long double a = 1.0L - std::pow(1.0L - (long double)l.Opacity, 1.0L / c);
    const long double t = 1.0L - out[3];
    for (int k = 0; k < 3; ++k)
    {
      out[k] += t * a * l.Rgb[k];
    }
    out[3] += t * a;
  };
  over(Outer);
  over(Inner);
  over(Inner);
  over(Outer);
}
}

int TestIsoNested(int, char*[])
{
  Checker check;
  MeshBuilder m;
  const double o[3] = { -1, -1, -1 };
  const double a[3][3] = { { 0.5, 0, 0 }, { 0, 0.5, 0 }, { 0, 0, 0.5 } };
  const std::vector<vtkIdType> ids = AddLattice(m, 4, 4, 4, o, a, Sphere);
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        AddCube(m, LatticeCube(ids, 4, 4, i, j, k), CubeSplit::TriQuadraticHexahedron, Sphere);
  for (bool perPixel : { false, true })
  {
    VolumeScene scene(m.Grid());
    scene.Tf.Color->AddRGBPoint(0.0, 1, 1, 1);
    scene.Tf.Opacity->AddPoint(0.0, 0.0);
    scene.Mapper->SetCellOrdering(perPixel ? 1 : 0);
    scene.Mapper->AddIsosurface(Outer.R * Outer.R, Outer.Rgb[0], Outer.Rgb[1], Outer.Rgb[2],
      Outer.Opacity);
    scene.Mapper->AddIsosurface(Inner.R * Inner.R, Inner.Rgb[0], Inner.Rgb[1], Inner.Rgb[2],
      Inner.Opacity);
    vtkNew<vtkCamera> cam;
    cam->ParallelProjectionOn();
    cam->SetPosition(0, 0, 5);
    cam->SetFocalPoint(0, 0, 0);
    cam->SetViewUp(0, 1, 0);
    cam->SetParallelScale(Scale);
    cam->SetClippingRange(1, 10);
    int status = 0;
    const Image img = RenderDouble(scene.Mapper, cam, scene.Volume, N, N, &status);
    double worst = 0.0, worstSwap = 0.0;
    int pixels = 0;
    for (int j = 0; j < N; ++j)
    {
      for (int i = 0; i < N; ++i)
      {
        const double x = (i + 0.5 - N / 2.0) * (2.0 * Scale / N);
        const double y = (j + 0.5 - N / 2.0) * (2.0 * Scale / N);
        const double rho = std::sqrt(x * x + y * y);
        if (rho >= 0.97 * Outer.R)
        {
          continue;
        }
        long double expected[4];
        ClosedForm(rho, expected);
        for (int c = 0; c < 4; ++c)
        {
          worst = std::max(worst, static_cast<double>(std::abs(img.At(i, j, c) - expected[c])));
        }
        if (rho < Inner.R)
        {
          // How much a wrong order would show: red and green swapped in depth.
          worstSwap = std::max(worstSwap, static_cast<double>(std::abs(expected[0] - expected[1])));
        }
        ++pixels;
      }
    }
    check.Check(status == 1 && scene.NoMessages() && pixels > 800 && worst < 1e-12,
      std::string(perPixel ? "per pixel" : "visibility order") + ": max error vs the closed form " +
        Fmt(worst) + " over " + std::to_string(pixels) + " pixels (|red - green| up to " +
        Fmt(worstSwap) + ")");
  }
  return check.Result();
}
