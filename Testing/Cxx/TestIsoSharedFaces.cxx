// Isosurfaces (issue 4, HIAC 5.1): an isovalue lying exactly on faces
// shared by two cells is drawn once.
//
// s = z on [0,1]^3 as 2^3 Kuhn-split cubes (48 linear tetrahedra; the nodes on
// z = 0.5 have s = 0.5 exactly) and as 2^3 hexahedra; one unshaded surface of
// opacity 0.3 at s = 0.5 (interior shared faces), s = 1 (the boundary face
// where the rays enter) or s = 0 (the boundary face where they leave);
// non-absorbing volume. Oblique orthographic view: |cos| between the view
// direction and the plane's normal is c = 1/|(0.3, 0.2, 1)|, so every pixel
// whose ray crosses the plane inside the block must have
//   alpha = 1 - 0.7^(1/c)   (one layer; two layers would be 1 - 0.7^(2/c)),
// and pixels whose ray misses the plane's square alpha = 0. Checked to 1e-12
// at every pixel farther than 1e-6 from the square's border, both orderings.
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
constexpr double Opacity = 0.3;
const double View[3] = { 0.3, 0.2, 1.0 };

double Height(double, double, double z)
{
  return z;
}

/// The plane z = level seen by pixel (i, j): where the ray crosses it (x, y).
void Crossing(vtkCamera* cam, int i, int j, double level, double& x, double& y)
{
  double p[3];
  hovTest::OrthoRayPlaneCrossing(cam, N, i, j, 2, level, p);
  x = p[0];
  y = p[1];
}
}

int TestIsoSharedFaces(int, char*[])
{
  Checker check;
  const double len = std::sqrt(View[0] * View[0] + View[1] * View[1] + View[2] * View[2]);
  const double expected = 1.0 - std::pow(1.0 - Opacity, len);
  const double doubled = 1.0 - std::pow(1.0 - Opacity, 2.0 * len);
  for (int mesh = 0; mesh < 2; ++mesh)
  {
    MeshBuilder m;
    if (mesh == 0)
    {
      const double o[3] = { 0, 0, 0 }, size[3] = { 1, 1, 1 };
      m.AddTetBlock(2, 2, 2, o, size, Height);
    }
    else
    {
      const double o[3] = { 0, 0, 0 };
      const double a[3][3] = { { 0.5, 0, 0 }, { 0, 0.5, 0 }, { 0, 0, 0.5 } };
      const std::vector<vtkIdType> ids = AddLattice(m, 2, 2, 2, o, a, Height);
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i)
            AddCube(m, LatticeCube(ids, 2, 2, i, j, k), CubeSplit::Hexahedron, Height);
    }
    for (double level : { 0.5, 1.0, 0.0 })
    {
      for (bool perPixel : { false, true })
      {
        VolumeScene scene(m.Grid());
        scene.Tf.Color->AddRGBPoint(0.0, 1, 1, 1);
        scene.Tf.Opacity->AddPoint(0.0, 0.0);
        scene.Mapper->SetCellOrdering(perPixel ? 1 : 0);
        scene.Mapper->AddIsosurface(level, 1, 1, 1, Opacity);
        vtkNew<vtkCamera> cam;
        cam->ParallelProjectionOn();
        cam->SetFocalPoint(0.5, 0.5, 0.5);
        cam->SetPosition(0.5 + 4 * View[0], 0.5 + 4 * View[1], 0.5 + 4 * View[2]);
        cam->SetViewUp(0, 1, 0);
        cam->SetParallelScale(0.9);
        cam->SetClippingRange(1, 10);
        int status = 0;
        const Image img = RenderDouble(scene.Mapper, cam, scene.Volume, N, N, &status);
        double worst = 0.0;
        int inside = 0, twice = 0;
        for (int j = 0; j < N; ++j)
        {
          for (int i = 0; i < N; ++i)
          {
            double x, y;
            Crossing(cam, i, j, level, x, y);
            const double margin = std::min(std::min(x, 1 - x), std::min(y, 1 - y));
            if (std::abs(margin) < 1e-6)
            {
              continue;
            }
            const double want = margin > 0 ? expected : 0.0;
            const double a = img.At(i, j, 3);
            worst = std::max(worst, std::abs(a - want));
            inside += margin > 0;
            twice += std::abs(a - doubled) < 1e-9;
          }
        }
        check.Check(status == 1 && scene.NoMessages() && inside > 400 && worst < 1e-12 && twice == 0,
          std::string(mesh == 0 ? "tetrahedra" : "hexahedra") + ", s = " + Fmt(level) + ", " +
            (perPixel ? "per pixel" : "visibility order") + ": alpha " + Fmt(expected) +
            " expected (doubled: " + Fmt(doubled) + "), max error " + Fmt(worst) + " over " +
            std::to_string(inside) + " pixels, doubled at " + std::to_string(twice));
      }
    }
  }
  return check.Result();
}
