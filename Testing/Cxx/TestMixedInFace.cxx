// Pixel rays lying EXACTLY in shared face planes (issue 4: no cracks, no
// double counting). The unit cube as 2x2x2 cubes of side 1/2: Kuhn-split
// quadratic tetrahedra (general path), Kuhn-split linear tetrahedra (fast
// path), hexahedra, wedges (split along the vertical diagonal plane) and
// pyramids (apex at the cube centre: faces in x = y and x + y = 1 of the
// cube), all with a CONSTANT field. Orthographic
// axis-aligned views with a square 64-pixel image and parallel scale 1
// (AxisOrthoCamera): pixel centres are (i + 1/2)/32 - 1/2, dyadic, so the
// pixels with i - j = 16 (a - b) lie exactly in the diagonal faces x - y =
// (a - b)/2 of cube (a, b) that contain the view direction (and likewise for
// the view along -x and the planes y = z). Every pixel must equal the closed
// form of the box, alpha = 1 - exp(-tau L), rgb = c alpha, L = 1 inside and 0
// outside (no pixel centre lies on the box's boundary), to 1e-12, with
// per-pixel witness 0: a ray given to both cells sharing such a face counts
// its length twice, a ray given to neither leaves a crack.
#include "hovTestMixed.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"

#include <cmath>
#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
constexpr int N = 64;
constexpr double Tolerance = 1e-12;
const double Colour[3] = { 0.9, 0.6, 0.3 };
constexpr double Opacity = 0.6, Unit = 1.5; // tau = 0.4

double Constant(double, double, double)
{
  return 1.0;
}

MeshBuilder Block(bool allQuadratic)
{
  MeshBuilder m;
  const double o[3] = { 0, 0, 0 };
  const double a[3][3] = { { 0.5, 0, 0 }, { 0, 0.5, 0 }, { 0, 0, 0.5 } };
  const std::vector<vtkIdType> ids = AddLattice(m, 2, 2, 2, o, a, Constant);
  const CubeSplit q = CubeSplit::QuadraticTetras;
  const CubeSplit mixed[8] = { q, q, CubeSplit::Tetras, CubeSplit::Hexahedron, CubeSplit::Tetras,
    CubeSplit::Wedges, CubeSplit::Pyramids, q };
  for (int c = 0; c < 8; ++c)
  {
    AddCube(
      m, LatticeCube(ids, 2, 2, c % 2, (c / 2) % 2, c / 4), allQuadratic ? q : mixed[c], Constant);
  }
  return m;
}
} // namespace

int TestMixedInFace(int, char*[])
{
  Checker ck;
  const double tau = Opacity / Unit;
  const double alphaIn = -std::expm1(-tau * 1.0);
  for (int mesh = 0; mesh < 2; ++mesh)
  {
    const std::string meshName = mesh == 0 ? "Kuhn quadratic tetrahedra"
                                           : "quadratic/linear tetrahedra, hex, wedges, pyramids";
    VolumeScene scene(Block(mesh == 0).Grid());
    ConstantTF(scene.Tf, Colour, Opacity, Unit);
    scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
    for (int view = 0; view < 2; ++view)
    {
      vtkNew<vtkCamera> cam;
      AxisOrthoCamera(cam, 1.0); // along -z: rays in the planes x - y = const
      if (view == 1)
      {
        cam->SetPosition(5.0, 0.5,
          0.5); // along -x: rays in the planes y - z = const
        cam->SetViewUp(0, 0, 1);
      }
      for (int order :
        { vtkHighOrderVolumeMapper::VISIBILITY_SORT, vtkHighOrderVolumeMapper::PER_PIXEL_SORT })
      {
        scene.Mapper->SetCellOrdering(order);
        scene.Observer->Clear();
        int status = 0;
        const Image img = RenderDouble(scene.Mapper, cam, scene.Volume, N, N, &status);
        const std::string label = meshName + (view ? ", along -x, " : ", along -z, ") +
          (order ? "PER_PIXEL_SORT" : "VISIBILITY_SORT");
        double maxErr = 0.0;
        int covered = 0, inPlane = 0, bad = 0, badInPlane = 0;
        for (int j = 0; j < N && img.W == N; ++j)
        {
          for (int i = 0; i < N; ++i)
          {
            const double u = OrthoPixelCoord(i, N), v = OrthoPixelCoord(j, N);
            const bool inside = u > 0.0 && u < 1.0 && v > 0.0 && v < 1.0;
            // In a diagonal plane of a cube (a, b): u - v (Kuhn, wedges, pyramids) or
            // u + v (pyramids) a multiple of 1/2.
            const bool diagonal = inside && ((i - j) % 16 == 0 || (i + j + 1) % 16 == 0);
            const double alpha = inside ? alphaIn : 0.0;
            covered += inside;
            inPlane += diagonal;
            double err = std::abs(img.At(i, j, 3) - alpha);
            for (int c = 0; c < 3; ++c)
            {
              err = std::max(err, std::abs(img.At(i, j, c) - Colour[c] * alpha));
            }
            if (!(err <= Tolerance))
            {
              badInPlane += diagonal;
              if (bad++ < 3)
              {
                std::cout << "  pixel (" << i << "," << j << ")" << (diagonal ? " in a face" : "")
                          << ": alpha " << img.At(i, j, 3) << " expected " << alpha << "\n";
              }
            }
            maxErr = std::max(maxErr, err);
          }
        }
        const vtkIdType witness = scene.Mapper->GetWitnessViolations();
        std::cout << "== " << label << ": covered " << covered << " pixels, " << inPlane
                  << " of them in a face plane; bad " << bad << " (" << badInPlane
                  << " in a face plane), max error " << Fmt(maxErr) << ", witness " << witness
                  << "\n";
        ck.Check(status == 1 && scene.NoMessages(),
          label + ": renders without error or warning ('" +
            Msg(scene.Observer->GetWarningMessage()) + "')");
        ck.Check(img.W == N && covered == N * N / 4 && inPlane >= 40,
          label +
            ": the box covers the central quarter, with pixel "
            "rays in face planes");
        ck.Check(bad == 0,
          label + ": every pixel equals 1-exp(-tau L) within " + Fmt(Tolerance) + " (max " +
            Fmt(maxErr) + ")");
        ck.Check(witness == 0, label + ": witness 0");
      }
    }
  }
  return ck.Result();
}
