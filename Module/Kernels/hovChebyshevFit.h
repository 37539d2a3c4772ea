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
 * One table of cosines serves every Chebyshev step of the kernels (these and
 * the shaded quadrature's panels, hovShadedSegment.cxx): cos(pi m / ChebN)
 * correctly rounded, so cos(pi / 2) is exactly 0 and the table is
 * antisymmetric (cos(pi (N - m) / N) = -cos(pi m / N) bit for bit), which
 * std::cos(Pi m / N) is not (6e-17 at pi / 2, -1.8e-16 at 3 pi / 2, 21 of 32
 * entries 1 to 14 ulp off, asymmetries up to 5 ulp).
 *
 * Thread safety: stateless (the product table is a function-local static).
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

/// cos(pi m / ChebN), m = 0 .. ChebN, correctly rounded (file doc).
inline constexpr double ChebyshevCosines[ChebN + 1] = { 1.0, 0.98078528040323044912618223613424,
  0.92387953251128675612818318939679, 0.83146961230254523707878837761791,
  0.70710678118654752440084436210485, 0.55557023301960222474283081394853,
  0.38268343236508977172845998403040, 0.19509032201612826784828486847702, 0.0,
  -0.19509032201612826784828486847702, -0.38268343236508977172845998403040,
  -0.55557023301960222474283081394853, -0.70710678118654752440084436210485,
  -0.83146961230254523707878837761791, -0.92387953251128675612818318939679,
  -0.98078528040323044912618223613424, -1.0 };

/// cos(pi m / ChebN) for any integer m, from the table by symmetry (the
/// cosine is even and has period 2 ChebN in m).
inline double ChebyshevCosine(int m)
{
  m %= 2 * ChebN; // in (-2 ChebN, 2 ChebN)
  m = m < 0 ? -m : m;
  return m <= ChebN ? ChebyshevCosines[m] : ChebyshevCosines[2 * ChebN - m];
}

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
