// vtkSteinVisibilitySort on non-convex and non-conforming meshes: a block with
// a square hole, a U (notched block), disconnected blocks, a sliding
// (non-conforming) interface and a log pile of long thin interleaved wedges;
// random perspective/parallel views, views from inside the hole and the notch
// (eye inside the bounding box), and a model transform. Stein: every cell
// once, zero oracle violations (rays and interior faces) in both directions.
// vtkCellCenterDepthSort on the same cases: violations printed, and each
// non-convex mesh must make it fail somewhere (else the mesh is too easy).
#include "hovSortCases.h"
#include "hovTestScenes.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
struct Mesh
{
  std::string Name;
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  std::vector<SortView> Inside;
  bool MustFoolCenterSort;
};

std::vector<Mesh> Meshes()
{
  std::vector<Mesh> m;
  const double e1[3] = { 0.5, 0.5, 0.5 }, f1[3] = { 0.9, 0.6, 0.2 };
  const double e2[3] = { 0.45, 0.55, 0.85 }, f2[3] = { 0.52, 0.4, 0.0 };
  m.push_back({ "holed block", HoledBlock(9, 21),
    { InsideView("inside hole, oblique", e1, f1), InsideView("inside hole, down", e2, f2) },
    true });
  const double e3[3] = { 0.5, 0.6, 0.5 }, f3[3] = { 0.1, 0.5, 0.3 };
  const double e4[3] = { 0.5, 0.8, 0.5 }, f4[3] = { 0.9, 0.2, 0.9 };
  m.push_back({ "notched block", NotchedBlock(9, 22),
    { InsideView("inside notch, wall", e3, f3), InsideView("inside notch, oblique", e4, f4) },
    true });
  m.push_back({ "disconnected", DisconnectedBlocks(23), {}, true });
  m.push_back({ "sliding interface", SlidingInterface(24), {}, false });
  m.push_back({ "log pile", InterleavedSticks(8, 10), {}, true });
  return m;
}
}

int TestSortNonConvex(int, char*[])
{
  Checker ck;
  vtkNew<vtkMatrix4x4> model;
  TestModelTransform(model);
  PrintSortHeader();
  unsigned seed = 300;
  for (const Mesh& m : Meshes())
  {
    double b[6];
    m.Grid->GetBounds(b);
    std::vector<SortView> views = RandomViews(b, 4, ++seed);
    views.insert(views.end(), m.Inside.begin(), m.Inside.end());
    std::vector<SortCase> cases;
    for (size_t v = 0; v < views.size(); ++v)
    {
      SortCase c = RunSortCase(m.Name, m.Grid, views[v], nullptr);
      PrintSortCase(c);
      CheckExactCase(ck, c);
      cases.push_back(c);
    }
    // One more: the model transform, the camera moved with the mesh.
    SortView moved = views[0];
    double c0[4] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]), 1 }, w[4];
    model->MultiplyPoint(c0, w);
    for (int j = 0; j < 3; ++j)
    {
      moved.Position[j] += w[j] - moved.FocalPoint[j];
      moved.FocalPoint[j] = w[j];
    }
    SortCase c = RunSortCase(m.Name, m.Grid, moved, model);
    PrintSortCase(c);
    CheckExactCase(ck, c);
    cases.push_back(c);
    const vtkIdType center = CenterViolations(cases);
    std::cout << "  -> " << m.Name << ": vtkCellCenterDepthSort " << center
              << " violations (ray pairs + faces) over " << cases.size() << " views\n";
    if (m.MustFoolCenterSort)
    {
      ck.Check(center > 0, m.Name + ": vtkCellCenterDepthSort has violations (" +
          std::to_string(center) + ")");
    }
  }
  return ck.Result();
}
