/**
 * @file BenchSortMeshes.h
 * @brief Boundary-heavy tetrahedral meshes for hovBenchSort (issue 20): a
 * finned heatsink on a regular grid of unit cubes, each cube split into the 6
 * tetrahedra around its main diagonal (Kuhn; conforming). The base is
 * @p base cube layers thick over nx x ny cubes; @p fins fins along y, each
 * @p thickness cubes thick and @p height layers high, separated by gaps of
 * @p gap cubes (nx = fins (thickness + gap)). Every fin cell touches the
 * mesh boundary when thickness <= 2 (the fins' faces are coplanar across
 * fins: exact zeros for the predicates).
 */
#ifndef BenchSortMeshes_h
#define BenchSortMeshes_h

#include "vtkSmartPointer.h" // the returned grid

class vtkUnstructuredGrid;

namespace hovBench
{
vtkSmartPointer<vtkUnstructuredGrid> Heatsink(
  int fins, int thickness, int gap, int ny, int base, int height);
}

#endif
