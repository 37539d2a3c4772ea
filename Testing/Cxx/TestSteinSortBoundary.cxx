// vtkSteinVisibilitySort's ADJACENCY_GRAPH on boundary-heavy meshes, where the
// order between cells rests on the boundary face pairs (hovSteinBoundaryPairs):
// the bundled bracket (56k tets, a quarter on the boundary, concave, with
// holes) from three views, and a 4 x 4 x 4 lattice of small disconnected
// jittered blocks staggered in depth (every cell a boundary cell; many EXIT /
// ENTRY face pairs at different depths), perspective and parallel views, also
// from inside the lattice. Each order is judged by the independent ray/face
// oracle (hovSortOracle): every cell once, zero ray and face violations.
#include "hovSortCases.h"
#include "hovSortMeshes.h"
#include "hovSortOracle.h"
#include "hovTestMeshes.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
/// 4 x 4 x 4 small blocks of 2 x 2 x 2 jittered Kuhn cubes, gaps between
/// them, alternate rows shifted by half a block so blocks hide each other.
/// Jitter 0: every boundary face in an axis-aligned plane shared with other
/// blocks' faces and corners (the exact zeros of grid-aligned meshes such as
/// the benchmark's heatsink, decided by hov::AxisOrient3d).
vtkSmartPointer<vtkUnstructuredGrid> BlockLattice(unsigned seed, double jitter)
{
  MeshBuilder all;
  for (int k = 0; k < 4; ++k)
  {
    for (int j = 0; j < 4; ++j)
    {
      for (int i = 0; i < 4; ++i)
      {
        const double o[3] = { 1.3 * i + 0.55 * ((j + k) & 1), 1.3 * j + 0.4 * (k & 1), 1.3 * k };
        const double size[3] = { 0.9, 0.8, 0.7 + 0.1 * (i & 1) };
        const unsigned s = seed + 31u * static_cast<unsigned>(i + 4 * (j + 4 * k));
        MeshBuilder m = JitteredTetBlock(2, 2, 2, o, size, jitter, s);
        all.Append(m);
      }
    }
  }
  return all.Grid();
}

void Run(Checker& ck, const std::string& mesh, vtkUnstructuredGrid* grid, const SortView& view,
  const OracleOptions& options)
{
  vtkNew<vtkCamera> cam;
  view.Apply(cam);
  vtkNew<vtkSteinVisibilitySort> sort;
  const std::vector<vtkIdType> order =
    FullOrder(sort, grid, cam, nullptr, vtkVisibilitySort::BACK_TO_FRONT);
  const OracleResult r = CheckVisibilityOrder(grid, cam, nullptr, order, options);
  std::cout << "  " << mesh << " / " << view.Name << ": " << r.Str() << ", boundary cells "
            << sort->GetNumberOfBoundaryCells() << ", tests " << sort->GetNumberOfObstructsTests()
            << ", edges " << sort->GetNumberOfGraphEdges() << ", cycles "
            << sort->GetNumberOfCycles() << "\n";
  const std::string what = mesh + " / " + view.Name;
  ck.Check(r.EveryCellOnce(), what + ": every cell once");
  ck.Check(r.RayViolations == 0 && r.FaceViolations == 0, what + ": no oracle violation");
  ck.Check(r.OverlappingPairs == 0, what + ": the mesh is valid (no overlapping cells)");
  ck.Check(sort->GetNumberOfCycles() == 0, what + ": no cycle reported");
  ck.Check(r.PairsChecked > 0, what + ": the oracle saw overlapping cells along rays");
}
}

int TestSteinSortBoundary(int argc, char* argv[])
{
  Checker ck;
  for (const double jitter : { 0.3, 0.0 })
  {
    const std::string name = jitter > 0 ? "block lattice" : "aligned lattice";
    vtkSmartPointer<vtkUnstructuredGrid> lattice = BlockLattice(41, jitter);
    double b[6];
    lattice->GetBounds(b);
    OracleOptions options;
    options.RaysX = options.RaysY = 120;
    options.RandomRays = 4000;
    for (const SortView& view : RandomViews(b, 4, 910))
    {
      Run(ck, name, lattice, view, options);
    }
    // Along the lattice's x rows and from inside it (blocks on all sides).
    SortView along;
    along.Name = "along x";
    along.Position[0] = b[0] - 2 * (b[1] - b[0]);
    along.Position[1] = 0.45 * (b[2] + b[3]);
    along.Position[2] = 0.55 * (b[4] + b[5]);
    along.FocalPoint[0] = 0.5 * (b[0] + b[1]);
    along.FocalPoint[1] = 0.5 * (b[2] + b[3]);
    along.FocalPoint[2] = 0.5 * (b[4] + b[5]);
    along.ViewUp[0] = 0;
    along.ViewUp[1] = 0;
    along.ViewUp[2] = 1;
    Run(ck, name, lattice, along, options);
    const double eye[3] = { b[0] + 1.2, b[2] + 1.2, b[4] + 1.2 }; // in the gap of 4 blocks
    const double focal[3] = { b[1], b[3], b[5] };
    Run(ck, name, lattice, InsideView("inside", eye, focal), options);
  }
  {
    vtkSmartPointer<vtkUnstructuredGrid> bracket = LoadBracket(argc, argv);
    ck.Check(bracket && bracket->GetNumberOfCells() > 50000, "bracket: loaded");
    if (bracket)
    {
      double b[6];
      bracket->GetBounds(b);
      OracleOptions options;
      options.RaysX = options.RaysY = 100;
      options.RandomRays = 2000;
      for (const SortView& view : RandomViews(b, 3, 57))
      {
        Run(ck, "bracket", bracket, view, options);
      }
    }
  }
  return ck.Result();
}
