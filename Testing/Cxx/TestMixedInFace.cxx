// Pixel rays lying EXACTLY in shared face planes (issue 4: no cracks, no
// double counting). The unit cube as 2x2x2 cubes of side 1/2: Kuhn-split
// quadratic tetrahedra (general path), Kuhn-split linear tetrahedra (fast
// path), hexahedra, wedges (split along the vertical diagonal plane) and
// pyramids (apex at the cube centre: faces in x = y and x + y = 1 of the
// cube), all with a CONSTANT field; and Kuhn cubes whose 6 tetrahedra are
// alternately linear and quadratic (the fast and the general path share every
// interior triangle, so both must apply the same tie rule). Orthographic
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
#include "vtkCellType.h"

#include <array>
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

/// Cube @p c (lattice order) as its 6 Kuhn tetrahedra along the diagonal
/// c0-c6, alternately linear (fast path) and quadratic (general path): every
/// interior face is shared by a linear and a quadratic tetrahedron.
void AddAlternatingKuhnCube(MeshBuilder& m, const std::array<vtkIdType, 8>& c)
{
  const int paths[6][2] = { { 1, 2 }, { 1, 5 }, { 4, 5 }, { 4, 7 }, { 3, 7 }, { 3, 2 } };
  for (int t = 0; t < 6; ++t)
  {
    std::vector<vtkIdType> ids = { c[0], c[paths[t][0]], c[paths[t][1]], c[6] };
    double e[3][3];
    for (int v = 0; v < 3; ++v)
    {
      for (int k = 0; k < 3; ++k)
      {
        e[v][k] = m.Points[ids[v + 1]][k] - m.Points[ids[0]][k];
      }
    }
    const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
      e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
      e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    if (det < 0.0)
    {
      std::swap(ids[1], ids[2]);
    }
    if (t % 2 == 0)
    {
      m.AddCell(VTK_TETRA, ids);
      continue;
    }
    const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
    for (const auto& edge : edges)
    {
      const std::array<double, 3> p = m.Points[ids[edge[0]]], q = m.Points[ids[edge[1]]];
      ids.push_back(m.AddPoint(0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2]), 1.0));
    }
    m.AddCell(VTK_QUADRATIC_TETRA, ids);
  }
}

MeshBuilder Block(int kind)
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
    if (kind == 2)
    {
      AddAlternatingKuhnCube(m, LatticeCube(ids, 2, 2, c % 2, (c / 2) % 2, c / 4));
      continue;
    }
    AddCube(
      m, LatticeCube(ids, 2, 2, c % 2, (c / 2) % 2, c / 4), kind == 0 ? q : mixed[c], Constant);
  }
  return m;
}
} // namespace

int TestMixedInFace(int, char*[])
{
  Checker ck;
  const double tau = Opacity / Unit;
  const double alphaIn = -std::expm1(-tau * 1.0);
  const char* meshNames[3] = { "Kuhn quadratic tetrahedra",
    "quadratic/linear tetrahedra, hex, wedges, pyramids",
    "Kuhn tetrahedra, alternately linear and quadratic" };
  for (int mesh = 0; mesh < 3; ++mesh)
  {
    const std::string meshName = meshNames[mesh];
    VolumeScene scene(Block(mesh).Grid());
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
                  << " of them on a cube diagonal; bad " << bad << " (" << badInPlane
                  << " on a diagonal), max error " << Fmt(maxErr) << ", witness " << witness
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
