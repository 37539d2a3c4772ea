// vtkSteinVisibilitySort basics: every cell exactly once, shared faces in the
// right order (checked independently from face planes and the eye), two tets
// in both directions and projections, a model transform that swaps them,
// point coordinates stored as float, double or int, chunking, empty input, an
// unsupported cell (warning), tetrahedra with a missing point id and a NaN
// corner (warning; the cell array read in place is not trusted for them),
// cells appended in place (set up again), a cyclic triple of interleaved
// bars, perspective from inside the mesh, and re-sorting after a camera
// change without a new set-up.
#include "hovSortMeshes.h"
#include "hovTestMeshes.h"

#include "vtkCamera.h"
#include "vtkCell.h"
#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

using hovTest::MeshBuilder;

namespace
{
int Failures = 0;
void Check(bool ok, const std::string& what)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << "\n";
  Failures += ok ? 0 : 1;
}

/// The whole traversal; checks that every cell comes exactly once.
std::vector<vtkIdType> Traverse(vtkSteinVisibilitySort* sort, const std::string& what)
{
  std::vector<vtkIdType> order;
  sort->InitTraversal();
  for (vtkIdTypeArray* a = sort->GetNextCells(); a; a = sort->GetNextCells())
  {
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      order.push_back(a->GetValue(i));
    }
  }
  const vtkIdType n = sort->GetInput()->GetNumberOfCells();
  std::vector<int> seen(n, 0);
  bool once = static_cast<vtkIdType>(order.size()) == n;
  for (vtkIdType c : order)
  {
    once = once && c >= 0 && c < n && seen[c]++ == 0;
  }
  Check(once, what + ": every cell exactly once (" + std::to_string(n) + " cells)");
  return order;
}

/// Interior faces whose cell behind the face (seen from the camera) comes later in a
/// back-to-front order (independent check: Newell plane of the shared face).
int FaceViolations(vtkUnstructuredGrid* grid, vtkCamera* cam, const std::vector<vtkIdType>& order)
{
  std::vector<vtkIdType> pos(grid->GetNumberOfCells());
  for (size_t i = 0; i < order.size(); ++i)
  {
    pos[order[i]] = static_cast<vtkIdType>(i);
  }
  std::map<std::vector<vtkIdType>, std::vector<vtkIdType>> faces;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    vtkCell* cell = grid->GetCell(c);
    for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
    {
      vtkIdList* ids = cell->GetFace(f)->GetPointIds();
      std::vector<vtkIdType> key(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds());
      std::sort(key.begin(), key.end());
      faces[key].push_back(c);
    }
  }
  double eye[3], dop[3];
  cam->GetPosition(eye);
  cam->GetDirectionOfProjection(dop);
  int bad = 0;
  for (const auto& kv : faces)
  {
    if (kv.second.size() != 2)
    {
      continue;
    }
    // Newell normal and centre of the face, centroid of the first cell.
    double n[3] = { 0, 0, 0 }, fc[3] = { 0, 0, 0 }, cc[3] = { 0, 0, 0 }, x[3], y[3];
    const size_t m = kv.first.size();
    // Points of the face in cyclic order: take them from the first cell's face.
    vtkCell* cell = grid->GetCell(kv.second[0]);
    for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
    {
      vtkIdList* ids = cell->GetFace(f)->GetPointIds();
      std::vector<vtkIdType> key(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds());
      std::sort(key.begin(), key.end());
      if (key != kv.first)
      {
        continue;
      }
      for (size_t i = 0; i < m; ++i)
      {
        grid->GetPoint(ids->GetId(i), x);
        grid->GetPoint(ids->GetId((i + 1) % m), y);
        n[0] += (x[1] - y[1]) * (x[2] + y[2]);
        n[1] += (x[2] - y[2]) * (x[0] + y[0]);
        n[2] += (x[0] - y[0]) * (x[1] + y[1]);
        for (int k = 0; k < 3; ++k)
          fc[k] += x[k] / m;
      }
    }
    for (vtkIdType i = 0; i < cell->GetNumberOfPoints(); ++i)
    {
      grid->GetPoint(cell->GetPointId(i), x);
      for (int k = 0; k < 3; ++k)
        cc[k] += x[k] / cell->GetNumberOfPoints();
    }
    // Faces with a vertex behind the eye do not constrain the visible order.
    bool behind = false;
    for (vtkIdType id : kv.first)
    {
      grid->GetPoint(id, x);
      const double depth = (x[0] - eye[0]) * dop[0] + (x[1] - eye[1]) * dop[1] + (x[2] - eye[2]) * dop[2];
      behind = behind || (!cam->GetParallelProjection() && depth <= 1e-9);
    }
    if (behind)
    {
      continue;
    }
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double sideCell = 0, sideEye = 0;
    for (int k = 0; k < 3; ++k)
    {
      sideCell += n[k] / len * (cc[k] - fc[k]);
      sideEye += n[k] / len * (cam->GetParallelProjection() ? -dop[k] : eye[k] - fc[k]);
    }
    if (std::fabs(sideEye) < 1e-9)
    {
      continue; // edge-on: either order is right
    }
    // The first cell is in front iff it is on the eye's side of the face.
    const bool firstInFront = (sideCell > 0) == (sideEye > 0);
    const vtkIdType front = firstInFront ? kv.second[0] : kv.second[1];
    const vtkIdType back = firstInFront ? kv.second[1] : kv.second[0];
    bad += pos[front] < pos[back] ? 1 : 0;
  }
  return bad;
}

