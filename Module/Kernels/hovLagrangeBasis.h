/**
 * @file hovLagrangeBasis.h
 * @brief Shape functions (and derivatives) of VTK 9.1's Lagrange tetrahedra,
 * hexahedra and wedges (cell types 71, 72, 73) of any order 1..10, in VTK's
 * node order and parametric coordinates.
 *
 * Shape functions (the formulas of vtkLagrangeInterpolation,
 * vtkLagrangeTetra and vtkLagrangeTriangle, evaluated in double):
 *  - hexahedron of orders (p0, p1, p2): w = l_i(r) l_j(s) l_k(t), l the 1D
 *    Lagrange polynomials of order p_d on the equispaced nodes m / p_d;
 *    node index = vtkHigherOrderHexahedron::PointIndexFromIJK(i, j, k);
 *  - tetrahedron of order n (from the point count (n+1)(n+2)(n+3)/6):
 *    barycentric tau = (r, s, t, 1 - r - s - t), w = prod_d
 *    Eta(n, lambda_d, tau_d), Eta(n, c, x) = prod_{i=1}^{c} (n x - i + 1) / i
 *    (Silvester 1969), lambda the node's barycentric index;
 *    node index = vtkHigherOrderTetra::Index(lambda); the 15-node quadratic
 *    tetrahedron (VTK's FIFTEEN_POINT_TETRA) uses VTK's closed form;
 *  - wedge of orders (p, p, q): w = Eta(p, i, r) Eta(p, j, s)
 *    Eta(p, p-i-j, 1-r-s) l_k(t); node index =
 *    vtkHigherOrderWedge::PointIndexFromIJK(i, j, k); the 21-node quadratic
 *    wedge (VTK_21_POINT_WEDGE) uses VTK's closed form.
 * Derivatives are exact (analytic product rule; the two closed forms in
 * forward-mode dual numbers). Layout as VTK's usual InterpolateDerivs:
 * derivs[d * n + i] = dw_i / dpc_d (note: VTK 9.1's vtkLagrangeHexahedron::
 * InterpolateDerivs returns them interleaved per node, derivs[3 i + d]).
 * Measured (TestLagrangeVTKShapes): shape functions, derivatives, node
 * numbering and node coordinates agree with VTK 9.1's classes to 4.7e-16
 * (relative) for all three types, orders 1..8, anisotropic orders and the
 * two closed-form cells.
 *
 * Orders: tetrahedra from the point count; hexahedra and wedges from the
 * HigherOrderDegrees tuple if given, else the uniform order that matches the
 * point count (VTK's rule). Orders > MaxLagrangeOrder (10) are rejected.
 *
 * Parametric domains: hexahedron [0,1]^3; tetrahedron r,s,t >= 0,
 * r+s+t <= 1; wedge r,s >= 0, r+s <= 1, 0 <= t <= 1.
 *
 * Thread safety: Initialize() is not thread safe; every const method is
 * (one basis per distinct (shape, order) is shared by all cells and threads).
 * @sa hovLagrangeCell.h (geometry, field, inversion), vtkLagrangeHexahedron
 */
#ifndef hovLagrangeBasis_h
#define hovLagrangeBasis_h

#include "hovConfig.h"

#include <array>  // node index table entries
#include <string> // Initialize() messages
#include <vector> // node index table

namespace hov
{
/// Lagrange cells; the values are VTK's cell type constants.
enum class LagrangeShape : int
{
  Tetra = 71,
  Hexahedron = 72,
  Wedge = 73
};

/// Largest order per parametric direction.
constexpr int MaxLagrangeOrder = 10;

/// Node count of a Lagrange cell of @p shape and orders (p0, p1, p2) (the
/// general layout; tetrahedra use p0). 0 for invalid orders.
HOV_EXPORT int LagrangeNodeCount(LagrangeShape shape, const int order[3]);

class HOV_EXPORT LagrangeBasis
{
public:
  /**
   * Set up for a cell of @p shape with @p nodeCount nodes; @p degrees (may
   * be null) is the cell's HigherOrderDegrees tuple. False, with a message,
   * for an unsupported type, an order above MaxLagrangeOrder, degrees that
   * do not match the point count, or wedge degrees p0 != p1.
   */
  bool Initialize(LagrangeShape shape, int nodeCount, const int* degrees = nullptr,
    std::string* message = nullptr);

  bool IsInitialized() const { return this->NodeCount > 0; }
  LagrangeShape GetShape() const { return this->Shape; }
  /// Orders per parametric direction (tetrahedra: n, n, n).
  const int* GetOrder() const { return this->Order; }
  int GetNodeCount() const { return this->NodeCount; }
  /// The 15-node tetrahedron or 21-node wedge (closed-form shape functions).
  bool IsSpecial() const { return this->Special; }

  /**
   * Degree of the shape functions along a straight line in parametric
   * space (tetrahedron n, wedge p + q, hexahedron p0 + p1 + p2; the special
   * cells 4 and 6).
   */
  int GetLineDegree() const;

  /// Parametric coordinates of node @p node.
  void NodeParametricCoords(int node, double pc[3]) const;
  /// A parametric point well inside (the centroid of the domain).
  void ParametricCenter(double pc[3]) const;
  /// How far @p pc lies outside the domain (max of the bounding
  /// inequalities, parametric units; <= 0 inside).
  double DistanceOutside(const double pc[3]) const;

  /// Shape functions w[GetNodeCount()] at @p pc.
  void Functions(const double pc[3], double* w) const;
  /// Shape functions and derivatives (layout in the file doc); @p w may be null.
  void FunctionsAndDerivatives(const double pc[3], double* w, double* derivs) const;

  /**
   * Interpolate @p components values per node (values[node * components + c])
   * at @p pc: @p value[c] and, if @p gradient is given, gradient[3 c + d] =
   * d value_c / d pc_d. Sum-factorised over the node indices (one weight
   * product per node; hovLagrangeSumFactorisation.cxx), the special cells by
   * the node loop; no scratch storage. Agrees with the weights of
   * FunctionsAndDerivatives() to rounding. components <= 4.
   */
  void Interpolate(const double pc[3], const double* values, int components, double* value,
    double* gradient) const;

  /// The node's index triple (hexahedron/wedge: i, j, k; tetrahedron: the
  /// barycentric index lambda0..3 with tau as in the file doc).
  const std::array<int, 4>& NodeIndex(int node) const { return this->Nodes[node]; }

private:
  template <class Visitor>
  void VisitNodes(const double pc[3], bool derivatives, Visitor&& visit) const;
  /// Interpolate() by the node loop for @p C components, gradient if @p G.
  template <int C, bool G>
  void InterpolateNodes(const double pc[3], const double* values, double* value,
    double* gradient) const;
  /// Interpolate() by sum factorisation over the node indices, every shape
  /// but the special cells (hovLagrangeSumFactorisation.cxx).
  void InterpolateFactorised(const double pc[3], const double* values, int components,
    double* value, double* gradient) const;
  template <class Visitor>
  void VisitSpecial(const double pc[3], Visitor&& visit) const;

  LagrangeShape Shape = LagrangeShape::Hexahedron;
  int Order[3] = { 0, 0, 0 };
  int NodeCount = 0;
  bool Special = false;
  std::vector<std::array<int, 4>> Nodes;
  /// The nodes in the order of the sums: tetrahedra (a, b, c) with a, b, c
  /// ascending (a + b + c <= n); hexahedra and wedges (i, j, k) with k, j, i.
  std::vector<int> SumNodes;
};
}

#endif
