/**
 * @file hovChebyshevFit.h
 * @brief The Chebyshev interpolation steps shared by the non-affine cell
 * restrictions (hovCellRestriction.h: the scalar; hovGradientRestriction.h:
 * its gradient): samples at the ChebN + 1 Chebyshev extreme points of an
 * interval, the interpolant's coefficients (DCT-I), the truncation to the
 * smallest degree whose bound meets a tolerance, and the conversion to
 * monomials in the local variable tau = t - a.
 *
 * Bound of a truncation to degree m (hovCellRestriction.h explains the
 * factor 2): 2 sum_{k > m} |c_k| + 64 eps sum |c_k| + floor.
 *
 * Thread safety: stateless (the cosine table is a function-local static).
 */
#ifndef hovChebyshevFit_h
#define hovChebyshevFit_h

#include "hovPolynomial.h"

namespace hov
{
namespace detail
{
/// Chebyshev sample count - 1 (degree of the interpolant before truncation).
constexpr int ChebN = 16;
/// Largest degree of a returned piece.
constexpr int MaxPieceDegree = 8;

/// The sample points of [a, b]: t[0] = b, t[ChebN] = a, t[j] = mid + half cos(pi j / N).
void ChebyshevPoints(double a, double b, double t[ChebN + 1]);

/// Chebyshev coefficients c[0..ChebN] of the interpolant of f at ChebyshevPoints.
void ChebyshevCoefficients(const double f[ChebN + 1], double c[ChebN + 1]);

/**
 * The smallest degree m <= MaxPieceDegree whose bound (file doc) is at most
 * @p tolerance, or MaxPieceDegree; @p bound receives that degree's bound.
 */
int TruncationDegree(const double c[ChebN + 1], double floor, double tolerance, double& bound);

/// Monomial polynomial in tau = t - a from Chebyshev coefficients c[0..m] on [a, b].
Polynomial ChebyshevToLocal(const double* c, int m, double a, double b);
}
}

#endif
