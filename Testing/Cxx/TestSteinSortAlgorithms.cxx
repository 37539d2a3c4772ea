// vtkSteinVisibilitySort: both algorithms, ADJACENCY_GRAPH (default) and the
// published MULTITILED_MERGE, on random jittered tetrahedra, a conforming
// mixed mesh, a holed block (also seen from inside the hole), disconnected
// blocks and a log pile of long thin wedges, perspective and parallel views:
// each order is judged by the independent ray/face oracle (hovSortOracle):
// every cell once, zero ray and face violations, no cycle. Both algorithms
// must also report the cycle of the cyclic triple and still emit every cell
// once, and the graph's order must not depend on earlier views or the object.
#include "hovSortMeshes.h"
#include "hovSortCases.h"
#include "hovSortOracle.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
const char* AlgorithmName(int a)
{
  return a == vtkSteinVisibilitySort::ADJACENCY_GRAPH ? "graph" : "merge";
}

/// Both algorithms on one mesh and view; returns the graph's order.
void RunBoth(Checker& ck, const std::string& mesh, vtkUnstructuredGrid* grid, const SortView& view)
{
  vtkNew<vtkCamera> cam;
  view.Apply(cam);
  OracleOptions options;
  options.RaysX = options.RaysY = 100;
  options.RandomRays = 3000;
  for (int a : { vtkSteinVisibilitySort::ADJACENCY_GRAPH, vtkSteinVisibilitySort::MULTITILED_MERGE })
  {
    vtkNew<vtkSteinVisibilitySort> sort;
    sort->SetAlgorithm(a);
    const std::vector<vtkIdType> order =
      FullOrder(sort, grid, cam, nullptr, vtkVisibilitySort::BACK_TO_FRONT);
    const OracleResult r = CheckVisibilityOrder(grid, cam, nullptr, order, options);
    std::cout << "  " << mesh << " / " << view.Name << " / " << AlgorithmName(a) << ": "
              << r.Str() << ", cycles " << sort->GetNumberOfCycles() << ", tests "
              << sort->GetNumberOfObstructsTests() << ", edges " << sort->GetNumberOfGraphEdges()
              << "\n";
    const std::string what = mesh + " / " + view.Name + " / " + AlgorithmName(a);
    ck.Check(r.EveryCellOnce(), what + ": every cell once");
    ck.Check(r.RayViolations == 0 && r.FaceViolations == 0, what + ": no oracle violation");
    ck.Check(r.OverlappingPairs == 0, what + ": the mesh is valid (no overlapping cells)");
    ck.Check(sort->GetNumberOfCycles() == 0, what + ": no cycle reported");
    ck.Check(r.PairsChecked > 0, what + ": the oracle saw overlapping cells along rays");
  }
}

/// The cyclic triple: a cycle reported, every cell once, for both algorithms.
void CyclicCase(Checker& ck)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = CyclicTriple();
  vtkNew<vtkCamera> cam;
  FigureCamera(cam, false);
  for (int a : { vtkSteinVisibilitySort::ADJACENCY_GRAPH, vtkSteinVisibilitySort::MULTITILED_MERGE })
  {
    vtkNew<vtkSteinVisibilitySort> sort;
    sort->SetAlgorithm(a);
    const std::vector<vtkIdType> order =
      FullOrder(sort, grid, cam, nullptr, vtkVisibilitySort::BACK_TO_FRONT);
    const OracleResult r = CheckVisibilityOrder(grid, cam, nullptr, order);
    vtkNew<vtkIdList> cycle;
    sort->GetCycleCells(cycle);
    std::cout << "  cyclic triple / " << AlgorithmName(a) << ": cycles "
              << sort->GetNumberOfCycles() << ", cycle cells " << cycle->GetNumberOfIds() << ", "
              << r.Str() << "\n";
    const std::string what = std::string("cyclic triple / ") + AlgorithmName(a);
    ck.Check(r.EveryCellOnce(), what + ": every cell once");
    ck.Check(sort->GetNumberOfCycles() >= 1 && cycle->GetNumberOfIds() == 3,
      what + ": the cycle of the three cells is reported");
  }
}