void SetCamera(vtkCamera* cam, const double pos[3], const double focal[3], bool parallel)
{
  cam->SetPosition(pos[0], pos[1], pos[2]);
  cam->SetFocalPoint(focal[0], focal[1], focal[2]);
  cam->SetViewUp(0, 0, 1);
  if (std::fabs(pos[0] - focal[0]) + std::fabs(pos[1] - focal[1]) < 1e-12)
  {
    cam->SetViewUp(0, 1, 0);
  }
  cam->SetParallelProjection(parallel);
  cam->SetParallelScale(2);
  cam->SetViewAngle(40);
}

}

namespace
{
void TwoTets(vtkCamera* cam)
{
  MeshBuilder m;
  for (double z0 : { 0.0, 3.0 }) // cell 0 low, cell 1 high
  {
    const vtkIdType a = m.AddPoint(0, 0, z0, 0), b = m.AddPoint(1, 0, z0, 0),
                    c = m.AddPoint(0, 1, z0, 0), d = m.AddPoint(0.2, 0.2, z0 + 1, 0);
    m.AddTet(a, b, c, d);
  }
  auto grid = m.Grid(false);
  vtkNew<vtkSteinVisibilitySort> sort;
  sort->SetInput(grid);
  sort->SetCamera(cam);
  const double above[3] = { 0.3, 0.3, 10 }, below[3] = { 0.3, 0.3, -10 }, f[3] = { 0.3, 0.3, 2 };
  for (bool parallel : { false, true })
  {
    const std::string p = parallel ? "parallel" : "perspective";
    SetCamera(cam, above, f, parallel);
    sort->SetDirectionToBackToFront();
    auto o = Traverse(sort, "two tets " + p);
    Check(o == std::vector<vtkIdType>({ 0, 1 }), "two tets, eye above, back to front, " + p);
    sort->SetDirectionToFrontToBack();
    o = Traverse(sort, "two tets " + p);
    Check(o == std::vector<vtkIdType>({ 1, 0 }), "two tets, eye above, front to back, " + p);
    SetCamera(cam, below, f, parallel);
    sort->SetDirectionToBackToFront();
    o = Traverse(sort, "two tets " + p);
    Check(o == std::vector<vtkIdType>({ 1, 0 }), "two tets, eye below, back to front, " + p);
  }
  // Re-sort after a camera change: new order, set-up reused.
  SetCamera(cam, above, f, false);
  Traverse(sort, "resort");
  cam->Elevation(180); // now looking from below
  cam->OrthogonalizeViewUp();
  auto o = Traverse(sort, "resort after camera change");
  Check(o == std::vector<vtkIdType>({ 1, 0 }) && sort->GetLastSetupSeconds() == 0,
    "camera change: new order, view-independent set-up reused");
  // A model transform that mirrors z swaps the order (eye above again).
  SetCamera(cam, above, f, false);
  vtkNew<vtkMatrix4x4> mirror;
  mirror->SetElement(2, 2, -1);
  sort->SetModelTransform(mirror);
  o = Traverse(sort, "mirrored");
  Check(o == std::vector<vtkIdType>({ 1, 0 }) && sort->GetLastSetupSeconds() > 0,
    "model transform mirroring z swaps the order (set-up rebuilt)");
  vtkNew<vtkMatrix4x4> identity;
  sort->SetModelTransform(identity);
  o = Traverse(sort, "identity again");
  Check(o == std::vector<vtkIdType>({ 0, 1 }), "identity model transform restores the order");
}

void CyclicBars(vtkCamera* cam, bool parallel)
{
  MeshBuilder m;
  const double pi = 3.14159265358979323846;
  double v[3][2];
  for (int i = 0; i < 3; ++i)
  {
    v[i][0] = 2 * std::cos(pi / 2 + 2 * pi * i / 3);
    v[i][1] = 2 * std::sin(pi / 2 + 2 * pi * i / 3);
  }
  for (int i = 0; i < 3; ++i)
  {
    const double* a = v[i];
    const double* b = v[(i + 1) % 3];
    const double d[2] = { b[0] - a[0], b[1] - a[1] };
    const double len = std::hypot(d[0], d[1]);
    const double w[2] = { -0.25 * d[1] / len, 0.25 * d[0] / len };
    // From a - d/2 (z 0) to b + d/2 (z 1): high at its end, low at its start.
    const double s[3] = { a[0] - 0.5 * d[0], a[1] - 0.5 * d[1], 0 };
    const double t[3] = { b[0] + 0.5 * d[0], b[1] + 0.5 * d[1], 1 };
    std::vector<vtkIdType> ids;
    for (double h : { 0.0, 0.05 })
    {
      ids.push_back(m.AddPoint(s[0] - w[0], s[1] - w[1], s[2] + h, 0));
      ids.push_back(m.AddPoint(t[0] - w[0], t[1] - w[1], t[2] + h, 0));
      ids.push_back(m.AddPoint(t[0] + w[0], t[1] + w[1], t[2] + h, 0));
      ids.push_back(m.AddPoint(s[0] + w[0], s[1] + w[1], s[2] + h, 0));
    }
    m.AddCell(VTK_HEXAHEDRON, ids);
  }
  auto grid = m.Grid(false);
  vtkNew<vtkSteinVisibilitySort> sort;
  sort->SetInput(grid);
  sort->SetCamera(cam);
  const double pos[3] = { 0.1, 0.05, 20 }, f[3] = { 0, 0, 0.5 };
  SetCamera(cam, pos, f, parallel);
  const std::string p = parallel ? " (parallel)" : " (perspective)";
  Traverse(sort, "cyclic bars" + p);
  vtkNew<vtkIdList> cyc;
  sort->GetCycleCells(cyc);
  std::set<vtkIdType> cells;
  for (vtkIdType i = 0; i < cyc->GetNumberOfIds(); ++i)
  {
    cells.insert(cyc->GetId(i));
  }
  std::cout << "     cycles " << sort->GetNumberOfCycles() << ", cycle cells " << cyc->GetNumberOfIds()
            << ", moves " << sort->GetNumberOfMoves() << "\n";
  Check(sort->GetNumberOfCycles() >= 1 && cells == std::set<vtkIdType>({ 0, 1, 2 }) &&
      cyc->GetNumberOfIds() == 3,
    "cyclic triple reported with its three cells" + p);
}
}

