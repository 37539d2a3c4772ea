// Isosurfaces (issue 4): Phong shading with the renderer's lights (the
// on-screen Render path, not RenderImage's headlight).
//
// The sphere s = x^2 + y^2 + z^2 = R^2 in 4^3 triquadratic hexahedra (exact),
// opaque white surface, non-absorbing volume, orthographic view along -z,
// rendered in an offscreen window; the mapper's float image is checked at
// every surface pixel away from the silhouette against the closed form of
// hov::ShadePhong with the analytic normal n:
//  1. one scene light, directional from (1, 2, 3) (position - focal point),
//     colour (1, 0.5, 0.25), intensity 0.8; property Ambient 0.1, Diffuse 0.7,
//     Specular 0 (Shade on):  C = 0.1 + 0.8 * 0.7 |n.l| colour
//  2. the same plus Specular 0.3, power 12, and a second, positional light
//     at (0, 0, 3) with colour 1 and quadratic attenuation (0, 0, 1), Blinn
//     half vector with the view v = (0, 0, 1):
//     C += sum_i f_i I_i ks |n.h_i|^p (white highlights), f = 1/d^2;
//  3. Shade off: C = the surface colour (unshaded) whatever the lights.
// Tolerance 1e-6 (the float image).
#include "hovTestMixed.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace hovTest;

namespace
{
constexpr int N = 48;
constexpr double Scale = 1.1, Radius = 0.6, Shift = 1.0 / 8192.0;

double Sphere(double x, double y, double z)
{
  return x * x + y * y + z * z;
}

void Normalize(double v[3])
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int k = 0; k < 3; ++k)
    v[k] /= n;
}

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
}

int TestIsoLights(int, char*[])
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
  const double dirFrom[3] = { 1, 2, 3 }, colour[3] = { 1, 0.5, 0.25 };
  const double spotPos[3] = { 0, 0, 3 };
  for (int variant = 0; variant < 3; ++variant)
  {
    VolumeScene scene(m.Grid());
    scene.Tf.Color->AddRGBPoint(0.0, 1, 1, 1);
    scene.Tf.Opacity->AddPoint(0.0, 0.0);
    scene.Mapper->AddIsosurface(Radius * Radius, 1, 1, 1, 1.0);
    scene.Tf.Property->SetShade(variant < 2);
    scene.Tf.Property->SetAmbient(0.1);
    scene.Tf.Property->SetDiffuse(0.7);
    scene.Tf.Property->SetSpecular(variant == 1 ? 0.3 : 0.0);
    scene.Tf.Property->SetSpecularPower(12);
    vtkNew<vtkCamera> cam;
    cam->ParallelProjectionOn();
    cam->SetPosition(Shift, 0, 5);
    cam->SetFocalPoint(Shift, 0, 0);
    cam->SetViewUp(0, 1, 0);
    cam->SetParallelScale(Scale);
    auto ren = BlackRenderer(cam);
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPosition(dirFrom[0], dirFrom[1], dirFrom[2]);
    light->SetFocalPoint(0, 0, 0);
    light->SetColor(colour[0], colour[1], colour[2]);
    light->SetIntensity(0.8);
    ren->AddLight(light);
    vtkNew<vtkLight> spot;
    spot->SetLightTypeToSceneLight();
    spot->PositionalOn();
    spot->SetPosition(spotPos[0], spotPos[1], spotPos[2]);
    spot->SetFocalPoint(0, 0, 0);
    spot->SetConeAngle(90); // no cone
    spot->SetAttenuationValues(0, 0, 1);
    spot->SetSwitch(variant == 1);
    ren->AddLight(spot);
    ren->AddVolume(scene.Volume);
    auto win = OffscreenWindow(ren, N, N);
    win->Render();
    const Image img = FloatImage(scene.Mapper);
    double l[3] = { dirFrom[0], dirFrom[1], dirFrom[2] };
    Normalize(l);
    double worst = 0.0;
    int pixels = 0;
    for (int j = 0; j < N && img.W == N; ++j)
    {
      for (int i = 0; i < N; ++i)
      {
        const double x = (i + 0.5 - N / 2.0) * (2.0 * Scale / N) + Shift;
        const double y = (j + 0.5 - N / 2.0) * (2.0 * Scale / N);
        const double r2 = x * x + y * y;
        if (r2 >= 0.95 * Radius * Radius)
          continue;
        const double p[3] = { x, y, std::sqrt(Radius * Radius - r2) };
        const double n[3] = { p[0] / Radius, p[1] / Radius, p[2] / Radius };
        double expected[3] = { 1, 1, 1 };
        if (variant < 2)
        {
          for (int c = 0; c < 3; ++c)
            expected[c] = 0.1 + 0.8 * 0.7 * std::abs(Dot(n, l)) * colour[c];
        }
        if (variant == 1)
        {
          const double v[3] = { 0, 0, 1 };
          double h1[3] = { l[0] + v[0], l[1] + v[1], l[2] + v[2] };
          Normalize(h1);
          double ls[3] = { spotPos[0] - p[0], spotPos[1] - p[1], spotPos[2] - p[2] };
          const double d2 = Dot(ls, ls);
          Normalize(ls);
          double h2[3] = { ls[0] + v[0], ls[1] + v[1], ls[2] + v[2] };
          Normalize(h2);
          for (int c = 0; c < 3; ++c)
          {
            expected[c] += 0.8 * 0.3 * std::pow(std::abs(Dot(n, h1)), 12) * colour[c];
            expected[c] += (1.0 / d2) * (0.7 * std::abs(Dot(n, ls)) +
                                          0.3 * std::pow(std::abs(Dot(n, h2)), 12));
          }
        }
        for (int c = 0; c < 3; ++c)
          worst = std::max(worst, std::abs(img.At(i, j, c) - std::min(expected[c], 1.0)));
        ++pixels;
      }
    }
    const char* names[3] = { "directional scene light, diffuse",
      "directional + positional light, specular", "Shade off (unshaded)" };
    // Shade on with isosurfaces: the one warning that the volume is unshaded.
    check.Check(scene.NoMessagesBut(IsoShadeWarning) && pixels > 500 && worst < 1e-6,
      std::string(names[variant]) + ": max error vs the closed form " + Fmt(worst) + " over " +
        std::to_string(pixels) + " pixels");
  }
  return check.Result();
}
