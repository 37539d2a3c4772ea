// The axis-aligned face planes of vtkSteinVisibilitySort's geometry
// (hovStein::Geometry::AxisPlane, Filters/hovSteinGeometry.h): the exact faces
// whose corners share one coordinate are marked, and no other, counted
// independently from VTK's own cell faces; for each marked face,
// hov::AxisOrient3d (two comparisons, used by Obstructs) equals hov::Orient3d
// of its exact triangle for every point of the mesh, including the points on
// the plane. Meshes: grid-aligned Kuhn tetrahedra (many marked faces, points
// exactly on their planes), the same jittered (the count must agree whatever
// it is), and an axis-aligned hexahedral grid (every quad face marked).
#include "hovGeometricPredicates.h"
#include "hovSortMeshes.h"
#include "hovSteinGeometry.h"
#include "hovTestMeshes.h"
#include "hovTestScenes.h"

#include "vtkCell.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
/// Faces of the cells of @p grid whose points all share one coordinate exactly.
long AlignedFaces(vtkUnstructuredGrid* grid)
{
  long count = 0;
  ForEachVTKFace(grid, [&](vtkIdType, const std::vector<vtkIdType>& ids) {
    for (int k = 0; k < 3; ++k)
    {
      bool same = true;
      const double first = grid->GetPoint(ids[0])[k];
      for (size_t i = 1; i < ids.size(); ++i)
      {
        same = same && grid->GetPoint(ids[i])[k] == first;
      }
      if (same)
      {
        ++count;
        break;
      }
    }
  });
  return count;
}

/// Checks the marks of @p grid; @p expected: "some", "none" or "all" faces marked.
void Run(Checker& ck, const std::string& name, vtkUnstructuredGrid* grid, const std::string& expected)
{
  hovStein::Geometry g;
  g.Build(grid, nullptr);
  long faces = 0, exact = 0, marked = 0, onPlane = 0, mismatches = 0;
  for (vtkIdType c = 0; c < g.NumberOfCells; ++c)
  {
    const hovStein::Shape& s = hovStein::GetShape(g.Kinds[c]);
    for (int f = 0; f < s.NumFaces; ++f)
    {
      ++faces;
      if ((g.FaceCode(c, f) & 3) != hovStein::FaceExact)
      {
        continue;
      }
      ++exact;
      int axis = -1, sigma = 0;
      if (!g.AxisPlane(c, f, axis, sigma))
      {
        continue;
      }
      ++marked;
      vtkIdType t[3];
      g.ExactTriple(c, f, t);
      const double *a = g.Point(t[0]), *b = g.Point(t[1]), *cc = g.Point(t[2]);
      for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
      {
        const int exactSide = hov::Orient3d(a, b, cc, g.Point(p));
        onPlane += exactSide == 0;
        mismatches += hov::AxisOrient3d(axis, sigma, a, g.Point(p)) != exactSide;
      }
    }
  }
  const long independent = AlignedFaces(grid);
  std::cout << "  " << name << ": faces " << faces << ", exact " << exact << ", marked " << marked
            << " (independent count " << independent << "), points on marked planes " << onPlane
            << ", AxisOrient3d != Orient3d " << mismatches << "\n";
  ck.Check(exact > 0, name + ": geometry built, exact faces found");
  ck.Check(marked == independent, name + ": marked faces = faces whose corners share a coordinate");
  ck.Check(mismatches == 0, name + ": AxisOrient3d equals Orient3d on every mesh point");
  if (expected == "some")
  {
    ck.Check(marked > 0 && marked < faces && onPlane > marked, name + ": some faces marked, points on them");
  }
  else if (expected == "all")
  {
    ck.Check(marked == faces, name + ": every face marked");
  }
  else
  {
    ck.Check(marked == 0, name + ": no face marked");
  }
}
}

int TestSteinAxisPlanes(int, char*[])
{
  Checker ck;
  const double o[3] = { -1.25, 0.5, 3.0 }, size[3] = { 2.0, 1.5, 0.75 };
  Run(ck, "aligned Kuhn tetrahedra", JitteredTetBlock(3, 3, 3, o, size, 0.0, 7).Grid(), "some");
  Run(ck, "axis-aligned hexahedra", JitteredHexBlock(3, 0.0), "all");
  // Jittered: only the block's outer faces may keep a shared coordinate;
  // the count must still agree.
  vtkSmartPointer<vtkUnstructuredGrid> jittered = JitteredTetBlock(3, 3, 3, o, size, 0.3, 7).Grid();
  Run(ck, "jittered Kuhn tetrahedra", jittered, AlignedFaces(jittered) > 0 ? "some" : "none");
  return ck.Result();
}
