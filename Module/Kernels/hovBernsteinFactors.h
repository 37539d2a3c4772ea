/**
 * @file hovBernsteinFactors.h
 * @brief The Bernstein bases of the factors of VTK's Lagrange cells (a line,
 * a triangle, a tetrahedron of some order) and their conversion from values
 * at the factor's equispaced nodes: M[j][a] = B_a(x_j), T = M^-1 (Gauss-Jordan
 * with partial pivoting in long double), b = T f. Shared by the field hull
 * (hovLagrangeHull.h: the cell's factors) and the triangular face nets of the
 * ray caster (hovCurvedTriangleNets.h). Internal (namespace hov::detail).
 *
 * Thread safety: pure functions.
 */
#ifndef hovBernsteinFactors_h
#define hovBernsteinFactors_h

#include <array>  // multi-indices
#include <vector> // matrices

namespace hov
{
namespace detail
{
/// n! in double.
double Factorial(int n);

/// x^k for k >= 0.
double Power(double x, int k);

/// Inverts the n x n row-major @p m in place (Gauss-Jordan, partial pivoting,
/// long double); false if singular.
bool InvertDense(std::vector<long double>& m, int n);

/// A factor: kind (3: tetrahedron, 2: triangle, 1: line) and order.
struct FactorShape
{
  int Kind, Order;
  /// Number of basis functions (and of equispaced nodes).
  int Size() const;
  /// The multi-indices of the factor's basis, in a fixed order: a outer, then
  /// b, then c (a triangle's (a, b): the powers of x[0] and x[1]).
  void Indices(std::vector<std::array<int, 3>>& out) const;
  /// Bernstein function with multi-index @p m at coordinates @p x.
  double Function(const std::array<int, 3>& m, const double* x) const;
};

/**
 * The factor's multi-indices (@p indices, FactorShape::Indices), the collocation
 * matrix M[j][a] = B_a(indices[j] / order) (row-major) and its inverse @p t;
 * false if M is singular.
 */
bool EquispacedFactorMatrices(const FactorShape& shape, std::vector<std::array<int, 3>>& indices,
  std::vector<long double>& m, std::vector<long double>& t);
}
}

#endif
