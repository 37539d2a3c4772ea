// vtkSteinVisibilitySort on random jittered tetrahedral blocks and on a
// conforming mixed mesh (hexahedra, voxels, wedges, pyramids, tetrahedra),
// perspective and parallel views from random directions and with a model
// transform: every cell exactly once, zero violations found by the
// independent ray/face oracle (hovSortOracle) in both directions. The same
// meshes through vtkCellCenterDepthSort: its violations are printed (the
// jittered boundary makes the blocks non-convex, so it must show some).
#include "hovSortCases.h"
#include "hovTestScenes.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>
#include <string>

using namespace hovTest;

int TestSortRandomMeshes(int, char*[])
{
  Checker ck;
  vtkNew<vtkMatrix4x4> model;
  TestModelTransform(model);
  std::vector<SortCase> cases;
  PrintSortHeader();
  struct Mesh
  {
    std::string Name;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
  };
  const Mesh meshes[] = { { "random tets 4^3", RandomTetMesh(4, 11) },
    { "random tets 9^3", RandomTetMesh(9, 12) }, { "mixed", MixedMesh(5) } };
  for (const Mesh& m : meshes)
  {
    double b[6];
    m.Grid->GetBounds(b);
    std::vector<SortView> views = RandomViews(b, 6, 100 + static_cast<unsigned>(cases.size()));
    for (size_t v = 0; v < views.size(); ++v)
    {
      // The last two views also carry the model transform (the camera then
      // looks at the untransformed box from far enough to see it).
      vtkMatrix4x4* mt = v + 2 >= views.size() ? model.Get() : nullptr;
      if (mt)
      {
        double c[4] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]), 1 }, w[4];
        mt->MultiplyPoint(c, w);
        for (int j = 0; j < 3; ++j)
        {
          const double shift = w[j] - views[v].FocalPoint[j];
          views[v].FocalPoint[j] += shift;
          views[v].Position[j] += shift;
        }
      }
      SortCase c = RunSortCase(m.Name, m.Grid, views[v], mt);
      PrintSortCase(c);
      CheckExactCase(ck, c);
      cases.push_back(c);
    }
  }
  const vtkIdType center = CenterViolations(cases);
  std::cout << "  vtkCellCenterDepthSort: " << center << " violations (ray pairs + faces) in "
            << cases.size() << " cases\n";
  ck.Check(center > 0, "vtkCellCenterDepthSort shows violations on the jittered meshes");
  return ck.Result();
}
