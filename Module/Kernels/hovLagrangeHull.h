/**
 * @file hovLagrangeHull.h
 * @brief A rigorous, tight range of a Lagrange cell's interpolated field over
 * the whole cell, from the field's Bernstein-Bezier coefficients on the
 * cell's own domain (convex hull property), at O(N^2) per cell.
 *
 * The Lagrange shape functions of VTK's tetrahedra (order n), hexahedra
 * (p0, p1, p2) and wedges (p, p, q) span exactly the polynomial space of the
 * Bernstein basis of the same shape and degrees:
 *  - tetrahedron: B_a(tau) = n! / (a0! a1! a2! a3!) prod_d tau_d^a_d,
 *    tau = (r, s, t, 1 - r - s - t), |a| = n;
 *  - hexahedron: B_i^p0(r) B_j^p1(s) B_k^p2(t), B_i^p(x) = C(p,i) x^i (1-x)^(p-i);
 *  - wedge: the triangle's B_(i,j,p-i-j)(r, s, 1-r-s) times B_k^q(t).
 * These are non-negative on the cell and sum to 1, so the field
 * f = sum_a b_a B_a lies in [min b, max b] on the cell (and equals a vertex
 * value at every vertex). The coefficients are b = T f_nodes with T = M^-1,
 * M[node][a] = B_a(pc_node). Both bases are tensor products of factors (the
 * tetrahedron: one factor; the wedge: triangle x line; the hexahedron: three
 * lines), so T is the Kronecker product of the factors' inverses, each
 * inverted once per basis in long double and applied along its axis:
 * O(N (sum of factor sizes)) per cell (O(N^2) for tetrahedra).
 *
 * Rounding: each coefficient carries the bound 2 (S + 2) eps sum_j |T_aj f_j|
 * + rho sum_j |T_aj| max|f|, S the sum of the factor sizes, rho the sum over
 * the factors of 2 max row sum |I - M_d T_d| with the rounded T_d (measured in
 * long double when T_d is made; M^-1 f - T f = T R (I - R)^-1 f, to first
 * order in the factors' residuals); the hull is widened by that and by
 * OutsideSlack x (max b - min b), for points within ~1e-10 (parametric)
 * outside the cell, where ray intervals may end (their ~1e-12 accuracy).
 *
 * Not supported (Initialize returns false): the 15-node tetrahedron and the
 * 21-node wedge (their spaces are not full Bernstein spaces); callers use the
 * looser CellDerivativeBounds::FieldMin/FieldMax there.
 *
 * Measured (TestLagrangeHull): coefficients reproduce the interpolant at
 * random points to <= 1.2e-12 relative (orders 1..8, every type); dense
 * samples never leave the hull, which exceeds the sampled range by <= 44%
 * for smooth fields (quadratic tetrahedron; node noise makes high orders
 * much looser); linear fields: the vertex range widened by OutsideSlack.
 *
 * Thread safety: Initialize() is not thread safe; Hull() and Coefficients()
 * are (const).
 * @sa hovLagrangeBasis.h, hovEnclosure.h (CellDerivativeBounds)
 */
#ifndef hovLagrangeHull_h
#define hovLagrangeHull_h

#include "hovConfig.h"
#include "hovLagrangeBasis.h"

#include <vector> // the conversion matrix

namespace hov
{
class HOV_EXPORT LagrangeHull
{
public:
  /// Relative widening of the hull for points just outside the cell (see file doc).
  static constexpr double OutsideSlack = 1e-8;

  /// Build T for @p basis (any order; O(N^3) once). False for the special cells.
  bool Initialize(const LagrangeBasis& basis);
  bool IsInitialized() const { return this->N > 0; }
  int GetSize() const { return this->N; }

  /// Bernstein-Bezier coefficients b[N] of the field with node values @p f (VTK node order).
  void Coefficients(const double* f, double* b) const;

  /// Rigorous range [@p lo, @p hi] of the field with node values @p f over the cell.
  void Hull(const double* f, double& lo, double& hi) const;

  /// Bernstein basis function @p a at @p pc (for tests; same indexing as Coefficients).
  double BasisFunction(int a, const double pc[3]) const;

  /// Largest node count (a hexahedron of order MaxLagrangeOrder).
  static constexpr int MaxNodes =
    (MaxLagrangeOrder + 1) * (MaxLagrangeOrder + 1) * (MaxLagrangeOrder + 1);

private:
  /// One tensor factor: the inverse of its nodes-by-basis matrix.
  struct Factor
  {
    int Size = 0;
    std::vector<double> T; ///< Size x Size, row-major
  };
  /// Applies the factors to @p v (tensor layout; @p absolute: |T_d| instead of T_d).
  void Apply(double* v, bool absolute) const;
  /// The factor basis function @p a of factor @p d at the factor's coordinates.
  double FactorFunction(int d, int a, const double* x) const;

  int N = 0;
  int NumFactors = 0;
  Factor Factors[3];
  double Residual = 0.0;      ///< rho of the file doc (+ eps)
  double GammaSize = 0.0;     ///< S of the file doc
  std::vector<int> Layout;    ///< node -> position in the tensor layout
  std::vector<double> RowAbs; ///< per coefficient (tensor layout): sum_j |T_aj|
  LagrangeBasis Basis;
};
}

#endif
