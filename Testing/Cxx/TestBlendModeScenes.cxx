// The blend modes MAXIMUM_INTENSITY, MINIMUM_INTENSITY and AVERAGE_INTENSITY
// in every render mode against an independent per-ray reference, on analytic
// scenes whose field along every pixel ray is a known polynomial of t:
//  - "tet cube": [-1,1]^3 as 3x3x3 Kuhn cubes of linear tetrahedra, affine
//    field (CPU_ACCURATE, OPENGL_PROJECTION, RAY_CAST);
//  - "quadratic tetra": one 10-node tetrahedron carrying the quadratic
//    f = 1.3 - 1.6 |x - c|^2 (interior maximum at c; the polynomial path);
//  - "quadratic hex": [-1,1]^3 as one triquadratic hexahedron (CPU modes) and
//    as one order-2 Lagrange hexahedron (RAY_CAST) with a quadratic field.
// Reference (nothing of the module): the pixel ray from the camera
// parameters (hovTestRef::PixelRay), its exact clip against the box or the
// tetrahedron, the field along it as the quadratic through three exact
// samples of the analytic function; extremum = the ends and the vertex;
// average = 8-point Gauss-Legendre on every piece between the crossings of
// the opacity nodes and of AverageIPScalarRange (the integrand a(s) sn(s) is a
// polynomial of degree <= 4 there: exact), transfer functions read through
// vtkPiecewiseFunction::GetValue / vtkColorTransferFunction::GetColor.
// Pixel as vtkGPUVolumeRayCastMapper defines it (hovBlendModes.h):
// MIP/MinIP (c(s*) a(s*), a(s*)) with the raw opacity; average (v, v, v, 1).
// Expected: every channel of every pixel within BlendTolerance; max and mean
// error per channel printed per scene, mode and blend mode.
#include "hovTestReference.h"
#include "hovTestBlendScenes.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkHigherOrderHexahedron.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using hovTestRef::Real;
/// Float image against the exact pixel: float rounding (6e-8) plus the
/// double-precision kernels; measured max 3.0e-8 in every scene and mode.
constexpr double BlendTolerance = 1e-6;
constexpr int W = 40, H = 36;
const double AverageRange[2] = { 0.15, 1.1 };

using Field = std::function<double(double, double, double)>;

struct Scene
{
  std::string Name;
  vtkSmartPointer<vtkUnstructuredGrid> Grid;     ///< CPU modes
  vtkSmartPointer<vtkUnstructuredGrid> RayGrid;  ///< RAY_CAST (null: Grid)
  Field F;
  bool Tetra = false; ///< clip against Tet, else the box [-1,1]^3
  double Tet[4][3];
};

double Affine(double x, double y, double z)
{
  return 0.6 + 0.3 * x - 0.2 * y + 0.25 * z;
}

Scene TetCube()
{
  Scene s;
  s.Name = "tet cube";
  hovTest::MeshBuilder m;
  const double o[3] = { -1, -1, -1 }, size[3] = { 2, 2, 2 };
  m.AddTetBlock(3, 3, 3, o, size, Affine);
  s.Grid = m.Grid();
  s.F = Affine;
  return s;
}

Scene QuadraticTetra()
{
  Scene s;
  s.Name = "quadratic tetra";
  const double p[4][3] = { { -1, -1, -1 }, { 1.2, -1, -0.9 }, { -1, 1.1, -1 }, { -0.8, -1, 1.2 } };
  std::copy(&p[0][0], &p[0][0] + 12, &s.Tet[0][0]);
  s.Tetra = true;
  double c[3] = { 0, 0, 0 };
  for (int v = 0; v < 4; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      c[k] += 0.25 * p[v][k];
    }
  }
  s.F = [c](double x, double y, double z) {
    return 1.3 - 1.6 * ((x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]) + (z - c[2]) * (z - c[2]));
  };
  hovTest::MeshBuilder m;
  const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  std::vector<vtkIdType> ids;
  for (int v = 0; v < 4; ++v)
  {
    ids.push_back(m.AddPoint(p[v][0], p[v][1], p[v][2], s.F(p[v][0], p[v][1], p[v][2])));
  }
  for (const auto& e : edges)
  {
    double x[3];
    for (int k = 0; k < 3; ++k)
    {
      x[k] = 0.5 * (p[e[0]][k] + p[e[1]][k]);
    }
    ids.push_back(m.AddPoint(x[0], x[1], x[2], s.F(x[0], x[1], x[2])));
  }
  m.AddCell(VTK_QUADRATIC_TETRA, ids);
  s.Grid = m.Grid();
  return s;
}

