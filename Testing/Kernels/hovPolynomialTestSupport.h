/**
 * @file hovPolynomialTestSupport.h
 * @brief Tolerances (with the measurements behind them) and independent
 * references for the tests of hovPolynomial and hovPolynomialSegment.
 *
 * Nothing here calls the code under test: polynomials are built from their
 * roots and evaluated in cpp_bin_float_50; the segment reference finds its
 * breakpoints with the textbook quadratic formula in 50 digits and integrates
 * the raw emission-absorption integrand with Boost tanh-sinh (outer) and
 * 30-point Gauss-Legendre (inner, optical depth) in cpp_bin_float_50 / long
 * double, from the raw transfer-function nodes (not hov::TransferFunction).
 */
#ifndef hovPolynomialTestSupport_h
#define hovPolynomialTestSupport_h

#include "hovPolynomial.h"

#include "hovKernelTestReference.h" // Mp, RefTransferFunction, PwlAt

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hovtest
{
struct PolynomialToleranceTable
{
  /// Simple roots of polynomials with exactly representable coefficients on
  /// [0,1], absolute. Measured worst 1.1e-16 (compensated Horner makes the
  /// residual test as accurate as 106-bit evaluation; the root is rounded
  /// once). 4 ulp of 1 allowed.
  double SimpleRootAbs = 1e-15;
  /// Double roots (exact coefficients): conditioning ~ sqrt(bound/|p''/2|)
  /// with the 106-bit evaluation bound ~ 1e-31. Measured worst 0 (the
  /// critical point is the root; found by the derivative's simple root).
  double DoubleRootAbs = 1e-14;
  /// Triple root: ~ (bound)^(1/3) ~ 1e-10 in theory. Measured 0 (reported
  /// as the derivative's double root at the exact point).
  double TripleRootAbs = 1e-9;
  /// Random polynomials (rounded coefficients): |p(r)| at a returned root,
  /// computed in 50 digits, relative to sum |c_i||r|^i. Measured worst
  /// 2.4e-16 (backward error of a few ulp). 
  double ResidualRel = 4e-15;
  /// Random polynomials: every well-separated constructed root is found
  /// within this many times its first-order condition number
  /// (eps sum|c_i||r|^i / |p'(r)|). Measured worst ratio 0.5.
  double ConditionFactor = 16.0;
};
inline constexpr PolynomialToleranceTable PolyTol{};

/// Monic polynomial prod (t - r_i) in 50 digits (coefficients, constant first).
inline std::vector<Mp> PolyFromRoots(const std::vector<double>& roots)
{
  std::vector<Mp> c{ Mp(1) };
  for (double r : roots)
  {
    std::vector<Mp> n(c.size() + 1, Mp(0));
    for (size_t i = 0; i < c.size(); ++i)
    {
      n[i + 1] += c[i];
      n[i] -= c[i] * Mp(r);
    }
    c = n;
  }
  return c;
}

/// Rounds 50-digit coefficients into a hov::Polynomial scaled by @p scale;
/// @p exact is set to whether the rounding was exact.
inline hov::Polynomial ToPolynomial(const std::vector<Mp>& c, double scale, bool* exact = nullptr)
{
  hov::Polynomial p;
  p.Degree = static_cast<int>(c.size()) - 1;
  bool ok = true;
  for (size_t i = 0; i < c.size(); ++i)
  {
    p.C[i] = static_cast<double>(c[i] * Mp(scale));
    ok = ok && Mp(p.C[i]) == c[i] * Mp(scale);
  }
  if (exact)
  {
    *exact = ok;
  }
  return p;
}

/// p(t) in 50 digits from the double coefficients of @p p.
inline Mp EvalMp(const hov::Polynomial& p, const Mp& t)
{
  Mp r = p.C[p.Degree];
  for (int i = p.Degree - 1; i >= 0; --i)
  {
    r = r * t + Mp(p.C[i]);
  }
  return r;
}

/// sum |c_i| |t|^i (the scale of rounding errors in p(t)).
inline double Magnitude(const hov::Polynomial& p, double t)
{
  double m = 0.0;
  for (int i = p.Degree; i >= 0; --i)
  {
    m = m * std::fabs(t) + std::fabs(p.C[i]);
  }
  return m;
}
}

#endif
