// vtkSteinVisibilitySort (ADJACENCY_GRAPH) gives the same result for any number
// of threads: the bundled bracket (56k tetrahedra), a conforming mixed mesh
// (non-planar hexahedron faces), the sliding interface (boundary face pairs,
// coplanar touching faces), a holed block seen from inside the hole (cells
// clipped by and hidden behind the near plane), disconnected blocks and the
// cyclic triple, perspective and parallel views. Each case is sorted by a
// fresh sort object (first sort, with the view-independent set-up) and then
// re-sorted after a 5 degree azimuth, under TBB with 2, 4 and 1 threads, the
// Sequential backend and STDThread with 2 and 3 threads (vtkSMPTools::LocalScope;
// a probe checks that 2 or more threads really run when several are asked
// for): the orders, the cycle counts and cells, the numbers of Obstructs()
// tests and of graph edges must equal those of the first configuration
// exactly, and every order must hold every cell once.
#include "hovSortCases.h"
#include "hovSortMeshes.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <chrono> // probe sleeps
#include <iostream>
#include <mutex>
#include <set>
#include <string>
#include <thread> // thread ids, hardware_concurrency
#include <vector>

using namespace hovTest;

namespace
{
/// Distinct threads running the pieces of a small vtkSMPTools::For whose
/// pieces sleep (so an idle worker always gets some).
int ProbeThreads()
{
  std::mutex mutex;
  std::set<std::thread::id> ids;
  for (int attempt = 0; attempt < 100 && ids.size() < 2; ++attempt) // slow wake-up when loaded
  {
    vtkSMPTools::For(0, 16, 1, [&](vtkIdType, vtkIdType) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      std::lock_guard<std::mutex> lock(mutex);
      ids.insert(std::this_thread::get_id());
    });
  }
  return static_cast<int>(ids.size());
}

/// First sort and re-sort of @p grid for @p view with a fresh sort object.
SteinSeries SortTwice(vtkUnstructuredGrid* grid, const SortView& view)
{
  vtkNew<vtkCamera> cam;
  view.Apply(cam);
  vtkNew<vtkSteinVisibilitySort> sort;
  return SortSeries(sort, grid, cam, 2);
}

/// Every cell exactly once.
bool EveryCellOnce(std::vector<vtkIdType> order, vtkIdType n)
{
  if (static_cast<vtkIdType>(order.size()) != n)
  {
    return false;
  }
  std::sort(order.begin(), order.end());
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (order[i] != i)
    {
      return false;
    }
  }
  return true;
}

/// One case under every configuration; checks against the first one.
void RunCase(Checker& ck, const std::string& mesh, vtkUnstructuredGrid* grid, const SortView& view)
{
  struct Config
  {
    const char* Backend;
    int Threads;
  };
  const Config configs[] = { { "TBB", 2 }, { "TBB", 4 }, { "TBB", 1 }, { "Sequential", 1 },
    { "STDThread", 2 }, { "STDThread", 3 } };
  const bool multicore = std::thread::hardware_concurrency() > 1;
  SteinSeries reference;
  bool first = true;
  for (const Config& c : configs)
  {
    SteinSeries out;
    int running = 0;
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ c.Threads, c.Backend, false }, [&]() {
      running = c.Threads > 1 && multicore ? ProbeThreads() : 1;
      out = SortTwice(grid, view);
    });
    const std::string what =
      mesh + " / " + view.Name + " / " + c.Backend + " " + std::to_string(c.Threads);
    if (c.Threads > 1 && multicore && running < 2)
    {
      ck.Check(false, what + ": only " + std::to_string(running) + " thread(s) ran");
    }
    if (first)
    {
      reference = out;
      first = false;
      std::cout << "  " << mesh << " / " << view.Name << ": cycles " << out.Cycles[0] << ", "
                << out.Cycles[1] << "; tests " << out.Tests[0] << ", " << out.Tests[1]
                << "; edges " << out.Edges[0] << ", " << out.Edges[1] << "\n";
      const vtkIdType n = grid->GetNumberOfCells();
      ck.Check(EveryCellOnce(out.Order[0], n) && EveryCellOnce(out.Order[1], n),
        what + ": every cell once (first sort and re-sort)");
      continue;
    }
    ck.Check(out == reference, what + ": same orders, cycles, tests and edges as " +
        configs[0].Backend + " " + std::to_string(configs[0].Threads));
  }
}
}

int TestSteinSortThreads(int argc, char* argv[])
{
  Checker ck;
  const std::string data = ArgAfter(argc, argv, "-D", "");
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((data + "/bracket_tet4_ccx.vtu").c_str());
  reader->Update();
  struct Mesh
  {
    std::string Name;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
  };
  const Mesh meshes[] = { { "bracket", reader->GetOutput() }, { "mixed", MixedMesh(7) },
    { "sliding interface", SlidingInterface(5) }, { "disconnected", DisconnectedBlocks(23) },
    { "cyclic triple", CyclicTriple() } };
  if (!ck.Check(meshes[0].Grid->GetNumberOfCells() > 50000, "the bracket was read"))
  {
    return ck.Result();
  }
  unsigned seed = 900;
  for (const Mesh& m : meshes)
  {
    double b[6];
    m.Grid->GetBounds(b);
    for (const SortView& view : RandomViews(b, 2, seed++))
    {
      RunCase(ck, m.Name, m.Grid, view);
    }
  }
  vtkSmartPointer<vtkUnstructuredGrid> holed = HoledBlock(6, 22);
  double b[6];
  holed->GetBounds(b);
  const double eye[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), b[4] + 0.3 * (b[5] - b[4]) };
  const double focal[3] = { b[0], b[2], b[5] };
  RunCase(ck, "holed", holed, InsideView("inside the hole", eye, focal));
  vtkNew<vtkCamera> figure;
  FigureCamera(figure, false);
  SortView along;
  along.Name = "along -z";
  figure->GetPosition(along.Position);
  figure->GetFocalPoint(along.FocalPoint);
  figure->GetViewUp(along.ViewUp);
  RunCase(ck, "cyclic triple", meshes[4].Grid, along);
  return ck.Result();
}