int TestSteinSortBasics(int, char*[])
{
  vtkNew<vtkCamera> cam;
  TwoTets(cam);
  CyclicBars(cam, false);
  CyclicBars(cam, true);

  // Blocks of tetrahedra (positive and inverted) and jittered hexahedra, from
  // outside (both projections) and from inside the bounding box.
  const double outside[3] = { 4.2, -3.1, 2.7 }, centre[3] = { 0.5, 0.5, 0.5 };
  const double inside[3] = { 0.43, 0.52, 0.47 }, corner[3] = { 1, 1, 1 };
  const double hexOut[3] = { 11, -7, 6 }, hexCentre[3] = { 2, 2, 2 }, hexIn[3] = { 1.9, 2.2, 2.1 };
  struct Case
  {
    std::string Name;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
    const double *Pos, *Focal;
    bool Parallel;
  };
  auto tets = hovTest::UnitBlock(4).Grid(false);
  auto inverted = hovTest::UnitBlock(3, true).Grid(false);
  auto hexes = hovTest::JitteredHexBlock(4, 0.3);
  const Case cases[] = { { "tet block, perspective", tets, outside, centre, false },
    { "tet block, parallel", tets, outside, centre, true },
    { "inverted tet block, perspective", inverted, outside, centre, false },
    { "tet block, eye inside", tets, inside, corner, false },
    { "jittered hex block, perspective", hexes, hexOut, hexCentre, false },
    { "jittered hex block, parallel", hexes, hexOut, hexCentre, true },
    { "jittered hex block, eye inside", hexes, hexIn, hexCentre, false } };
  for (const Case& c : cases)
  {
    vtkNew<vtkSteinVisibilitySort> sort;
    sort->SetInput(c.Grid);
    sort->SetCamera(cam);
    SetCamera(cam, c.Pos, c.Focal, c.Parallel);
    const auto order = Traverse(sort, c.Name);
    const int bad = FaceViolations(c.Grid, cam, order);
    std::cout << "     tests " << sort->GetNumberOfObstructsTests() << ", moves "
              << sort->GetNumberOfMoves() << ", cycles " << sort->GetNumberOfCycles() << "\n";
    Check(bad == 0 && sort->GetNumberOfCycles() == 0,
      c.Name + ": no interior face out of order (" + std::to_string(bad) + "), no cycle");
  }

  // Point storage: float, double and integer coordinates (the last read one
  // point at a time, the others in parallel) of the tet block scaled 4x
  // (integers): the same order, every face in order.
  {
    const double far[3] = { 16.8, -12.4, 10.8 }, mid[3] = { 2, 2, 2 };
    SetCamera(cam, far, mid, false);
    std::vector<vtkIdType> orders[3];
    int violations = 0;
    for (int type = 0; type < 3; ++type)
    {
      vtkSmartPointer<vtkDataArray> data;
      if (type == 0)
      {
        data = vtkSmartPointer<vtkFloatArray>::New();
      }
      else if (type == 1)
      {
        data = vtkSmartPointer<vtkDoubleArray>::New();
      }
      else
      {
        data = vtkSmartPointer<vtkIntArray>::New();
      }
      data->SetNumberOfComponents(3);
      data->SetNumberOfTuples(tets->GetNumberOfPoints());
      for (vtkIdType i = 0; i < tets->GetNumberOfPoints(); ++i)
      {
        const double* x = tets->GetPoint(i);
        data->SetTuple3(i, 4 * x[0], 4 * x[1], 4 * x[2]);
      }
      vtkNew<vtkPoints> points;
      points->SetData(data);
      vtkNew<vtkUnstructuredGrid> grid;
      grid->ShallowCopy(tets);
      grid->SetPoints(points);
      vtkNew<vtkSteinVisibilitySort> sort;
      sort->SetInput(grid);
      sort->SetCamera(cam);
      orders[type] = Traverse(sort, "tet block x4, point type " + std::to_string(type));
      violations += FaceViolations(grid, cam, orders[type]);
    }
    Check(orders[0] == orders[1] && orders[1] == orders[2] && violations == 0,
      "float, double and int points: the same order, no face out of order (" +
        std::to_string(violations) + ")");
  }

  // Chunks of MaxCellsReturned, the same order as GetOrder().
  {
    vtkNew<vtkSteinVisibilitySort> sort;
    sort->SetInput(tets);
    sort->SetCamera(cam);
    SetCamera(cam, outside, centre, false);
    sort->SetMaxCellsReturned(7);
    sort->InitTraversal();
    std::vector<vtkIdType> chunks;
    bool sizes = true;
    for (vtkIdTypeArray* a = sort->GetNextCells(); a; a = sort->GetNextCells())
    {
      sizes = sizes && a->GetNumberOfTuples() >= 1 && a->GetNumberOfTuples() <= 7;
      for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
        chunks.push_back(a->GetValue(i));
    }
    vtkIdTypeArray* whole = sort->GetOrder();
    std::vector<vtkIdType> all(whole->GetPointer(0), whole->GetPointer(0) + whole->GetNumberOfTuples());
    Check(sizes && chunks == all && all.size() == 384, "chunks of 7 concatenate to GetOrder()");
  }

  // Empty input: no cells, no error; also a grid after Initialize(), whose
  // cell array is null.
  for (int initialized = 0; initialized < 2; ++initialized)
  {
    vtkNew<vtkUnstructuredGrid> empty;
    if (initialized)
    {
      empty->Initialize();
    }
    vtkNew<vtkSteinVisibilitySort> sort;
    vtkNew<vtkTest::ErrorObserver> obs;
    sort->AddObserver(vtkCommand::ErrorEvent, obs);
    sort->AddObserver(vtkCommand::WarningEvent, obs);
    sort->SetInput(empty);
    sort->SetCamera(cam);
    sort->InitTraversal();
    Check(sort->GetNextCells() == nullptr && !obs->GetError() && !obs->GetWarning(),
      initialized ? "empty input after Initialize() (null cell array): nothing, no error"
                  : "empty input: nothing, no error");
  }

  // Sorts a grid from outside, its warnings observed.
  auto sortObserved = [&](vtkUnstructuredGrid* grid, vtkSteinVisibilitySort* sort,
                        vtkTest::ErrorObserver* obs, const std::string& what) {
    sort->AddObserver(vtkCommand::WarningEvent, obs);
    sort->SetInput(grid);
    sort->SetCamera(cam);
    SetCamera(cam, outside, centre, false);
    return Traverse(sort, what);
  };

  // An unsupported cell among tetrahedra: a warning, output first, once.
  {
    MeshBuilder m = hovTest::UnitBlock(2);
    const vtkIdType a = m.AddPoint(0, 0, 2, 0), b = m.AddPoint(1, 0, 2, 0), c = m.AddPoint(1, 1, 2, 0);
    m.AddCell(VTK_TRIANGLE, { a, b, c });
    auto grid = m.Grid(false);
    vtkNew<vtkSteinVisibilitySort> sort;
    vtkNew<vtkTest::ErrorObserver> obs;
    const auto order = sortObserved(grid, sort, obs, "unsupported cell");
    const vtkIdType tri = grid->GetNumberOfCells() - 1;
    Check(obs->GetWarning() && obs->GetWarningMessage().find("first: cell " + std::to_string(tri)) != std::string::npos &&
        sort->GetNumberOfUnorderedCells() == 1 && order.front() == tri,
      "unsupported cell: warning with its id, counted, output first");
  }

  // Linear tetrahedra whose cell array is read in place, with one tet that
  // names a point that does not exist and one with a NaN corner: both are
  // bad (warning, output first) and the others sorted as without them.
  {
    MeshBuilder m = hovTest::UnitBlock(2);
    const vtkIdType np = m.Grid(false)->GetNumberOfPoints();
    const vtkIdType beyond = static_cast<vtkIdType>(std::min<long long>(VTK_ID_MAX / 4, 1LL << 40));
    const vtkIdType a = m.AddPoint(0, 0, 2, 0), b = m.AddPoint(1, 0, 2, 0);
    const vtkIdType c = m.AddPoint(1, 1, 2, 0);
    const vtkIdType nan = m.AddPoint(std::nan(""), 0, 3, 0);
    m.AddCell(VTK_TETRA, { a, b, c, np + beyond }); // read, it would crash
    m.AddCell(VTK_TETRA, { a, b, c, nan });
    auto grid = m.Grid(false);
    vtkNew<vtkSteinVisibilitySort> sort;
    vtkNew<vtkTest::ErrorObserver> obs;
    const auto order = sortObserved(grid, sort, obs, "tets with a missing point and a NaN corner");
    const vtkIdType first = grid->GetNumberOfCells() - 2;
    const bool badFirst = order.size() > 2 &&
      std::set<vtkIdType>(order.begin(), order.begin() + 2) ==
        std::set<vtkIdType>({ first, first + 1 });
    vtkNew<vtkSteinVisibilitySort> clean;
    clean->SetInput(hovTest::UnitBlock(2).Grid(false));
    clean->SetCamera(cam);
    const auto cleanOrder = Traverse(clean, "the same tets without them");
    Check(obs->GetWarning() &&
        obs->GetWarningMessage().find("first: cell " + std::to_string(first)) !=
          std::string::npos &&
        sort->GetNumberOfUnorderedCells() == 2 && badFirst &&
        std::vector<vtkIdType>(order.begin() + 2, order.end()) == cleanOrder,
      "missing point and NaN corner: warning, both output first, the rest as without them");
  }
  // Cells appended in place (the grid's MTime need not change, the cell
  // array's storage moves): the sort reads its corners from that cell array,
  // notices and sets up again: every cell, old and new, exactly once.
  {
    auto grid = hovTest::UnitBlock(3).Grid(false);
    vtkNew<vtkSteinVisibilitySort> sort;
    sort->SetInput(grid);
    sort->SetCamera(cam);
    SetCamera(cam, outside, centre, false);
    const vtkIdType before = static_cast<vtkIdType>(Traverse(sort, "tet block 3^3").size());
    const vtkMTimeType mtime = grid->GetMTime();
    const void* old = grid->GetCells()->GetConnectivityArray()->GetVoidPointer(0);
    const vtkIdType ids[4] = { 0, 1, 2, 3 };
    while (grid->GetCells()->GetConnectivityArray()->GetVoidPointer(0) == old)
    {
      grid->InsertNextCell(VTK_TETRA, 4, ids); // the same tet again: a duplicate cell
    }
    const vtkIdType added = grid->GetNumberOfCells() - before;
    std::cout << "     appended " << added << " cells, grid MTime "
              << (grid->GetMTime() == mtime ? "unchanged" : "changed") << "\n";
    SetCamera(cam, outside, centre, false);
    const auto order = Traverse(sort, "after appending cells in place");
    Check(added > 0 && static_cast<vtkIdType>(order.size()) == before + added,
      "cells appended in place: set up again, every cell once");
  }
  std::cout << (Failures ? "FAILED: " : "passed, failures: ") << Failures << "\n";
  return Failures ? 1 : 0;
}
