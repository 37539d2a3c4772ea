/**
 * @file hovCellShapes.h
 * @brief Shape functions of VTK 9.1's linear and quadratic 3D cells in VTK's
 * node order and parametric coordinates, their derivatives, the geometry map
 * of straight-edged cells and its inverse (Newton).
 *
 * Cells (VTK type constant = enum value): tetrahedron (10), voxel (11),
 * hexahedron (12), wedge (13), pyramid (14), quadratic tetrahedron (24),
 * quadratic hexahedron (25, 20-node serendipity), quadratic wedge (26,
 * 15 nodes), quadratic pyramid (27, 13 nodes), triquadratic hexahedron
 * (29, 27 nodes). The formulas are VTK 9.1's InterpolationFunctions
 * (vtkTetra ... vtkTriQuadraticHexahedron), transcribed once as a template
 * and evaluated in double, in forward-mode dual numbers (exact derivatives)
 * and in polynomials of one variable (CellShapeFunctionsAlongLine).
 *
 * Parametric domains (VTK's): tetrahedra r,s,t >= 0, r+s+t <= 1; hexahedra,
 * voxels and pyramids the unit cube (the pyramid is VTK's collapsed cube: at
 * t = 1 every (r,s) is the apex); wedges r,s >= 0, r+s <= 1, 0 <= t <= 1.
 *
 * Geometry (HIAC section 5; issue 4: straight edges): the position is
 * interpolated from the CORNERS only with the linear cell's functions
 * (GeometryShape); a quadratic cell's mid-edge/face/centre nodes are
 * assumed to lie where that map puts them. points[] always holds all nodes
 * (3 doubles each, VTK order); only the first CellCornerCount are read.
 *
 * Thread safety: stateless, re-entrant; no allocation.
 * @sa hovCellRestriction.h, hovRayCell.h
 */
#ifndef hovCellShapes_h
#define hovCellShapes_h

#include "hovConfig.h"
#include "hovPolynomial.h" // CellShapeFunctionsAlongLine output

namespace hov
{
/// Supported cells; the values are VTK's cell type constants.
enum class CellShape : int
{
  Tetra = 10,
  Voxel = 11,
  Hexahedron = 12,
  Wedge = 13,
  Pyramid = 14,
  QuadraticTetra = 24,
  QuadraticHexahedron = 25,
  QuadraticWedge = 26,
  QuadraticPyramid = 27,
  TriQuadraticHexahedron = 29
};

/// Largest node count of a supported cell (triquadratic hexahedron).
constexpr int MaxCellNodes = 27;

/// True if @p vtkCellType is one of the CellShape values.
HOV_EXPORT bool IsSupportedCellType(int vtkCellType);

/// Number of nodes (4, 8, 8, 6, 5, 10, 20, 15, 13, 27).
HOV_EXPORT int CellNodeCount(CellShape shape);

/// The linear cell whose map from the corners is the geometry.
HOV_EXPORT CellShape GeometryShape(CellShape shape);

/// Number of corners (nodes of GeometryShape).
HOV_EXPORT int CellCornerCount(CellShape shape);

/// Parametric coordinates of node @p node (VTK's GetParametricCoords).
HOV_EXPORT void CellNodeParametricCoords(CellShape shape, int node, double pc[3]);

/// A parametric point well inside the cell (centroid of the corners' pcoords).
HOV_EXPORT void CellParametricCenter(CellShape shape, double pc[3]);

/// Shape functions w[CellNodeCount] at @p pc (VTK's InterpolationFunctions).
HOV_EXPORT void CellShapeFunctions(CellShape shape, const double pc[3], double* w);

/**
 * Derivatives dw/dr, dw/ds, dw/dt in VTK's layout: derivs[i], derivs[n + i],
 * derivs[2n + i] for node i, n = CellNodeCount. Linear cells (the geometry
 * of every cell, so Newton's inner loop): closed forms evaluated in the dual
 * numbers' order, the same values for finite pc (up to the sign of a zero;
 * where the dual path meets inf * 0 they stay finite); quadratic
 * cells: dual numbers (exact differentiation of VTK's formulas).
 */
HOV_EXPORT void CellShapeDerivatives(CellShape shape, const double pc[3], double* derivs);

namespace detail
{
/// CellShapeDerivatives by dual numbers for every shape (the reference of
/// the linear closed forms; TestCellShapes).
HOV_EXPORT void CellShapeDerivativesDual(CellShape shape, const double pc[3], double* derivs);
}

/**
 * Shape functions along the parametric line pc(y) = @p pcStart + y @p pcStep:
 * w[i] receives w_i(pc(y)) as a polynomial in y (degree <= 6 for these cells:
 * 1 linear tetrahedron, 2 quadratic tetrahedron/wedge, 3 hexahedron, 4-6 the
 * quadratic hexahedra and pyramids), by direct expansion in double.
 */
HOV_EXPORT void CellShapeFunctionsAlongLine(
  CellShape shape, const double pcStart[3], const double pcStep[3], Polynomial* w);

/// Sum of w_i(pc) values[i] (the interpolated scalar).
HOV_EXPORT double InterpolateCellScalar(CellShape shape, const double* values, const double pc[3]);

/**
 * How far @p pc lies outside the parametric domain, in parametric units
 * (max over the domain's bounding inequalities; <= 0 inside).
 */
HOV_EXPORT double ParametricDistanceOutside(CellShape shape, const double pc[3]);

/// Position x(pc) from the corners (GeometryShape's map) and, if
/// @p jacobian is given, its columns dx/dr, dx/ds, dx/dt (row-major 3x3, J[i][j] = dx_i/dpc_j).
HOV_EXPORT void EvaluateGeometry(
  CellShape shape, const double* points, const double pc[3], double x[3], double* jacobian);

/// Newton settings of InvertGeometry.
struct GeometryInversionSettings
{
  /// Stop when the parametric step is below this (max norm).
  double StepTolerance = 1e-14;
  int MaxIterations = 40;
};

/**
 * Parametric coordinates of @p x: Newton on x(pc) = x, starting from @p pc
 * (in: guess, out: result), then, if that fails, from the centre and from
 * the 8 points (0.25|0.75)^3 clamped into the domain. Converged when the
 * step is below StepTolerance (the result is then within ~1e-14 of the
 * exact inverse for well-shaped cells; near a pyramid apex the Jacobian
 * degenerates and only the converged position residual is guaranteed).
 * Each Newton step is limited to a parametric length of 1 (damping far from
 * the solution). Returns false (pc = best iterate) if no start converged,
 * the Jacobian is singular, or input is not finite.
 */
HOV_EXPORT bool InvertGeometry(CellShape shape, const double* points, const double x[3],
  double pc[3], const GeometryInversionSettings& settings = GeometryInversionSettings());

}

#endif