Scene QuadraticHex()
{
  Scene s;
  s.Name = "quadratic hex";
  s.F = [](double x, double y, double z) {
    return 1.2 - 0.45 * (x * x + y * y + z * z) + 0.2 * x - 0.1 * y * z;
  };
  // The Lagrange hexahedron: node of (i, j, k) at (-1 + i, -1 + j, -1 + k).
  hovTest::MeshBuilder lagrange;
  std::vector<vtkIdType> ids(27);
  const int order[3] = { 2, 2, 2 };
  std::vector<std::array<double, 3>> x(27);
  for (int k = 0; k < 3; ++k)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int i = 0; i < 3; ++i)
      {
        x[vtkHigherOrderHexahedron::PointIndexFromIJK(i, j, k, order)] = { -1.0 + i, -1.0 + j,
          -1.0 + k };
      }
    }
  }
  for (int n = 0; n < 27; ++n)
  {
    ids[n] = lagrange.AddPoint(x[n][0], x[n][1], x[n][2], s.F(x[n][0], x[n][1], x[n][2]));
  }
  lagrange.AddCell(VTK_LAGRANGE_HEXAHEDRON, ids);
  s.RayGrid = lagrange.Grid();
  s.Grid = hovTest::TriquadraticHex(s.F);
  return s;
}

/// The exact pixel of one ray (see the file doc).
struct Reference
{
  vtkPiecewiseFunction* Opacity;
  vtkColorTransferFunction* Color;
  double Range[2]; ///< data scalar range
  int Blend;
  double Lo = -1e38, Hi = 1e38;

  Real A(Real s) const
  {
    return std::min(1.0, std::max(0.0, this->Opacity->GetValue(static_cast<double>(s))));
  }

  void Pixel(const Scene& scene, const hovTestRef::Ray& ray, double out[4]) const
  {
    std::fill(out, out + 4, 0.0);
    Real t0, t1;
    const double box[6] = { -1, 1, -1, 1, -1, 1 };
    const bool hit = scene.Tetra ? hovTestRef::IntersectTetra(ray, scene.Tet, t0, t1)
                                 : hovTestRef::IntersectBox(ray, box, t0, t1);
    if (!hit || !(t1 > t0))
    {
      return;
    }
    auto f = [&](Real t) {
      const hovTestRef::Vec3 x = ray.At(t);
      return static_cast<Real>(scene.F(static_cast<double>(x[0]), static_cast<double>(x[1]),
        static_cast<double>(x[2])));
    };
    // s(t0 + u) = c0 + c1 u + c2 u^2 through three samples.
    const Real L = t1 - t0, fa = f(t0), fm = f(t0 + L / 2), fb = f(t1);
    const Real c0 = fa, c2 = 2 * (fa - 2 * fm + fb) / (L * L), c1 = (fb - fa) / L - c2 * L;
    auto s = [&](Real u) { return c0 + u * (c1 + u * c2); };
    if (this->Blend != 3)
    {
      const int sign = this->Blend == 1 ? 1 : -1;
      Real best = sign * fa > sign * fb ? fa : fb;
      if (c2 != 0)
      {
        const Real u = -c1 / (2 * c2);
        if (u > 0 && u < L && sign * s(u) > sign * best)
        {
          best = s(u);
        }
      }
      const double a = static_cast<double>(this->A(best));
      double rgb[3];
      this->Color->GetColor(static_cast<double>(best), rgb);
      for (int k = 0; k < 3; ++k)
      {
        out[k] = std::min(1.0, std::max(0.0, rgb[k])) * a;
      }
      out[3] = a;
      return;
    }
    // Average: pieces between the crossings of the nodes and the range limits.
    std::vector<Real> cuts{ 0, L }, levels{ this->Lo, this->Hi };
    for (int n = 0; n < this->Opacity->GetSize(); ++n)
    {
      double node[4];
      this->Opacity->GetNodeValue(n, node);
      levels.push_back(node[0]);
    }
    for (Real v : levels)
    {
      // c2 u^2 + c1 u + (c0 - v) = 0
      if (std::abs(c2) < 1e-300L)
      {
        if (c1 != 0)
        {
          cuts.push_back((v - c0) / c1);
        }
        continue;
      }
      // The cancellation-free pair of roots (c2 may be rounding noise).
      const Real disc = c1 * c1 - 4 * c2 * (c0 - v);
      if (disc >= 0)
      {
        const Real q = -(c1 + (c1 < 0 ? -1 : 1) * std::sqrt(disc)) / 2;
        if (q != 0)
        {
          cuts.push_back(q / c2);
          cuts.push_back((c0 - v) / q);
        }
      }
    }
    std::sort(cuts.begin(), cuts.end());
    static const Real gx[8] = { -0.9602898564975362316835609L, -0.7966664774136267395915539L,
      -0.5255324099163289858177390L, -0.1834346424956498049394761L, 0.1834346424956498049394761L,
      0.5255324099163289858177390L, 0.7966664774136267395915539L, 0.9602898564975362316835609L };
    static const Real gw[8] = { 0.1012285362903762591525314L, 0.2223810344533744705443560L,
      0.3137066458778872873379622L, 0.3626837833783619829651504L, 0.3626837833783619829651504L,
      0.3137066458778872873379622L, 0.2223810344533744705443560L, 0.1012285362903762591525314L };
    Real integral = 0, length = 0;
    const Real r0 = this->Range[0], r1 = this->Range[1];
    for (size_t k = 0; k + 1 < cuts.size(); ++k)
    {
      const Real a = std::max<Real>(0, cuts[k]), b = std::min(L, cuts[k + 1]);
      if (!(b > a))
      {
        continue;
      }
      const Real mid = s((a + b) / 2);
      if (mid < this->Lo || mid > this->Hi)
      {
        continue;
      }
      length += b - a;
      for (int q = 0; q < 8; ++q)
      {
        const Real u = (a + b) / 2 + (b - a) / 2 * gx[q];
        const Real v = s(u);
        integral += (b - a) / 2 * gw[q] * this->A(v) * (r1 > r0 ? (v - r0) / (r1 - r0) : 0);
      }
    }
    if (length > 0)
    {
      const double v = std::min(1.0, std::max(0.0, static_cast<double>(integral / length)));
      out[0] = out[1] = out[2] = v;
      out[3] = 1.0;
    }
  }
};

