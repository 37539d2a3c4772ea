// Isosurfaces (issue 4, HIAC 5.1-5.2): a sphere-like isosurface inside a
// quadratic field is smooth and correctly occluded.
//
// Field s = x^2 + y^2 + z^2 on [-1,1]^3 as 4^3 cubes, each a triquadratic
// hexahedron or split into 6 quadratic tetrahedra (both represent s exactly,
// so the isosurface s = R^2 is exactly the sphere of radius R). The volume
// does not absorb; the surface is opaque (opacity 1), white, Phong-shaded
// with the property's Shade on, Ambient 0, Diffuse 1, Specular 0 and the
// headlight of RenderImage (directional, along the view; the one warning
// allowed says that the volume itself is not shaded). Orthographic view
// along -z: at a pixel (x, y) inside the sphere's disc the closed form is
//   R = G = B = |n . l| = sqrt(R^2 - x^2 - y^2) / R,  A = 1
// (the sphere's analytic normal). Measured: the largest error over every
// surface pixel away from the silhouette (x^2 + y^2 < 0.95 R^2), for the
// quadratic cells (smooth) and for the same field on linear tetrahedra of a
// 4x finer lattice (flat facets: constant normal per cell) -- the smooth error
// must be below 1e-9 and the facets' error above 100 times it.
//
// Occlusion: a slab z in [1.2, 1.5] of linear tetrahedra in front of the
// block, scalar 10, black, extinction 2 per unit length (RAW_EXTINCTION):
// every surface pixel is the closed form times exp(-2 * 0.3) (the slab
// neither emits nor lets the sphere through unattenuated), both orderings.
#include "hovTestMixed.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace hovTest;

namespace
{
constexpr int N = 64;
constexpr double Scale = 1.1, Radius = 0.6;
/// View not shifted: the pixels i == j have rays exactly in the diagonal
/// faces x = y of the quadratic tetrahedra, given to exactly one of the two
/// cells by the rays' symbolic perturbation (hovRayCell.h; TestMixedInFace).
constexpr double Shift = 0.0;
constexpr double SlabValue = 10.0, SlabTau = 2.0, SlabZ0 = 1.2, SlabZ1 = 1.5;

double Sphere(double x, double y, double z)
{
  return x * x + y * y + z * z;
}

MeshBuilder Block(CubeSplit split, bool slab, int n = 4)
{
  MeshBuilder m;
  const double o[3] = { -1, -1, -1 }, h = 2.0 / n;
  const double a[3][3] = { { h, 0, 0 }, { 0, h, 0 }, { 0, 0, h } };
  const std::vector<vtkIdType> ids = AddLattice(m, n, n, n, o, a, Sphere);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        AddCube(m, LatticeCube(ids, n, n, i, j, k), split, Sphere);
  if (slab)
  {
    const double so[3] = { -1.2, -1.2, SlabZ0 }, size[3] = { 2.4, 2.4, SlabZ1 - SlabZ0 };
    m.AddTetBlock(2, 2, 1, so, size, [](double, double, double) { return SlabValue; });
  }
  return m;
}

void AlongZ(vtkCamera* cam)
{
  cam->ParallelProjectionOn();
  cam->SetPosition(Shift, 0, 5);
  cam->SetFocalPoint(Shift, 0, 0);
  cam->SetViewUp(0, 1, 0);
  cam->SetParallelScale(Scale);
  cam->SetClippingRange(1, 10);
}

double PixelCoord(int i)
{
  return (i + 0.5 - N / 2.0) * (2.0 * Scale / N);
}

/// Largest |R - expected| over the surface pixels, with the slab's attenuation @p atten.
double SurfaceError(const Image& img, double atten, int& pixels)
{
  double worst = 0.0;
  pixels = 0;
  for (int j = 0; j < N; ++j)
  {
    for (int i = 0; i < N; ++i)
    {
      const double x = PixelCoord(i) + Shift, y = PixelCoord(j), r2 = x * x + y * y;
      if (r2 >= 0.95 * Radius * Radius)
      {
        continue;
      }
      const double expected = atten * std::sqrt(Radius * Radius - r2) / Radius;
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(img.At(i, j, c) - expected));
      }
      worst = std::max(worst, std::abs(img.At(i, j, 3) - 1.0));
      ++pixels;
    }
  }
  return worst;
}

