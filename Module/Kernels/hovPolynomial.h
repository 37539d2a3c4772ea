/**
 * @file hovPolynomial.h
 * @brief Small dense polynomials in one variable (degree <= 9) and robust
 * real-root isolation on a closed interval.
 *
 * A cell's field restricted to a ray is a polynomial s(t) in the ray
 * parameter: quadratic in a quadratic tetrahedron or wedge with straight edges
 * (HIAC section 5.2), cubic in a trilinear hexahedron, degree <= 8 for the
 * straight-edged serendipity/Lagrange cells of the module. The segment integral
 * (hovPolynomialSegment.h) needs the t where s(t) equals a transfer-function
 * node or an isovalue, and the extrema of s. Degree 9 is allowed so that the
 * antiderivative of a degree-8 polynomial (an optical depth) is representable.
 *
 * Domain: finite double coefficients; intervals [lo, hi] with finite lo <= hi.
 * Coefficients are scaled by a power of two (exact) before root finding, so
 * nothing overflows for coefficients anywhere in the double range.
 *
 * Root finding (FindRoots): returns, sorted and without duplicates, every t
 * in [lo, hi] where p(t) = level, whether p crosses the level there or only
 * touches it (a tangency, e.g. an extremum exactly at a node: reported ONCE,
 * at the point of contact; callers that split a ray there lose nothing, since
 * s stays on one side). A polynomial identically equal to the level reports
 * no root (the caller treats constants separately).
 *  - degree <= 2: cancellation-free quadratic formula
 *      q = b' + sign(b') sqrt(D), t1 = q / a, t2 = c / q  (b' = -b/2,
 *    D = b'^2 - a c) with D computed by Kahan's FMA algorithm (error <= 2 ulp
 *    of D itself, Boldo 2009), so roots 2^-27 apart are still separated
 *    when the coefficients are exact. a -> 0 degenerates smoothly to the
 *    linear root c/q (the other root q/a leaves the interval or overflows
 *    to inf and is dropped); a = 0 exactly is the linear case. |D| <=
 *    NearDoubleRootEps^2 (b'^2 + |ac|) (below the residual of Kahan's
 *    method) is a double root -b'/a (tangency, reported once); D below that
 *    is no root.
 *  - degree >= 3: recursive isolation. The roots of p' (found the same way)
 *    split [lo, hi] into intervals where p is monotone; p is evaluated at
 *    their ends by compensated Horner (EvaluateCompensated: as accurate as
 *    Horner in twice the working precision, error <= eps|p| +
 *    2 gamma_2n^2 sum|c_i||t|^i), a value within that bound counts as zero
 *    (an end root, a tangency or a multiple root: reported once), and each
 *    sign change is solved by safeguarded Newton/bisection (SolveMonotone) to
 *    a bracket of 2 ulp or a residual within the evaluation bound.
 *  - roots within RootEndSlack = 4 eps max(|lo|,|hi|) outside [lo, hi] are
 *    clamped onto the end (a root exactly at an end is found whatever the
 *    rounding). Roots closer than that to each other are merged.
 * Accuracy: a simple root r is returned within a few ulp plus
 * (evaluation bound)/|p'(r)|; a root of multiplicity m within
 * ~(bound / |p^(m)(r)/m!|)^(1/m) (the conditioning of the problem).
 *
 * Thread safety: stateless, re-entrant; no allocation.
 * @sa hovPolynomialSegment.h
 */
#ifndef hovPolynomial_h
#define hovPolynomial_h

#include "hovConfig.h"

#include <algorithm>        // std::min, std::max (inline helpers)
#include <cmath>            // std::abs (inline helpers)
#include <initializer_list> // FromCoefficients

namespace hov
{
/// Dense polynomial sum_{i <= Degree} C[i] t^i.
struct Polynomial
{
  /// Largest degree stored: 8 for fields along rays, +1 for antiderivatives.
  static constexpr int MaxDegree = 9;
  int Degree = 0;
  double C[MaxDegree + 1] = {};

