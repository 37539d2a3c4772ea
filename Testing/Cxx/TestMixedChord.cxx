// No cracks and no double counting between general cells (issue 4): blocks
// of every cell type with a CONSTANT field, whose union is an axis-aligned
// box, render at every pixel exactly the closed form of the box:
//   alpha = 1 - exp(-tau L),  rgb = c alpha  (Williams-Max, constant colour c)
// with L the analytic chord of the pixel ray through the box (slab method,
// long double) and tau = a / u (VTK_UNSTRUCTURED semantics). A crack shows as
// a pixel with too little alpha, a doubly counted face or overlap as too much.
//
// Meshes:
//  1. [0,2]^3 as 2x2x2 unit cubes: column (0,0) hexahedron below, quadratic
//     (20-node) hexahedron above; column (1,0) 2 wedges / 2 quadratic wedges;
//     column (0,1) 6 pyramids / 6 quadratic pyramids around the cube centre;
//     column (1,1) a voxel / a triquadratic hexahedron; plus, beside them, a
//     column of [2,3]x[0,2]x[0,2] as Kuhn tetrahedra (the linear fast path)
//     below and quadratic tetrahedra above. Shared faces: quad/quad with the
//     same corner ids (bit-identical crossings), triangle/triangle, and
//     coplanar non-conforming quad/triangle pairs.
//  2. Two hexahedra filling [0,2]x[0,1]x[0,1] whose shared face is NOT planar
//     (two of its corners moved along the box edges: (1,0,0) -> (0.85,0,0),
//     (1,1,1) -> (1.2,1,1)); the outer boundary stays the box, so the chord
//     is known although the interface is a bilinear patch.
//  3. Mesh 1 with the constant as CELL scalars (each general cell one
//     constant piece per interval).
// Views: orthographic along -z (shifted off the cell faces), orthographic
// oblique, perspective oblique, perspective from inside the mesh (cells cut
// by the near plane and the eye plane); both cell orderings. Every pixel whose ray is
// farther than 1e-9 from the box's edges must match to 1e-11 (double image),
// pixels missing the box must be exactly 0; the per-pixel witness must be 0.
#include "hovTestAnalytic.h"
#include "hovTestMixed.h"
#include "hovTestReference.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"

#include <cmath>
#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
constexpr int W = 64, H = 56;
constexpr double Tolerance = 1e-11;
const double Colour[3] = { 0.9, 0.6, 0.3 };
constexpr double Opacity = 0.6, Unit = 1.5; // tau = 0.4

double Constant(double, double, double)
{
  return 1.0;
}

