/**
 * @file BenchHighOrderMeshes.h
 * @brief Generated curved Lagrange meshes for hovBenchHighOrder (issue 20):
 * an N x N x N block of the unit cube (hexahedra, or each hexahedron split
 * into 6 tetrahedra along its main diagonal, conforming), every node placed
 * by the curving map
 *   Phi(X, Y, Z) = (r cos(theta), r sin(theta), 0.8 Z + 0.15 sin(pi X) sin(pi Y)),
 *   r = 1 + 0.6 X, theta = 1.2 (Y - 0.5) + 0.3 Z,
 * (a twisted, bulged shell sector: every cell is curved), with the point
 * scalar "f" = sin(2 x) + z cos(3 y) + 0.5 x y at the node's position (not a
 * polynomial: the mesh interpolates it to the cells' order). Nodes are
 * shared between cells (merged on their exact reference-grid position).
 * Node positions in each cell come from VTK's own GetParametricCoords, so the
 * node order is VTK's.
 */
#ifndef BenchHighOrderMeshes_h
#define BenchHighOrderMeshes_h

#include "vtkSmartPointer.h" // the returned grid

class vtkUnstructuredGrid;

namespace hovBench
{
/// Lagrange tetrahedra (type 71) of @p order, 6 N^3 cells.
vtkSmartPointer<vtkUnstructuredGrid> CurvedTetMesh(int n, int order);
/// Lagrange hexahedra (type 72) of @p order, N^3 cells.
vtkSmartPointer<vtkUnstructuredGrid> CurvedHexMesh(int n, int order);
}

#endif