  /// Coefficients from the constant term up (at most MaxDegree + 1 of them;
  /// extra ones are ignored).
  static Polynomial FromCoefficients(std::initializer_list<double> c);
};

/// Relative size of |D| (to b'^2 + |ac|) below which a quadratic has a double root.
constexpr double NearDoubleRootEps = 4.0 * 2.220446049250313e-16;
/// Roots this far (relative to max(|lo|,|hi|), times eps) outside the interval are clamped onto it.
constexpr double RootEndSlackUlps = 4.0;

/// Highest index with a non-zero coefficient (0 for the zero polynomial).
inline int EffectiveDegree(const Polynomial& p);

/**
 * Drop the highest terms of @p s while |c_k| h^k <= @p tol (their largest
 * value on [0, h]); never below degree 1. A field that is linear along a ray
 * up to rounding (an affine cell with a linear field) then takes the linear
 * exact path instead of quadrature for a cubic with ~1e-17 coefficients.
 */
inline void TrimNegligibleTerms(Polynomial& s, double h, double tol);

/// p(t) by Horner's rule.
inline double Evaluate(const Polynomial& p, double t);

/// p(t) and p'(t) by Horner's rule.
HOV_EXPORT void EvaluateWithDerivative(const Polynomial& p, double t, double& value, double& slope);

/**
 * p(t) - level by compensated Horner (Graillat, Langlois & Louvet 2005, with
 * FMA): the result is as accurate as if computed in twice the precision and
 * rounded. @p errorBound, if given, receives a bound on its absolute error:
 * 2 eps |result| + 2 gamma_{2n}^2 (sum |c_i| |t|^i + |level|).
 */
HOV_EXPORT double EvaluateCompensated(
  const Polynomial& p, double t, double level = 0.0, double* errorBound = nullptr);

/// p'.
inline Polynomial Derivative(const Polynomial& p);

/// The antiderivative vanishing at 0. False (and @p out untouched) if its
/// degree would exceed MaxDegree.
inline bool Antiderivative(const Polynomial& p, Polynomial& out);

/// q(t) = p(offset + scale t), accumulated in long double.
HOV_EXPORT Polynomial ComposeAffine(const Polynomial& p, double offset, double scale);

/**
 * Sorted distinct roots of p(t) = @p level in [@p lo, @p hi] (see file doc);
 * @p roots must hold MaxDegree values. Returns their number (0 if the interval
 * is empty or not finite, or p is constant).
 */
HOV_EXPORT int FindRoots(const Polynomial& p, double level, double lo, double hi, double* roots);

/**
 * The root of p(t) = @p level in [@p lo, @p hi] for p monotone there:
 * the closed form for degree <= 2, else safeguarded Newton/bisection on the
 * sign change (regula falsi start; stops at a step below 1 ulp, a 2-ulp
 * bracket, or a residual within the evaluation bound). If the level is not
 * bracketed, the end where |p - level| is smaller is returned (an end within
 * the evaluation error of the level counts as the root).
 */
HOV_EXPORT double SolveMonotone(const Polynomial& p, double level, double lo, double hi);

// Small helpers inline (called per piece and per quadrature node).
inline int EffectiveDegree(const Polynomial& p)
{
  int n = std::min(std::max(p.Degree, 0), Polynomial::MaxDegree);
  while (n > 0 && p.C[n] == 0.0)
  {
    --n;
  }
  return n;
}

inline double Evaluate(const Polynomial& p, double t)
{
  const int n = std::min(std::max(p.Degree, 0), Polynomial::MaxDegree);
  double r = p.C[n];
  for (int i = n - 1; i >= 0; --i)
  {
    r = r * t + p.C[i];
  }
  return r;
}

inline Polynomial Derivative(const Polynomial& p)
{
  Polynomial d;
  const int n = std::min(std::max(p.Degree, 0), Polynomial::MaxDegree);
  d.Degree = std::max(n - 1, 0);
  for (int i = 1; i <= n; ++i)
  {
    d.C[i - 1] = i * p.C[i];
  }
  return d;
}

inline bool Antiderivative(const Polynomial& p, Polynomial& out)
{
  const int n = EffectiveDegree(p);
  if (n + 1 > Polynomial::MaxDegree)
  {
    return false;
  }
  Polynomial a;
  a.Degree = n + 1;
  for (int i = 0; i <= n; ++i)
  {
    a.C[i + 1] = p.C[i] / (i + 1);
  }
  out = a;
  return true;
}
inline void TrimNegligibleTerms(Polynomial& s, double h, double tol)
{
  while (s.Degree > 1)
  {
    double size = std::abs(s.C[s.Degree]);
    for (int k = 0; k < s.Degree; ++k)
    {
      size *= h;
    }
    if (!(size <= tol))
    {
      break;
    }
    s.C[s.Degree] = 0.0;
    --s.Degree;
  }
}
}

#endif
