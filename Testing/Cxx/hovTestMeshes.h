/**
 * @file hovTestMeshes.h
 * @brief Small tetrahedral meshes built by hand for the VTK-level tests
 * (TestBadInput*, TestOpenGL*, ...): a builder of points, scalars and cells,
 * and the unit block of Kuhn-split cubes most of those tests render.
 */
#ifndef hovTestMeshes_h
#define hovTestMeshes_h

#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkUnstructuredGrid.h" // Grid() returns one

#include <array>
#include <functional>
#include <vector>

namespace hovTest
{
/// A hand-built unstructured grid.
struct MeshBuilder
{
  std::vector<std::array<double, 3>> Points;
  std::vector<double> Scalars;
  std::vector<int> Types;
  std::vector<std::vector<vtkIdType>> Cells;

  vtkIdType AddPoint(double x, double y, double z, double s);
  void AddCell(int type, const std::vector<vtkIdType>& ids);
  /// Six times the signed volume of the tetrahedron @p t (VTK orientation).
  double SignedVolume6(const std::vector<vtkIdType>& t) const;
  /// A tetrahedron with VTK's positive orientation (vertex 3 on the side of
  /// the right-hand normal of 0,1,2), or inverted if @p inverted.
  void AddTet(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d, bool inverted = false);
  /// nx*ny*nz cubes over [o, o+size], each split into 6 tetrahedra (Kuhn:
  /// conforming), scalar f(x,y,z) at the points.
  void AddTetBlock(int nx, int ny, int nz, const double o[3], const double size[3],
    const std::function<double(double, double, double)>& f, bool inverted = false);
  /// A lone tetrahedron with its own four points and scalars @p svals.
  void AddLooseTet(const double p[4][3], const double svals[4]);
  /// Appends the points and cells of @p other (its point ids shifted past ours;
  /// no points are merged, so the pieces stay disconnected).
  void Append(const MeshBuilder& other);
  /// The grid; point scalars "s" (double) are the active scalars unless
  /// @p withScalars is false.
  vtkSmartPointer<vtkUnstructuredGrid> Grid(bool withScalars = true) const;
};

/// The default linear scalar field of the test blocks.
double DefaultField(double x, double y, double z);

/// Unit cube [0,1]^3 of n^3 Kuhn cubes with DefaultField scalars (range [0, 1.75]).
MeshBuilder UnitBlock(int n = 2, bool inverted = false);
}

#endif
