/**
 * @file hovPolynomialTestSupport.h
 * @brief Tolerances (with the measurements behind them) and independent
 * references for the tests of hovPolynomial and hovPolynomialSegment.
 *
 * Nothing here calls the code under test: polynomials are built from their
 * roots and evaluated in cpp_bin_float_50; the segment reference finds its
 * breakpoints with the textbook quadratic formula in 50 digits and integrates
 * the raw emission-absorption integrand in long double with adaptive Boost
 * gauss_kronrod<long double, 61> (outer) and 20-point Gauss-Legendre (inner:
 * the optical depth, exact for polynomial extinction of degree <= 39), from
 * the raw transfer-function nodes (not hov::TransferFunction).
 */
#ifndef hovPolynomialTestSupport_h
#define hovPolynomialTestSupport_h

#include "hovPolynomial.h"

#include "hovKernelTestReference.h" // Mp, RefTransferFunction, PwlAt

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

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
  /// 1.8e-16 (backward error of about one ulp: the root is a double).
  double ResidualRel = 4e-15;
  /// Random polynomials: every well-separated constructed root is found
  /// within this many times its first-order condition number
  /// (eps sum|c_i||r|^i / |p'(r)|). Measured worst ratio 0.82.
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

/// s(t) in long double.
inline long double EvalLd(const hov::Polynomial& p, long double t)
{
  long double r = p.C[p.Degree];
  for (int i = p.Degree - 1; i >= 0; --i)
  {
    r = r * t + p.C[i];
  }
  return r;
}

/**
 * Breakpoints of s on [0, L]: every t where s equals a node or s' = 0, found
 * independently of the kernels: sign changes on a uniform grid of @p grid
 * cells, refined by 200 bisections in long double. (Roots that cancel within
 * one grid cell, i.e. tangencies, are missed; they do not change the integral.)
 */
inline std::vector<long double> ReferenceBreakpoints(
  const RefTransferFunction& tf, const hov::Polynomial& s, double length, int grid = 4000)
{
  std::vector<double> levels(tf.ColorX);
  levels.insert(levels.end(), tf.OpacityX.begin(), tf.OpacityX.end());
  hov::Polynomial ds;
  ds.Degree = std::max(s.Degree - 1, 0);
  for (int i = 1; i <= s.Degree; ++i)
  {
    ds.C[i - 1] = i * s.C[i];
  }
  std::vector<long double> ts{ 0.0L, static_cast<long double>(length) };
  auto refine = [&](const hov::Polynomial& p, long double level, long double a, long double b) {
    const bool negA = EvalLd(p, a) - level < 0;
    for (int it = 0; it < 200; ++it)
    {
      const long double m = 0.5L * (a + b);
      ((EvalLd(p, m) - level < 0) == negA ? a : b) = m;
    }
    return 0.5L * (a + b);
  };
  auto scan = [&](const hov::Polynomial& p, long double level) {
    long double prevT = 0.0L, prev = EvalLd(p, 0.0L) - level;
    for (int i = 1; i <= grid; ++i)
    {
      const long double t = static_cast<long double>(length) * i / grid;
      const long double v = EvalLd(p, t) - level;
      if ((prev < 0) != (v < 0))
      {
        ts.push_back(refine(p, level, prevT, t));
      }
      prevT = t;
      prev = v;
    }
  };
  scan(ds, 0.0L);
  for (double x : levels)
  {
    scan(s, x);
  }
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  return ts;
}

/// Premultiplied RGBA of the ray [0, L] along s(t) (see file doc).
inline RefRGBA ReferencePolynomialRay(
  const RefTransferFunction& tf, const hov::Polynomial& s, double length, RefEmission emission)
{
  using boost::math::quadrature::gauss;
  using boost::math::quadrature::gauss_kronrod;
  const std::vector<long double> ts = ReferenceBreakpoints(tf, s, length);
  std::vector<long double> op(tf.Opacity.begin(), tf.Opacity.end());
  std::vector<long double> col[3];
  for (const auto& c : tf.Color)
  {
    for (int ch = 0; ch < 3; ++ch)
    {
      col[ch].push_back(c[ch]);
    }
  }
  const bool wm = emission == RefEmission::WilliamsMax;
  const long double invU = 1.0L / tf.Unit;
  RefRGBA out;
  long double depth = 0.0L;
  for (size_t p = 0; p + 1 < ts.size(); ++p)
  {
    const long double t0 = ts[p], t1 = ts[p + 1];
    const long double hint = EvalLd(s, 0.5L * (t0 + t1)); // the piece's interval
    auto opacity = [&](long double t) { return PwlAt(tf.OpacityX, op, EvalLd(s, t), hint); };
    auto tau = [&](long double t) -> long double {
      const long double a = opacity(t);
      switch (tf.Semantics)
      {
        case RefSemantics::GPU:
          return a >= 1.0L ? std::numeric_limits<long double>::infinity() : -std::log1p(-a) * invU;
        case RefSemantics::Unstructured:
          return a * invU;
        default:
          return a;
      }
    };
    if (opacity(t0) >= 1.0L && opacity(t1) >= 1.0L && tf.Semantics == RefSemantics::GPU)
    {
      if (wm) // opaque medium: everything left is absorbed at its front
      {
        const long double tr = std::exp(-depth);
        out.R += tr * PwlAt(tf.ColorX, col[0], EvalLd(s, t0), hint);
        out.G += tr * PwlAt(tf.ColorX, col[1], EvalLd(s, t0), hint);
        out.B += tr * PwlAt(tf.ColorX, col[2], EvalLd(s, t0), hint);
      }
      depth = std::numeric_limits<long double>::infinity();
      break;
    }
    auto depthTo = [&](long double t) {
      return t > t0 ? gauss<long double, 20>::integrate(tau, t0, t) : 0.0L;
    };
    for (int ch = 0; ch < 3; ++ch)
    {
      auto f = [&](long double t) -> long double {
        const long double c = PwlAt(tf.ColorX, col[ch], EvalLd(s, t), hint);
        const long double src = wm ? c * tau(t) : tf.EmissionScale * invU * c;
        return src * std::exp(-(depth + depthTo(t)));
      };
      long double err = 0.0L;
      (ch == 0 ? out.R : (ch == 1 ? out.G : out.B)) +=
        gauss_kronrod<long double, 61>::integrate(f, t0, t1, 5, 1e-15L, &err);
    }
    depth += depthTo(t1);
  }
  out.A = std::isfinite(static_cast<double>(depth)) ? -std::expm1(-depth) : 1.0L;
  return out;
}
}

#endif
