/**
 * @file hovSortCases.h
 * @brief The property check shared by the TestSort*.cxx tests: one mesh, one
 * view, vtkSteinVisibilitySort in both directions and vtkCellCenterDepthSort,
 * each order judged by the independent oracle (hovSortOracle.h) and by
 * vtkCellVisibilitySortFilter's interior-face count; one printed row per case.
 */
#ifndef hovSortCases_h
#define hovSortCases_h

#include "hovSortMeshes.h"
#include "hovSortOracle.h"

#include "vtkType.h"

#include <string>
#include <vector>

class vtkCamera;
class vtkMatrix4x4;
class vtkSteinVisibilitySort;
class vtkUnstructuredGrid;
class vtkVisibilitySort;

namespace hovTest
{
struct Checker;

/// The whole order of @p sort (input ids) in @p direction (vtkVisibilitySort's enum).
std::vector<vtkIdType> FullOrder(vtkVisibilitySort* sort, vtkUnstructuredGrid* grid,
  vtkCamera* cam, vtkMatrix4x4* model, int direction);

/// What one vtkSteinVisibilitySort reported for each sort of a series:
/// back-to-front order, cycles and their cells, Obstructs() tests, graph edges.
struct SteinSeries
{
  std::vector<std::vector<vtkIdType>> Order, CycleCells;
  std::vector<vtkIdType> Cycles, Tests, Edges;
  bool operator==(const SteinSeries& o) const
  {
    return this->Order == o.Order && this->CycleCells == o.CycleCells &&
      this->Cycles == o.Cycles && this->Tests == o.Tests && this->Edges == o.Edges;
  }
};

/// @p sorts sorts of @p grid by @p sort: @p cam's view, then each after a
/// further 5 degree azimuth of @p cam.
SteinSeries SortSeries(vtkSteinVisibilitySort* sort, vtkUnstructuredGrid* grid, vtkCamera* cam,
  int sorts);

struct SortCase
{
  std::string Mesh, View;
  std::string Camera; // position, focal point, view up, projection (for reproductions)
  vtkIdType Cells = 0;
  OracleResult Stein, SteinFrontToBack, Center;
  bool FrontToBackIsReverse = false;
  vtkIdType Cycles = 0, CycleCells = 0, Unordered = 0;
  vtkIdType FilterViolationsStein = 0, FilterViolationsCenter = 0;
  double SteinSeconds = 0, CenterSeconds = 0;
};

/// Runs both sorts on @p grid for @p view (and @p model, may be null).
SortCase RunSortCase(const std::string& mesh, vtkUnstructuredGrid* grid, const SortView& view,
  vtkMatrix4x4* model, const OracleOptions& options = OracleOptions());

void PrintSortHeader();
void PrintSortCase(const SortCase& c);

/// The checks of an acyclic case: Stein gives every cell once, no ray and no
/// face violation, front-to-back is the reverse, no cycle, no unordered
/// cell, the filter counts 0 face violations, and the mesh is valid (the
/// oracle finds no overlapping cells). Returns true if all passed.
bool CheckExactCase(Checker& ck, const SortCase& c);

/// Sums of the cell-centre sort's violations over cases (ray + face).
vtkIdType CenterViolations(const std::vector<SortCase>& cases);
}

#endif
