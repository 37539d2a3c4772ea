/**
 * @file hovBernstein.h
 * @brief Polynomials of one variable in Bernstein form on [0, 1] (degree <=
 * 30): evaluation, subdivision, rigorous range bounds, products, conversion
 * to and from the monomial basis, degree-<=8 approximation with a rigorous
 * error bound, and real-root isolation.
 *
 * b(y) = sum_{j=0}^{n} B[j] C(n,j) y^j (1-y)^(n-j), y in [0, 1].
 * A Lagrange cell's field restricted to a straight line in parametric space
 * is such a polynomial (degree = the cell's total order along the line: tet
 * p, wedge p + q, hexahedron p0 + p1 + p2; hovLagrangeRestriction.h), which
 * is why the degree goes beyond hovPolynomial's 9.
 *
 * Guarantees used by the enclosures (hovEnclosure.h):
 *  - convex hull: min_j B[j] <= b(y) <= max_j B[j] on [0, 1], and B[0] =
 *    b(0), B[n] = b(1) exactly (BernsteinRange);
 *  - subdivision (de Casteljau, only convex combinations: every computed
 *    coefficient has rounding error <= n eps max|B|) tightens the hull
 *    quadratically in the interval width;
 *  - Descartes' rule for the Bernstein basis: the number of roots of b in
 *    (0, 1), with multiplicity, is at most the number of sign changes of the
 *    B[j] and has the same parity (BernsteinRoots relies on 0 and 1).
 *
 * Thread safety: stateless, re-entrant; no allocation.
 * @sa hovPolynomial.h, hovLagrangeRestriction.h, hovEnclosure.h
 */
#ifndef hovBernstein_h
#define hovBernstein_h

#include "hovConfig.h"
#include "hovPolynomial.h" // monomial conversion

namespace hov
{
/// Largest Bernstein degree: a hexahedron of order 10 along a line.
constexpr int MaxBernsteinDegree = 30;

/// b(y) = sum_j B[j] C(n,j) y^j (1-y)^(n-j) on y in [0, 1], n = Degree.
struct BernsteinPolynomial
{
  int Degree = 0;
  double B[MaxBernsteinDegree + 1] = {};
};

/// Binomial coefficient C(n, k) for 0 <= k <= n <= MaxBernsteinDegree (exact), else 0.
HOV_EXPORT double Binomial(int n, int k);

/// b(y) by de Casteljau's algorithm (convex combinations; any real y).
HOV_EXPORT double EvaluateBernstein(const BernsteinPolynomial& b, double y);

/// b(y) and b'(y) (de Casteljau; the derivative from the last two stages).
HOV_EXPORT void EvaluateBernsteinWithDerivative(
  const BernsteinPolynomial& b, double y, double& value, double& slope);

/// Split at @p y: @p left is b on [0, y], @p right b on [y, 1], each
/// re-parametrised to [0, 1]. Either output may be null.
HOV_EXPORT void SubdivideBernstein(const BernsteinPolynomial& b, double y,
  BernsteinPolynomial* left, BernsteinPolynomial* right);

/// b on [y0, y1] (0 <= y0 < y1 <= 1) re-parametrised to [0, 1].
HOV_EXPORT BernsteinPolynomial RestrictBernstein(
  const BernsteinPolynomial& b, double y0, double y1);

/// The convex-hull bound: lo = min_j B[j], hi = max_j B[j] (see file doc).
HOV_EXPORT void BernsteinRange(const BernsteinPolynomial& b, double& lo, double& hi);

/**
 * A tighter range bound: the hull of the pieces of b on @p pieces equal
 * sub-intervals (one de Casteljau subdivision each), so the overestimate
 * shrinks like 1/pieces^2. pieces <= 1 is BernsteinRange.
 */
HOV_EXPORT void BernsteinRangeSubdivided(
  const BernsteinPolynomial& b, int pieces, double& lo, double& hi);

/// db/dy (degree n - 1; the zero polynomial of degree 0 for n = 0).
HOV_EXPORT BernsteinPolynomial BernsteinDerivative(const BernsteinPolynomial& b);

/// The same polynomial written with degree @p degree >= b.Degree.
HOV_EXPORT BernsteinPolynomial ElevateBernstein(const BernsteinPolynomial& b, int degree);

/// a * b; false (out untouched) if the degree would exceed MaxBernsteinDegree.
HOV_EXPORT bool MultiplyBernstein(
  const BernsteinPolynomial& a, const BernsteinPolynomial& b, BernsteinPolynomial& out);

/// The monomial polynomial p(y) (degree <= 9) in Bernstein form of degree
/// max(p's degree, @p minDegree) (positive weights: no cancellation).
HOV_EXPORT BernsteinPolynomial BernsteinFromMonomial(const Polynomial& p, int minDegree = 0);

/**
 * A polynomial q(y) of degree <= @p maxDegree (<= 8) in the monomial basis
 * with |b(y) - q(y)| <= @p errorBound on [0, 1], rigorously: q interpolates b
 * at the Chebyshev points of [0, 1] (exact when b.Degree <= maxDegree, up to
 * rounding), and errorBound is max_j |B[j] - Q[j]| of the difference in
 * Bernstein form of degree b.Degree (convex hull) plus a rounding allowance
 * 8 (n + 1) eps max_j (|B[j]| + |Q[j]|).
 */
HOV_EXPORT Polynomial ApproximateBernstein(
  const BernsteinPolynomial& b, int maxDegree, double& errorBound);

/// Settings of BernsteinRoots.
struct BernsteinRootSettings
{
  /// Sub-intervals narrower than this (in y) are not split further: a
  /// cluster of roots or a tangency inside is reported once, at its middle.
  double Resolution = 1e-13;
  /// Sub-intervals examined before giving up (then Complete = false).
  int MaxIntervals = 4096;
};

/**
 * Sorted distinct roots of b(y) = @p level in [0, 1] into @p roots (at most
 * @p maxRoots): recursive subdivision by Descartes' rule (no sign change of
 * B[j] - level: no root; one: exactly one, solved by safeguarded
 * Newton/bisection to a few ulp; else split at the middle), an end with
 * B = level exactly is a root, clusters narrower than Resolution are one
 * root. @p complete (if given) is false if MaxIntervals or maxRoots ran out.
 * Returns the number of roots.
 */
HOV_EXPORT int BernsteinRoots(const BernsteinPolynomial& b, double level, double* roots,
  int maxRoots, const BernsteinRootSettings& settings = BernsteinRootSettings(),
  bool* complete = nullptr);

/**
 * Bernstein coefficients (degree @p n <= MaxBernsteinDegree) of the
 * Lagrange basis polynomial of node @p i on the equispaced nodes k/n of
 * [0, 1], from the product of its n linear factors (exact to rounding).
 */
HOV_EXPORT BernsteinPolynomial EquispacedLagrangeBernstein(int n, int i);
}

#endif