double RenderError(CubeSplit split, bool slab, bool perPixel, int& pixels, bool& clean, int n = 4)
{
  MeshBuilder m = Block(split, slab, n);
  VolumeScene scene(m.Grid());
  scene.Tf.Color->AddRGBPoint(0.0, 1, 1, 1);
  scene.Tf.Color->AddRGBPoint(3.0, 1, 1, 1);
  scene.Tf.Color->AddRGBPoint(SlabValue, 0, 0, 0);
  scene.Tf.Opacity->AddPoint(0.0, 0.0);
  scene.Tf.Opacity->AddPoint(3.0, 0.0);
  scene.Tf.Opacity->AddPoint(SlabValue, SlabTau);
  scene.Tf.Property->ShadeOn();
  scene.Tf.Property->SetAmbient(0.0);
  scene.Tf.Property->SetDiffuse(1.0);
  scene.Tf.Property->SetSpecular(0.0);
  scene.Mapper->SetOpacitySemanticsToRawExtinction();
  scene.Mapper->SetCellOrdering(perPixel ? 1 : 0);
  scene.Mapper->AddIsosurface(Radius * Radius, 1, 1, 1, 1.0);
  vtkNew<vtkCamera> cam;
  AlongZ(cam);
  int status = 0;
  const Image img = RenderDouble(scene.Mapper, cam, scene.Volume, N, N, &status);
  // The one expected message: the volume itself is not shaded where there are
  // isosurfaces (hov::PropertyAudit; the volume here is black anyway).
  clean = status == 1 && scene.NoMessagesBut(IsoShadeWarning) &&
    scene.Mapper->GetWitnessViolations() == 0;
  if (!clean)
  {
    std::cout << "  status " << status << ", witness " << scene.Mapper->GetWitnessViolations()
              << ", error '" << Msg(scene.Observer->GetErrorMessage()) << "', warning '"
              << Msg(scene.Observer->GetWarningMessage()) << "'\n";
  }
  return SurfaceError(img, slab ? std::exp(-SlabTau * (SlabZ1 - SlabZ0)) : 1.0, pixels);
}
}

int TestIsoSphere(int, char*[])
{
  Checker check;
  int pixels = 0;
  bool clean = false;
  // The same field on linear tetrahedra of a 4x finer lattice (16^3 cubes):
  // a polyhedral surface with flat facets.
  const double facets = RenderError(CubeSplit::Tetras, false, false, pixels, clean, 16);
  std::cout << "linear tetrahedra, 16^3 Kuhn cubes (flat facets): max |I - n.l| = " << facets
            << " over " << pixels << " pixels\n";
  for (CubeSplit split : { CubeSplit::TriQuadraticHexahedron, CubeSplit::QuadraticTetras })
  {
    const double smooth = RenderError(split, false, false, pixels, clean);
    check.Check(clean && pixels > 500 && smooth < 1e-9 && facets > 100 * smooth,
      std::string(CubeSplitName(split)) + ": max |I - n.l| = " + Fmt(smooth) + " over " +
        std::to_string(pixels) + " pixels (facets " + Fmt(facets) + ")");
    for (bool perPixel : { false, true })
    {
      const double occluded = RenderError(split, true, perPixel, pixels, clean);
      check.Check(clean && pixels > 500 && occluded < 1e-9,
        std::string(CubeSplitName(split)) + " behind the slab (" +
          (perPixel ? "per pixel" : "visibility order") + "): max error vs exp(-tau L) n.l = " +
          Fmt(occluded));
    }
  }
  return check.Result();
}
