// vtkSteinVisibilitySort::ViewBufferCellLimit only decides whether the
// per-view buffers outlive a sort: with 0 (freed after every sort, as for
// inputs above the default 1,000,000 cells) one sort object gives, over a
// first sort and two re-sorts (5 and 10 degrees of azimuth), exactly the
// orders, cycles, Obstructs() tests and graph edges of an object that keeps
// them, with both algorithms, on the bundled bracket, a conforming mixed mesh,
// the sliding interface (boundary face pairs), a holed block seen from inside
// the hole (cells clipped by the near plane) and the cyclic triple.
#include "hovSortCases.h"
#include "hovSortMeshes.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <string>
#include <vector>

using namespace hovTest;

namespace
{
constexpr int Sorts = 3;

/// A first sort and two re-sorts of @p grid by one object with @p limit.
SteinSeries SortThrice(vtkUnstructuredGrid* grid, const SortView& view, int algorithm, vtkIdType limit)
{
  vtkNew<vtkCamera> cam;
  view.Apply(cam);
  vtkNew<vtkSteinVisibilitySort> sort;
  sort->SetAlgorithm(algorithm);
  sort->SetViewBufferCellLimit(limit);
  return SortSeries(sort, grid, cam, Sorts);
}

void RunCase(Checker& ck, const std::string& mesh, vtkUnstructuredGrid* grid, const SortView& view)
{
  const vtkIdType n = grid->GetNumberOfCells();
  for (int algorithm :
    { vtkSteinVisibilitySort::ADJACENCY_GRAPH, vtkSteinVisibilitySort::MULTITILED_MERGE })
  {
    const std::string what = mesh + " / " + view.Name +
      (algorithm == vtkSteinVisibilitySort::ADJACENCY_GRAPH ? " / graph" : " / merge");
    const SteinSeries kept = SortThrice(grid, view, algorithm, VTK_ID_MAX);
    const SteinSeries freed = SortThrice(grid, view, algorithm, 0);
    bool complete = true;
    for (int k = 0; k < Sorts; ++k)
    {
      complete = complete && static_cast<vtkIdType>(kept.Order[k].size()) == n;
    }
    ck.Check(complete, what + ": every sort orders all " + std::to_string(n) + " cells");
    ck.Check(freed == kept,
      what + ": buffers freed after each sort == kept (orders, cycles, tests, edges)");
  }
}
}

int TestSteinViewBuffers(int argc, char* argv[])
{
  Checker ck;
  vtkNew<vtkSteinVisibilitySort> defaults;
  ck.Check(defaults->GetViewBufferCellLimit() == 1000000, "default limit: 1,000,000 cells");
  defaults->SetViewBufferCellLimit(-3);
  ck.Check(defaults->GetViewBufferCellLimit() == 0, "a negative limit is clamped to 0");

  const std::string data = ArgAfter(argc, argv, "-D", "");
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((data + "/bracket_tet4_ccx.vtu").c_str());
  reader->Update();
  if (!ck.Check(reader->GetOutput()->GetNumberOfCells() > 50000, "the bracket was read"))
  {
    return ck.Result();
  }
  struct Mesh
  {
    std::string Name;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
  };
  const Mesh meshes[] = { { "bracket", reader->GetOutput() }, { "mixed", MixedMesh(5) },
    { "sliding interface", SlidingInterface(4) }, { "cyclic triple", CyclicTriple() } };
  unsigned seed = 1700;
  for (const Mesh& m : meshes)
  {
    double b[6];
    m.Grid->GetBounds(b);
    RunCase(ck, m.Name, m.Grid, RandomViews(b, 1, seed++)[0]);
  }
  vtkSmartPointer<vtkUnstructuredGrid> holed = HoledBlock(5, 22);
  double b[6];
  holed->GetBounds(b);
  const double eye[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), b[4] + 0.3 * (b[5] - b[4]) };
  const double focal[3] = { b[0], b[2], b[5] };
  RunCase(ck, "holed", holed, InsideView("inside the hole", eye, focal));
  return ck.Result();
}
