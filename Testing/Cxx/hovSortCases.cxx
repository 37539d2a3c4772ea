#include "hovSortCases.h"

#include "hovTestScenes.h" // Checker

#include "vtkCamera.h"
#include "vtkCellCenterDepthSort.h"
#include "vtkCellVisibilitySortFilter.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hovTest
{
std::vector<vtkIdType> FullOrder(vtkVisibilitySort* sort, vtkUnstructuredGrid* grid,
  vtkCamera* cam, vtkMatrix4x4* model, int direction)
{
  vtkNew<vtkMatrix4x4> identity;
  sort->SetInput(grid);
  sort->SetCamera(cam);
  sort->SetModelTransform(model ? model : identity.Get()); // copies the values
  sort->SetDirection(direction);
  sort->SetMaxCellsReturned(97); // several chunks: GetNextCells() is exercised too
  std::vector<vtkIdType> order;
  sort->InitTraversal();
  while (vtkIdTypeArray* a = sort->GetNextCells())
  {
    if (a->GetNumberOfTuples() == 0)
    {
      break;
    }
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      order.push_back(a->GetValue(i));
    }
  }
  return order;
}

SteinSeries SortSeries(vtkSteinVisibilitySort* sort, vtkUnstructuredGrid* grid, vtkCamera* cam,
  int sorts)
{
  SteinSeries out;
  for (int k = 0; k < sorts; ++k)
  {
    if (k > 0)
    {
      cam->Azimuth(5);
    }
    out.Order.push_back(FullOrder(sort, grid, cam, nullptr, vtkVisibilitySort::BACK_TO_FRONT));
    vtkNew<vtkIdList> cycle;
    sort->GetCycleCells(cycle);
    out.CycleCells.emplace_back(
      cycle->GetPointer(0), cycle->GetPointer(0) + cycle->GetNumberOfIds());
    out.Cycles.push_back(sort->GetNumberOfCycles());
    out.Tests.push_back(sort->GetNumberOfObstructsTests());
    out.Edges.push_back(sort->GetNumberOfGraphEdges());
  }
  return out;
}

namespace
{
vtkIdType FilterViolations(
  vtkUnstructuredGrid* grid, vtkCamera* cam, vtkMatrix4x4* model, vtkVisibilitySort* sort)
{
  vtkNew<vtkCellVisibilitySortFilter> filter;
  vtkNew<vtkTest::ErrorObserver> observer; // a cycle warning is expected on cyclic meshes
  filter->AddObserver(vtkCommand::WarningEvent, observer);
  filter->SetInputData(grid);
  filter->SetCamera(cam);
  filter->SetModelTransform(model);
  filter->SetVisibilitySort(sort);
  filter->Update();
  return filter->GetNumberOfViolations();
}
}

SortCase RunSortCase(const std::string& mesh, vtkUnstructuredGrid* grid, const SortView& view,
  vtkMatrix4x4* model, const OracleOptions& options)
{
  SortCase c;
  c.Mesh = mesh;
  c.View = view.Name + (model ? " +model" : "");
  c.Cells = grid->GetNumberOfCells();
  vtkNew<vtkCamera> cam;
  view.Apply(cam);
  {
    std::ostringstream s;
    s.precision(17);
    const double* p = cam->GetPosition();
    const double* f = cam->GetFocalPoint();
    const double* u = cam->GetViewUp();
    s << "position (" << p[0] << ", " << p[1] << ", " << p[2] << "), focal point (" << f[0] << ", "
      << f[1] << ", " << f[2] << "), view up (" << u[0] << ", " << u[1] << ", " << u[2] << "), "
      << (view.Parallel ? "parallel" : "perspective") << ", view angle " << view.ViewAngle;
    c.Camera = s.str();
  }

  vtkNew<vtkSteinVisibilitySort> stein;
  auto t0 = std::chrono::steady_clock::now();
  std::vector<vtkIdType> btf = FullOrder(stein, grid, cam, model, vtkVisibilitySort::BACK_TO_FRONT);
  c.SteinSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  c.Cycles = stein->GetNumberOfCycles();
  c.Unordered = stein->GetNumberOfUnorderedCells();
  vtkNew<vtkIdList> cycleCells;
  stein->GetCycleCells(cycleCells);
  c.CycleCells = cycleCells->GetNumberOfIds();
  c.FilterViolationsStein = FilterViolations(grid, cam, model, stein);
  std::vector<vtkIdType> ftb = FullOrder(stein, grid, cam, model, vtkVisibilitySort::FRONT_TO_BACK);
  c.Stein = CheckVisibilityOrder(grid, cam, model, btf, options);
  std::vector<vtkIdType> ftbReversed(ftb.rbegin(), ftb.rend());
  c.FrontToBackIsReverse = ftbReversed == btf;
  c.SteinFrontToBack = CheckVisibilityOrder(grid, cam, model, ftbReversed, options);

  vtkNew<vtkCellCenterDepthSort> center;
  t0 = std::chrono::steady_clock::now();
  std::vector<vtkIdType> ccd = FullOrder(center, grid, cam, model, vtkVisibilitySort::BACK_TO_FRONT);
  c.CenterSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  c.Center = CheckVisibilityOrder(grid, cam, model, ccd, options);
  c.FilterViolationsCenter = FilterViolations(grid, cam, model, center);
  return c;
}

