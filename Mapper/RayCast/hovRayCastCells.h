/**
 * @class   hov::RayCastCells
 * @brief   Converts a vtkUnstructuredGrid into the Lagrange mesh the ray
 *          caster (hov::CurvedRayCaster) takes: native Lagrange cells are
 *          copied, linear and quadratic cells are re-expressed as Lagrange
 *          cells of the same order.
 *
 * Native: VTK Lagrange tetrahedra, hexahedra, wedges (71, 72, 73), node ids
 * referenced as given (orders from HigherOrderDegrees or the node count).
 * Converted: tetrahedron 10 and voxel 11, hexahedron 12, wedge 13 (order 1),
 * quadratic tetrahedron 24, quadratic (serendipity, 20-node) hexahedron 25,
 * triquadratic hexahedron 29, quadratic wedge 26 and biquadratic-quadratic
 * wedge 32 (order 2). Each node of the Lagrange cell (its parametric
 * coordinates from hov::LagrangeBasis) gets the position and scalar of the
 * source cell's own shape functions there (vtkCell::InterpolateFunctions):
 * for the serendipity hexahedron and the 15-node wedge the missing face and
 * body nodes come from the serendipity functions, so the Lagrange cell
 * reproduces the source cell's geometry and field exactly wherever the
 * serendipity space lies inside the Lagrange space (it does: Q2 contains the
 * 20-node serendipity space, the 18-node wedge space contains the 15-node one).
 * Bezier tetrahedra, hexahedra and wedges (78, 79, 80, any order, from
 * HigherOrderDegrees or the node count) become the Lagrange cell of the same
 * type and order the same way (VTK's Bezier shape functions at the Lagrange
 * nodes): the same polynomial map and field, exactly up to rounding. Rational
 * Bezier cells (a RationalWeights point array with a weight other than 1)
 * are not polynomials and are skipped.
 * Pyramids: vtkPyramid (14) is the trilinear hexahedron with its top face
 * collapsed to the apex, and every vtkQuadraticPyramid (27) function has
 * degree <= 2 in each of r, s, t, so they become order-1 and order-2
 * Lagrange hexahedra (same InterpolateFunctions sampling) whose top nodes all
 * sit at the apex. The Jacobian vanishes there (not checked at those nodes);
 * the inversion accepts such a singular point when it maps to the target to
 * rounding.
 *
 * Skipped, counted per reason: other types (Lagrange and Bezier pyramids
 * 74/81, the 19-node pyramid 37, 2D cells, polyhedra, ...), rational Bezier
 * cells, NaN/Inf points or scalars, point ids out of range, and cells whose
 * Jacobian determinant is <= 1e-12 x size^3 at some node (inverted or
 * degenerate; sampled at the nodes, so a tangle strictly between nodes is not
 * detected here).
 *
 * Thread safety: Convert() is re-entrant (no shared state).
 * @sa hov::RayCast, hovLagrangeBasis.h
 */
#ifndef hovRayCastCells_h
#define hovRayCastCells_h

#include "vtkType.h" // vtkIdType

#include <cstdint> // 64-bit connectivity
#include <string>  // summary
#include <vector>  // arrays

class vtkDataArray;
class vtkUnstructuredGrid;

namespace hov
{
class RayCastCells
{
public:
  std::vector<double> Points, Scalars;
  std::vector<unsigned char> Types;
  std::vector<std::int64_t> Offsets, Connectivity;
  std::vector<int> Degrees; ///< empty or 3 per kept cell

  vtkIdType Cells = 0;       ///< cells of the input
  vtkIdType Native = 0;      ///< Lagrange cells kept as they are
  vtkIdType Converted = 0;   ///< linear/quadratic cells converted
  vtkIdType Unsupported = 0; ///< skipped: type not handled
  vtkIdType Rational = 0;    ///< skipped: rational Bezier cell
  int FirstUnsupportedType = -1;
  vtkIdType NonFinite = 0; ///< skipped: NaN/Inf point or scalar, bad id or node count
  vtkIdType Inverted = 0;  ///< skipped: Jacobian <= 0 at a node

  /**
   * Fill the arrays from @p grid and point scalars @p scalars (component
   * @p component, or the magnitude if -1). With @p cellScalars the array has
   * one value per cell: every cell gets its own copy of its nodes, all with
   * the cell's value (a piecewise-constant field; the same geometry).
   * Returns the number of kept cells.
   */
  vtkIdType Convert(
    vtkUnstructuredGrid* grid, vtkDataArray* scalars, int component, bool cellScalars = false);

  /// One line naming the skipped counts (empty if nothing was skipped).
  std::string Summary() const;
};
}

#endif