const char* BlendName(int b)
{
  return b == 1 ? "MIP" : b == 2 ? "MinIP" : "average";
}
}

int TestBlendModeScenes(int, char*[])
{
  hovTest::Checker check;
  vtkNew<vtkCamera> cam;
  hovTest::BlendCamera(cam);
  const hovTestRef::CameraSpec spec = hovTestRef::ReadCamera(cam);
  std::vector<hovTestRef::Ray> rays(static_cast<size_t>(W) * H);
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      rays[static_cast<size_t>(j) * W + i] = hovTestRef::PixelRay(spec, i, j, W, H);
    }
  }
  for (const Scene& scene : { TetCube(), QuadraticTetra(), QuadraticHex() })
  {
    for (int mode = 0; mode < 3; ++mode)
    {
      vtkUnstructuredGrid* grid = mode == 2 && scene.RayGrid ? scene.RayGrid : scene.Grid;
      hovTest::VolumeScene vs(grid);
      hovTest::BlendTF(vs.Tf);
      vtkHighOrderVolumeMapper* mapper = vs.Mapper;
      mapper->SetRenderMode(mode);
      mapper->SetAverageIPScalarRange(AverageRange[0], AverageRange[1]);
      vtkSmartPointer<vtkRenderer> ren;
      vtkSmartPointer<vtkRenderWindow> win;
      if (mode == 1)
      {
        ren = hovTest::BlackRenderer(cam);
        ren->AddVolume(vs.Volume);
        win = hovTest::OffscreenWindow(ren, W, H, 0);
      }
      Reference ref{ vs.Tf.Opacity, vs.Tf.Color, { 0, 0 }, 1 };
      grid->GetPointData()->GetScalars()->GetRange(ref.Range);
      ref.Lo = AverageRange[0];
      ref.Hi = AverageRange[1];
      for (int blend = 1; blend <= 3; ++blend)
      {
        mapper->SetBlendMode(blend);
        ref.Blend = blend;
        hovTest::Image img;
        if (mode == 1)
        {
          win->Render();
          img = hovTest::FloatImage(mapper);
        }
        else
        {
          img = hovTest::Render(mapper, cam, vs.Volume, W, H);
        }
        const std::string what =
          scene.Name + ", " + hovTest::ModeName(mode) + ", " + BlendName(blend);
        if (!check.Check(img.W == W && img.H == H, what + ": image of the right size"))
        {
          continue;
        }
        double maxErr[4] = { 0, 0, 0, 0 }, sumErr[4] = { 0, 0, 0, 0 };
        size_t covered = 0;
        for (int j = 0; j < H; ++j)
        {
          for (int i = 0; i < W; ++i)
          {
            double px[4];
            ref.Pixel(scene, rays[static_cast<size_t>(j) * W + i], px);
            covered += px[3] > 0 ? 1 : 0;
            for (int c = 0; c < 4; ++c)
            {
              const double e = std::abs(img.At(i, j, c) - px[c]);
              maxErr[c] = std::max(maxErr[c], std::isfinite(e) ? e : 1e300);
              sumErr[c] += e;
            }
          }
        }
        std::cout << "[measured] " << what << ": covered " << covered << " pixels; max error";
        for (double e : maxErr)
        {
          std::cout << " " << hovTest::Fmt(e);
        }
        std::cout << "; mean";
        for (double e : sumErr)
        {
          std::cout << " " << hovTest::Fmt(e / (W * H));
        }
        std::cout << "\n";
        check.Check(covered > static_cast<size_t>(W * H / 10), what + ": the scene covers pixels");
        check.Check(*std::max_element(maxErr, maxErr + 4) <= BlendTolerance,
          what + ": every channel within " + hovTest::Fmt(BlendTolerance));
        if (mode == 2)
        {
          check.Check(hovTest::MaxRayCastError(mapper) <= 1e-9, what + ": RAY_CAST error bound " +
              hovTest::Fmt(hovTest::MaxRayCastError(mapper)) + " <= 1e-9");
        }
      }
      check.Check(vs.NoMessages(), scene.Name + ", " + hovTest::ModeName(mode) + ": no message");
    }
  }
  return check.Result();
}
