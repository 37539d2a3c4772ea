// The parallel steps of vtkSteinVisibilitySort's set-up against serial ones,
// under 1 to 4 TBB threads and the Sequential backend, at the block sizes
// where they split: ParallelRunningSum and ParallelSelect
// (Filters/hovSteinBuckets.h) for 0 to 300001 items; hovStein::Geometry of
// 132k tetrahedra read in place from the grid's cell array and from own
// copies (32-bit cell storage, double points): the same corners, face codes
// and bounds, and the same Geometry object rebuilt shared, own, shared; a
// sort after the grid's cell storage was converted to 32 bits and back and
// squeezed (new arrays): set up again, every cell once.
#include "hovSortMeshes.h"
#include "hovSteinBuckets.h"
#include "hovSteinGeometry.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkUnstructuredGrid.h"

#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
struct Setting
{
  int Threads;
  std::string Backend;
};
const std::vector<Setting> Settings = { { 1, "TBB" }, { 2, "TBB" }, { 3, "TBB" }, { 4, "TBB" },
  { 1, "Sequential" } };

/// Runs @p fn under each setting; @p what names the setting for the check.
void UnderEach(const std::function<void(const std::string& what)>& fn)
{
  for (const Setting& s : Settings)
  {
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ s.Threads, s.Backend, false },
      [&]() { fn(s.Backend + " " + std::to_string(s.Threads) + " thread(s)"); });
  }
}

void CheckSums(Checker& ck)
{
  std::mt19937 rng(5);
  for (vtkIdType n : { 0, 1, 16383, 16384, 16385, 131071, 131072, 131073, 300001 })
  {
    std::vector<vtkIdType> counts(n + 1);
    counts[0] = 7;
    for (vtkIdType i = 1; i <= n; ++i)
    {
      counts[i] = rng() % 3 == 0 ? 0 : static_cast<vtkIdType>(rng() % 5);
    }
    std::vector<vtkIdType> expected = counts;
    for (vtkIdType i = 0; i < n; ++i)
    {
      expected[i + 1] += expected[i];
    }
    // Kept: every index whose count is odd (runs of each kind and both ends).
    std::vector<vtkIdType> selected = { -1, -2, -3 };
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (counts[i + 1] % 2)
      {
        selected.push_back(i);
      }
    }
    UnderEach([&](const std::string& what) {
      std::vector<vtkIdType> sums = counts;
      hovStein::ParallelRunningSum(sums.data(), n);
      std::vector<vtkIdType> out = { -1, -2, -3 };
      hovStein::ParallelSelect(
        n, [&counts](vtkIdType i) { return counts[i + 1] % 2 != 0; }, out);
      ck.Check(sums == expected && out == selected,
        "ParallelRunningSum and ParallelSelect, " + std::to_string(n) + " items, " + what +
          ": the serial sums and indices");
    });
  }
}

/// True if @p a and @p b hold the same cells, corners, face codes and bounds.
bool SameGeometry(const hovStein::Geometry& a, const hovStein::Geometry& b)
{
  bool same = a.NumberOfCells == b.NumberOfCells && a.Kinds == b.Kinds &&
    a.FaceCodes == b.FaceCodes && a.Diagonal == b.Diagonal &&
    a.MaxAbsCoordinate == b.MaxAbsCoordinate && a.Points == b.Points &&
    a.NumberOfBadCells == b.NumberOfBadCells;
  for (vtkIdType c = 0; same && c < a.NumberOfCells; ++c)
  {
    same = a.NumberOfCorners(c) == b.NumberOfCorners(c) &&
      std::equal(a.CellCorners(c), a.CellCorners(c) + a.NumberOfCorners(c), b.CellCorners(c));
  }
  return same;
}

