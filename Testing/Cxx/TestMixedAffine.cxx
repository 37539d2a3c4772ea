// General cells against the linear-tetrahedron path on fields both represent
// exactly: a 2x2x2 lattice of parallelepipeds (an affine, sheared grid, so the
// hexahedra are affine cells) with a LINEAR point field s = a + g.x, rendered
//  - as 6 Kuhn tetrahedra per parallelepiped (the reference: the exact linear path),
//  - as hexahedra, triquadratic hexahedra, 20-node hexahedra, wedges (2 per
//    parallelepiped, tops translated bottoms: affine), quadratic wedges,
//    quadratic tetrahedra: the restricted field is linear along every ray up
//    to rounding, so every pixel must agree with the tetrahedra to 1e-12;
//  - as pyramids (never affine: the restriction is a Chebyshev fit with a
//    1e-10 relative bound, then GK quadrature): agreement to 1e-8 required.
// Transfer function with several colour and opacity nodes inside the field's
// range (segments split at breakpoints); GPU-compatible (default) and
// VTK-unstructured opacity semantics, Williams-Max and Wilhelms-Van Gelder
// emission; both cell orderings; an oblique
// perspective view. The double image is compared (float would hide 1e-8).
#include "hovTestAnalytic.h"
#include "hovTestMixed.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"

#include <cmath>
#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
constexpr int W = 48, H = 40;

double Linear(double x, double y, double z)
{
  return 0.2 + 0.5 * x + 0.3 * y - 0.35 * z + 0.4;
}

MeshBuilder Lattice(CubeSplit split)
{
  MeshBuilder m;
  const double o[3] = { -0.8, -0.7, -0.6 };
  // Columns: the parallelepiped's edge vectors (sheared, not axis-aligned).
  const double a[3][3] = { { 0.8, 0.15, 0.1 }, { -0.1, 0.7, 0.2 }, { 0.12, -0.05, 0.65 } };
  const std::vector<vtkIdType> ids = AddLattice(m, 2, 2, 2, o, a, Linear);
  for (int k = 0; k < 2; ++k)
  {
    for (int j = 0; j < 2; ++j)
    {
      for (int i = 0; i < 2; ++i)
      {
        AddCube(m, LatticeCube(ids, 2, 2, i, j, k), split, Linear);
      }
    }
  }
  return m;
}
}

int TestMixedAffine(int, char*[])
{
  Checker ck;
  vtkNew<vtkCamera> cam;
  const double focal[3] = { 0.1, 0.05, 0.1 };
  const double dir[3] = { 0.55, -0.6, 0.58 };
  const double up[3] = { 0, 0, 1 };
  PlaceCamera(cam, focal, dir, 4.5, up, false, 38.0);
  cam->SetClippingRange(1.0, 20.0);

  auto setup = [](VolumeScene& scene) {
    DefaultTF(scene.Tf, 0.4);
    scene.Tf.Color->AddRGBPoint(0.45, 0.9, 0.9, 0.1);
    scene.Tf.Opacity->AddPoint(0.3, 0.05);
  };
  const MeshBuilder tets = Lattice(CubeSplit::Tetras);
  VolumeScene reference(tets.Grid());
  setup(reference);
  struct Kind
  {
    CubeSplit Split;
    double Tolerance;
  };
  const Kind kinds[] = { { CubeSplit::Hexahedron, 1e-12 }, { CubeSplit::TriQuadraticHexahedron, 1e-12 },
    { CubeSplit::QuadraticHexahedron, 1e-12 }, { CubeSplit::Wedges, 1e-12 },
    { CubeSplit::QuadraticWedges, 1e-12 }, { CubeSplit::QuadraticTetras, 1e-12 },
    { CubeSplit::Pyramids, 1e-8 } };
  // (opacity semantics, emission model): GPU + Williams-Max, VTK + Williams-Max,
  // VTK + Wilhelms-Van Gelder (emission scale 0.7).
  const int optics[3][2] = { { vtkHighOrderVolumeMapper::GPU_COMPATIBLE,
                               vtkHighOrderVolumeMapper::WILLIAMS_MAX },
    { vtkHighOrderVolumeMapper::VTK_UNSTRUCTURED, vtkHighOrderVolumeMapper::WILLIAMS_MAX },
    { vtkHighOrderVolumeMapper::VTK_UNSTRUCTURED, vtkHighOrderVolumeMapper::WILHELMS_VAN_GELDER } };
  for (const auto& optic : optics)
  {
    const int semantics = optic[0], emission = optic[1];
    for (int order : { vtkHighOrderVolumeMapper::VISIBILITY_SORT,
           vtkHighOrderVolumeMapper::PER_PIXEL_SORT })
    {
      reference.Mapper->SetOpacitySemantics(semantics);
      reference.Mapper->SetEmissionModel(emission);
      reference.Mapper->SetEmissionScale(0.7);
      reference.Mapper->SetCellOrdering(order);
      const Image ref = RenderDouble(reference.Mapper, cam, reference.Volume, W, H);
      const Sanity rs = CheckImage(ref);
      const std::string setting = std::string(semantics ? "VTK_UNSTRUCTURED" : "GPU_COMPATIBLE") +
        (emission ? ", Wilhelms-Van Gelder" : ", Williams-Max") + ", " +
        (order ? "PER_PIXEL_SORT" : "VISIBILITY_SORT");
      std::cout << "== reference (48 tetrahedra), " << setting << ": " << rs.Str() << "\n";
      // (Wilhelms-Van Gelder glow is not bounded by alpha: rgb <= alpha not required.)
      const bool sane = rs.NonFinite == 0 && rs.AlphaOut == 0 && (emission || rs.ColorOut == 0);
      ck.Check(sane && rs.Covered > static_cast<size_t>(W * H / 5) && reference.NoMessages(),
        "reference renders, covers > 20%, no messages");
      for (const Kind& kind : kinds)
      {
        const MeshBuilder mesh = Lattice(kind.Split);
        VolumeScene scene(mesh.Grid());
        setup(scene);
        scene.Mapper->SetOpacitySemantics(semantics);
        scene.Mapper->SetEmissionModel(emission);
        scene.Mapper->SetEmissionScale(0.7);
        scene.Mapper->SetCellOrdering(order);
        int status = 0;
        const Image img = RenderDouble(scene.Mapper, cam, scene.Volume, W, H, &status);
        const DiffStats d = Diff(img, ref, 0, 4, kind.Tolerance);
        const std::string label = std::string(CubeSplitName(kind.Split)) + " x8, " + setting;
        std::cout << "  " << label << ": cells " << scene.Mapper->GetNumberOfRenderedCells()
                  << ", segments " << scene.Mapper->GetNumberOfSegments() << ", pieces "
                  << scene.Mapper->GetNumberOfPieces() << ", witness "
                  << scene.Mapper->GetWitnessViolations() << "; vs tetrahedra " << d.Str() << "\n";
        ck.Check(status == 1 && scene.NoMessages(),
          label + ": renders without messages ('" + Msg(scene.Observer->GetWarningMessage()) + "')");
        ck.Check(img.W == W && d.Max <= kind.Tolerance,
          label + ": equals the tetrahedra within " + Fmt(kind.Tolerance) + " (max " + Fmt(d.Max) + ")");
      }
    }
  }
  return ck.Result();
}