/// MULTITILED_MERGE with the most tiles the setters allow (4096 x 4096): the
/// tile lists would hold ~10^8-10^9 entries (tens of GB, as many steps), so
/// the tiles are halved until tiles and entries number at most 2^20 here
/// (this mesh's 16 per cell are fewer); a sane tiling (64 x 64) is used as
/// set. Both orders stay exact.
void HugeTiles(Checker& ck, vtkUnstructuredGrid* grid, const SortView& view)
{
  vtkNew<vtkCamera> cam;
  view.Apply(cam);
  for (int tiles : { 4096, 64 })
  {
    vtkNew<vtkSteinVisibilitySort> sort;
    sort->SetAlgorithmToMultitiledMerge();
    sort->SetNumberOfTiles(tiles, tiles);
    const std::vector<vtkIdType> order =
      FullOrder(sort, grid, cam, nullptr, vtkVisibilitySort::BACK_TO_FRONT);
    const OracleResult r = CheckVisibilityOrder(grid, cam, nullptr, order);
    const int* used = sort->GetUsedTiles();
    const std::string what = "merge, " + std::to_string(tiles) + "^2 tiles requested";
    std::cout << "  " << what << ": used " << used[0] << " x " << used[1] << ", " << r.Str()
              << "\n";
    ck.Check(r.EveryCellOnce() && r.RayViolations == 0 && r.FaceViolations == 0,
      what + ": exact order");
    ck.Check(tiles == 4096 ? used[0] <= 1024 && used[0] == used[1] && used[0] >= 64
                           : used[0] == 64 && used[1] == 64,
      what + (tiles == 4096 ? ": reduced" : ": used as set"));
  }
}

/// The graph's order does not depend on the chunk size, the sort object or earlier views.
void Determinism(Checker& ck, vtkUnstructuredGrid* grid, const SortView& view)
{
  vtkNew<vtkCamera> cam;
  view.Apply(cam);
  vtkNew<vtkSteinVisibilitySort> sort;
  const std::vector<vtkIdType> a =
    FullOrder(sort, grid, cam, nullptr, vtkVisibilitySort::BACK_TO_FRONT);
  cam->Azimuth(3);
  FullOrder(sort, grid, cam, nullptr, vtkVisibilitySort::BACK_TO_FRONT);
  vtkNew<vtkCamera> same;
  view.Apply(same);
  sort->SetMaxCellsReturned(1000);
  const std::vector<vtkIdType> b =
    FullOrder(sort, grid, same, nullptr, vtkVisibilitySort::BACK_TO_FRONT);
  vtkNew<vtkSteinVisibilitySort> fresh;
  const std::vector<vtkIdType> c =
    FullOrder(fresh, grid, same, nullptr, vtkVisibilitySort::BACK_TO_FRONT);
  ck.Check(!a.empty() && a == b, "graph: re-sorting the same view repeats the order");
  ck.Check(a == c, "graph: a new sort object gives the same order");
}
}

int TestSteinSortAlgorithms(int, char*[])
{
  Checker ck;
  struct Mesh
  {
    std::string Name;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
  };
  const Mesh meshes[] = { { "random tets 5^3", RandomTetMesh(5, 21) }, { "mixed", MixedMesh(7) },
    { "holed", HoledBlock(6, 22) }, { "disconnected", DisconnectedBlocks(23) },
    { "log pile", InterleavedSticks(6, 6) } };
  unsigned seed = 300;
  for (const Mesh& m : meshes)
  {
    double b[6];
    m.Grid->GetBounds(b);
    for (const SortView& view : RandomViews(b, 3, seed++))
    {
      RunBoth(ck, m.Name, m.Grid, view);
    }
  }
  {
    // From inside the hole of the holed block (perspective).
    vtkSmartPointer<vtkUnstructuredGrid> holed = meshes[2].Grid;
    double b[6];
    holed->GetBounds(b);
    const double eye[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), b[4] + 0.3 * (b[5] - b[4]) };
    const double focal[3] = { b[0], b[2], b[5] };
    RunBoth(ck, "holed", holed, InsideView("inside the hole", eye, focal));
  }
  CyclicCase(ck);
  double b[6];
  meshes[0].Grid->GetBounds(b);
  Determinism(ck, meshes[0].Grid, RandomViews(b, 1, 77)[0]);
  HugeTiles(ck, meshes[0].Grid, RandomViews(b, 1, 78)[0]);
  return ck.Result();
}