void PrintSortHeader()
{
  std::cout << "  " << std::left << std::setw(18) << "mesh" << std::setw(30) << "view"
            << std::right << std::setw(7) << "cells" << std::setw(9) << "rays" << " | "
            << std::setw(26) << "Stein ray/face/filter/cyc" << " | " << std::setw(24)
            << "centre ray/face/filter" << std::setw(8) << "overlap" << std::setw(16)
            << "sec Stein/ctr" << "\n";
}

void PrintSortCase(const SortCase& c)
{
  std::ostringstream s, t, u;
  s << c.Stein.RayViolations << "/" << c.Stein.FaceViolations << "/" << c.FilterViolationsStein
    << "/" << c.Cycles;
  t << c.Center.RayViolations << "/" << c.Center.FaceViolations << "/"
    << c.FilterViolationsCenter;
  u << std::fixed << std::setprecision(3) << c.SteinSeconds << "/" << c.CenterSeconds;
  std::cout << "  " << std::left << std::setw(18) << c.Mesh << std::setw(30) << c.View
            << std::right << std::setw(7) << c.Cells << std::setw(9) << c.Stein.Rays << " | "
            << std::setw(26) << s.str() << " | " << std::setw(24) << t.str() << std::setw(8)
            << c.Stein.OverlappingPairs << std::setw(16) << u.str() << "\n";
}

bool CheckExactCase(Checker& ck, const SortCase& c)
{
  std::ostringstream what;
  what << c.Mesh << ", " << c.View << ": Stein exact (every cell once, 0 ray/face violations "
       << "both directions, FTB = reverse BTF, no cycle, filter 0)";
  const bool ok = c.Stein.EveryCellOnce() && c.SteinFrontToBack.EveryCellOnce() &&
    c.Stein.RayViolations == 0 && c.Stein.FaceViolations == 0 &&
    c.SteinFrontToBack.RayViolations == 0 && c.SteinFrontToBack.FaceViolations == 0 &&
    c.FrontToBackIsReverse && c.Cycles == 0 && c.Unordered == 0 && c.FilterViolationsStein == 0;
  if (!ok)
  {
    what << "\n      BTF: " << c.Stein.Str() << "\n      FTB: " << c.SteinFrontToBack.Str()
         << "\n      FTB is reverse: " << c.FrontToBackIsReverse << ", cycles " << c.Cycles
         << ", unordered " << c.Unordered << ", filter violations " << c.FilterViolationsStein
         << "\n      camera: " << c.Camera;
    for (const auto& p : c.Stein.Examples)
    {
      what << "\n      wrong pair: cell " << p.first << " is in front of cell " << p.second
           << " on some ray but comes first back to front";
    }
  }
  bool valid = c.Stein.OverlappingPairs == 0;
  ck.Check(valid, c.Mesh + ", " + c.View + ": the mesh is valid (no overlapping cells on rays)");
  return ck.Check(ok, what.str()) && valid;
}

vtkIdType CenterViolations(const std::vector<SortCase>& cases)
{
  vtkIdType v = 0;
  for (const SortCase& c : cases)
  {
    v += c.Center.RayViolations + c.Center.FaceViolations;
  }
  return v;
}
}