MeshBuilder AllTypesBlock()
{
  MeshBuilder m;
  const double o[3] = { 0, 0, 0 };
  const double a[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  const std::vector<vtkIdType> ids = AddLattice(m, 3, 2, 2, o, a, Constant);
  const CubeSplit below[4] = { CubeSplit::Hexahedron, CubeSplit::Wedges, CubeSplit::Pyramids,
    CubeSplit::Voxel };
  const CubeSplit above[4] = { CubeSplit::QuadraticHexahedron, CubeSplit::QuadraticWedges,
    CubeSplit::QuadraticPyramids, CubeSplit::TriQuadraticHexahedron };
  for (int c = 0; c < 4; ++c)
  {
    const int i = c % 2, j = c / 2;
    AddCube(m, LatticeCube(ids, 3, 2, i, j, 0), below[c], Constant);
    AddCube(m, LatticeCube(ids, 3, 2, i, j, 1), above[c], Constant);
  }
  for (int j = 0; j < 2; ++j)
  {
    AddCube(m, LatticeCube(ids, 3, 2, 2, j, 0), CubeSplit::Tetras, Constant);
    AddCube(m, LatticeCube(ids, 3, 2, 2, j, 1), CubeSplit::QuadraticTetras, Constant);
  }
  return m;
}

MeshBuilder NonPlanarPair()
{
  MeshBuilder m;
  const double o[3] = { 0, 0, 0 };
  const double a[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  const std::vector<vtkIdType> ids = AddLattice(m, 2, 1, 1, o, a, Constant);
  // Lattice index i + 3 (j + 2 k): (1,0,0) is 1, (1,1,1) is 10.
  m.Points[ids[1]][0] = 0.85;
  m.Points[ids[10]][0] = 1.2;
  AddCube(m, LatticeCube(ids, 2, 1, 0, 0, 0), CubeSplit::Hexahedron, Constant);
  AddCube(m, LatticeCube(ids, 2, 1, 1, 0, 0), CubeSplit::Hexahedron, Constant);
  return m;
}

struct View
{
  const char* Name;
  double Direction[3];
  bool Parallel;
  double AngleOrScale;
  double Distance; ///< from the box centre (< half the box: the eye is inside)
};
}

int TestMixedChord(int, char*[])
{
  Checker ck;
  const double tau = Opacity / Unit;
  struct Case
  {
    const char* Name;
    MeshBuilder Mesh;
    bool CellScalars;
    double Bounds[6];
  };
  Case cases[3] = {
    { "all cell types, [0,3]x[0,2]x[0,2]", AllTypesBlock(), false, { 0, 3, 0, 2, 0, 2 } },
    { "all cell types, cell scalars", AllTypesBlock(), true, { 0, 3, 0, 2, 0, 2 } },
    { "2 hexahedra sharing a non-planar face", NonPlanarPair(), false, { 0, 2, 0, 1, 0, 1 } }
  };
  const View views[4] = { { "ortho -z", { 0, 0, 1 }, true, 1.7, 8.0 },
    { "ortho oblique", { 0.5, -0.7, 0.6 }, true, 2.0, 8.0 },
    { "perspective oblique", { -0.4, -0.8, 0.5 }, false, 40.0, 8.0 },
    { "perspective, eye inside the mesh", { -0.4, -0.8, 0.5 }, false, 70.0, 0.3 } };
  for (Case& cs : cases)
  {
    auto grid = cs.Mesh.Grid();
    if (cs.CellScalars)
    {
      // The constant as a cell array (the point scalars "s" are ignored).
      vtkNew<vtkDoubleArray> c;
      c->SetName("c");
      c->SetNumberOfTuples(grid->GetNumberOfCells());
      c->FillValue(1.0);
      grid->GetCellData()->SetScalars(c);
    }
    VolumeScene scene(grid);
    if (cs.CellScalars)
    {
      scene.Mapper->SetScalarModeToUseCellData();
    }
    ConstantTF(scene.Tf, Colour, Opacity, Unit);
    scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
    for (const View& v : views)
    {
      vtkNew<vtkCamera> cam;
      const double b[6] = { cs.Bounds[0], cs.Bounds[1], cs.Bounds[2], cs.Bounds[3], cs.Bounds[4],
        cs.Bounds[5] };
      // Focal point off the cell faces (the shift keeps pixel rays out of face planes).
      const double focal[3] = { 0.5 * (b[0] + b[1]) + 1.0 / 8192, 0.5 * (b[2] + b[3]) + 1.0 / 4096,
        0.5 * (b[4] + b[5]) };
      const double up[3] = { 0, 1, 0 };
      PlaceCamera(cam, focal, v.Direction, v.Distance, up, v.Parallel, v.AngleOrScale);
      cam->SetClippingRange(v.Distance < 1.0 ? 0.01 : 1.0, 20.0);
      const hovTestRef::CameraSpec spec = hovTestRef::ReadCamera(cam);
      for (int order : { vtkHighOrderVolumeMapper::VISIBILITY_SORT,
             vtkHighOrderVolumeMapper::PER_PIXEL_SORT })
      {
        scene.Mapper->SetCellOrdering(order);
        scene.Observer->Clear();
        int status = 0;
        const Image img = RenderDouble(scene.Mapper, cam, scene.Volume, W, H, &status);
        const std::string label = std::string(cs.Name) + ", " + v.Name + ", " +
          (order ? "PER_PIXEL_SORT" : "VISIBILITY_SORT");
        double maxErr = 0.0;
        int covered = 0, compared = 0, bad = 0;
        for (int j = 0; j < H && img.W == W; ++j)
        {
          for (int i = 0; i < W; ++i)
          {
            const hovTestRef::Ray ray = hovTestRef::PixelRay(spec, i, j, W, H);
            hovTestRef::Real t0 = 0, t1 = 0;
            const bool hit = hovTestRef::IntersectBox(ray, b, t0, t1);
            if (hovTestRef::DistanceToBoxEdges(ray, b) < GrazeDistance)
            {
              continue;
            }
            const double chord = hit ? static_cast<double>(t1 - t0) : 0.0;
            const double alpha = -std::expm1(-tau * chord);
            covered += chord > 0;
            ++compared;
            double err = std::abs(img.At(i, j, 3) - alpha);
            for (int c = 0; c < 3; ++c)
            {
              err = std::max(err, std::abs(img.At(i, j, c) - Colour[c] * alpha));
            }
            if (!(err <= Tolerance) && bad++ < 3)
            {
              std::cout << "  pixel (" << i << "," << j << "): chord " << chord << " alpha "
                        << img.At(i, j, 3) << " expected " << alpha << " error " << err << "\n";
            }
            maxErr = std::max(maxErr, err);
          }
        }
        const vtkIdType witness = scene.Mapper->GetWitnessViolations();
        std::cout << "== " << label << ": covered " << covered << " of " << compared
                  << " compared pixels, max error " << Fmt(maxErr) << ", witness " << witness
                  << ", segments " << scene.Mapper->GetNumberOfSegments() << ", pieces "
                  << scene.Mapper->GetNumberOfPieces() << "\n";
        ck.Check(status == 1 && scene.NoMessages(),
          label + ": renders without error or warning ('" +
            Msg(scene.Observer->GetWarningMessage()) + "')");
        ck.Check(img.W == W && covered > W * H / 16, label + ": the box covers > 1/16 of the image");
        ck.Check(bad == 0, label + ": every pixel equals 1-exp(-tau L) within " + Fmt(Tolerance) +
            " (max " + Fmt(maxErr) + ")");
        if (order == vtkHighOrderVolumeMapper::PER_PIXEL_SORT)
        {
          ck.Check(witness == 0, label + ": per-pixel witness 0 (no overlap)");
        }
      }
    }
  }
  return ck.Result();
}