void CheckGeometry(Checker& ck, vtkUnstructuredGrid* grid)
{
  // Own copies: the cells stored with 32-bit ids, or the points as doubles.
  vtkNew<vtkUnstructuredGrid> narrow;
  narrow->DeepCopy(grid);
  narrow->GetCells()->ConvertTo32BitStorage();
  vtkNew<vtkUnstructuredGrid> doubles;
  doubles->DeepCopy(grid);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(grid->GetPoints());
  doubles->SetPoints(points);
  hovStein::Geometry serial;
  vtkSMPTools::LocalScope(
    vtkSMPTools::Config{ 1, "Sequential", false }, [&]() { serial.Build(narrow, nullptr); });
  ck.Check(!serial.SharedCells && serial.NumberOfCells == grid->GetNumberOfCells(),
    "32-bit cell storage: own corners");
  UnderEach([&](const std::string& what) {
    hovStein::Geometry shared, wide;
    shared.Build(grid, nullptr);
    wide.Build(doubles, nullptr);
    ck.Check(shared.SharedCells && wide.SharedCells && SameGeometry(shared, serial) &&
        SameGeometry(wide, serial),
      "corners read in place (float and double points), " + what +
        ": the same cells, corners, face codes and bounds as own corners read serially");
  });
  // One object rebuilt: shared, own, shared again.
  hovStein::Geometry g;
  g.Build(grid, nullptr);
  const bool first = g.SharedCells && SameGeometry(g, serial);
  g.Build(narrow, nullptr);
  const bool second = !g.SharedCells && SameGeometry(g, serial);
  g.Build(grid, nullptr);
  ck.Check(first && second && g.SharedCells && SameGeometry(g, serial),
    "one Geometry rebuilt shared, own, shared: the same each time");
}

void CheckStorageMoved(Checker& ck, vtkUnstructuredGrid* source)
{
  vtkNew<vtkUnstructuredGrid> grid;
  grid->DeepCopy(source);
  vtkNew<vtkCamera> cam;
  cam->SetPosition(4, -3, 2.5);
  cam->SetFocalPoint(0, 0.5, 3);
  vtkNew<vtkSteinVisibilitySort> sort;
  sort->SetInput(grid);
  sort->SetCamera(cam);
  sort->InitTraversal();
  vtkDataArray* before = grid->GetCells()->GetConnectivityArray();
  const vtkMTimeType mtime = grid->GetMTime();
  sort->GetOrder();
  // New arrays for the same cells (the old ones freed but for the sort's
  // references), then squeezed.
  grid->GetCells()->ConvertTo32BitStorage();
  grid->GetCells()->ConvertTo64BitStorage();
  grid->Squeeze();
  const bool moved = grid->GetCells()->GetConnectivityArray() != before;
  cam->Azimuth(5);
  vtkIdTypeArray* order = sort->GetOrder();
  std::vector<int> seen(grid->GetNumberOfCells(), 0);
  bool once = order->GetNumberOfTuples() == grid->GetNumberOfCells();
  for (vtkIdType i = 0; once && i < order->GetNumberOfTuples(); ++i)
  {
    const vtkIdType c = order->GetValue(i);
    once = c >= 0 && c < grid->GetNumberOfCells() && seen[c]++ == 0;
  }
  std::cout << "     storage " << (moved ? "moved" : "not moved") << ", MTime "
            << (grid->GetMTime() == mtime ? "unchanged" : "changed") << ", set-up "
            << sort->GetLastSetupSeconds() << " s\n";
  ck.Check(moved && once && sort->GetLastSetupSeconds() > 0,
    "cell storage converted and back, squeezed: set up again, every cell once");
}
}

int TestSteinParallelSteps(int, char*[])
{
  Checker ck;
  CheckSums(ck);
  const double o[3] = { -1.25, 0.5, 3.0 }, size[3] = { 2.0, 1.5, 0.75 };
  vtkSmartPointer<vtkUnstructuredGrid> tets = JitteredTetBlock(28, 28, 28, o, size, 0.3, 7).Grid();
  std::cout << "     " << tets->GetNumberOfCells() << " tetrahedra, " << tets->GetNumberOfPoints()
            << " points\n";
  CheckGeometry(ck, tets);
  CheckStorageMoved(ck, tets);
  return ck.Result();
}
