/**
 * @file hovLagrangeRestriction.h
 * @brief A Lagrange cell's interpolated field along a straight line in
 * PARAMETRIC space, exactly, as one polynomial in Bernstein form.
 *
 * For pc(y) = start + y step, y in [0, 1], the field
 * f(pc(y)) = sum_i f_i w_i(pc(y)) is a polynomial in y of degree
 * LagrangeBasis::GetLineDegree() (tetrahedron n, wedge p + q, hexahedron
 * p0 + p1 + p2; up to 30). Where the geometry map is affine the ray is such
 * a line, so this is the field along a ray segment (hovEnclosure.h uses it
 * for affine and, with a rigorous remainder, curved cells).
 *
 * Method: every shape function is a product of linear factors in pc
 * (hexahedra: (p r - k)/(i - k); Silvester's Eta: (n tau - c + 1)/c), each
 * linear in y with Bernstein coefficients (value at y = 0, value at y = 1).
 * Products of Bernstein polynomials are convolutions of the scaled
 * coefficients C(n,j) B[j], so the field's Bernstein coefficients come out
 * with no basis conversion (hence no ill-conditioning; sampling at
 * equispaced points and converting would amplify rounding by ~1e7 at degree
 * 24). Sums are grouped by the tensor structure: hexahedra cost
 * O(p^4), tetrahedra O(n^5 / 6), wedges O(p^2 (p + q) q).
 * The two closed-form cells (15-node tetrahedron, 21-node wedge; degree 4
 * and 5) are sampled at the degree + 1 equispaced points and converted
 * (amplification <= 10 at these degrees).
 *
 * Rounding: if @p roundingBound is given it receives a bound on the absolute
 * error of every coefficient, (2 D + 16) eps max_m A[m], A the same
 * computation on absolute values (first-order error analysis of the
 * products and sums; D the degree).
 *
 * Thread safety: re-entrant; no allocation (stack arrays sized by
 * MaxLagrangeOrder).
 * @sa hovBernstein.h, hovLagrangeBasis.h, hovEnclosure.h
 */
#ifndef hovLagrangeRestriction_h
#define hovLagrangeRestriction_h

#include "hovBernstein.h"
#include "hovConfig.h"
#include "hovLagrangeBasis.h"

namespace hov
{
/**
 * The field with node values @p values along pc(y) = @p start + y @p step,
 * y in [0, 1], into @p out (Bernstein, degree basis.GetLineDegree()).
 * False if the basis is not initialised.
 */
HOV_EXPORT bool LagrangeFieldAlongLine(const LagrangeBasis& basis, const double* values,
  const double start[3], const double step[3], BernsteinPolynomial& out,
  double* roundingBound = nullptr);
}

#endif
