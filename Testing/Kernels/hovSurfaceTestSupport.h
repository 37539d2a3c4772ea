/**
 * @file hovSurfaceTestSupport.h
 * @brief Independent references and helpers for the tests of the isosurface,
 * two-field and splatting kernels (TestIsosurfaceSegment, TestTwoFieldSegment,
 * TestSplat, TestShading).
 *
 * ReferenceTwoFieldRange() integrates the raw emission-absorption integrand
 * over [t0, t1] with the extinction read from one raw transfer function at
 * s1(t) and the colour from another at s2(t) (neither is a
 * hov::TransferFunction): breakpoints by a uniform scan + 200 bisections in
 * long double (levels of both functions on both fields, extrema of both
 * fields), then adaptive Boost gauss_kronrod<long double, 61> for the colour
 * with a nested 20-point Gauss-Legendre optical depth, as
 * ReferencePolynomialRay of hovPolynomialTestSupport.h (which it generalises;
 * with s1 = s2 it is the same integral). Nothing here calls the kernels.
 */
#ifndef hovSurfaceTestSupport_h
#define hovSurfaceTestSupport_h

#include "hovPolynomial.h"
#include "hovTransferFunction.h"

#include "hovKernelTestReference.h"   // RefTransferFunction, PwlAt, RefRGBA
#include "hovPolynomialTestSupport.h" // EvalLd

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace hovtest
{
/// Random table with @p nodes colour and opacity nodes in [0, 1] (opacity <= 0.95).
inline hov::TransferFunctionSpec RandomSurfaceSpec(
  std::mt19937_64& rng, hov::OpacitySemantics semantics, int nodes)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = semantics;
  spec.UnitDistance = LogUniform(rng, 0.2, 5.0);
  spec.EmissionScale = LogUniform(rng, 0.5, 2.0);
  auto positions = [&](int n) {
    std::vector<double> x;
    for (int i = 0; i < n; ++i)
    {
      x.push_back(Uniform(rng, 0, 1));
    }
    std::sort(x.begin(), x.end());
    return x;
  };
  for (double x : positions(nodes))
  {
    spec.Color.push_back({ x, Uniform(rng, 0, 1), Uniform(rng, 0, 1), Uniform(rng, 0, 1) });
  }
  for (double x : positions(nodes))
  {
    spec.Opacity.push_back({ x, Uniform(rng, 0, 0.95) });
  }
  return spec;
}

/// Random polynomial of degree @p degree with values roughly in [-0.1, 1.1]
/// on [0, L] (product of roots in [-0.3, 1.3] of x = t/L, scaled, shifted).
inline hov::Polynomial RandomSurfaceField(std::mt19937_64& rng, int degree, double length)
{
  std::vector<double> c{ 1.0 };
  for (int i = 0; i < degree; ++i)
  {
    const double r = Uniform(rng, -0.3, 1.3);
    std::vector<double> n(c.size() + 1, 0.0);
    for (size_t j = 0; j < c.size(); ++j)
    {
      n[j + 1] += c[j];
      n[j] -= r * c[j];
    }
    c = n;
  }
  double m = 0.0;
  for (int i = 0; i <= 64; ++i)
  {
    double v = 0.0;
    for (int j = degree; j >= 0; --j)
    {
      v = v * (i / 64.0) + c[j];
    }
    m = std::max(m, std::fabs(v));
  }
  hov::Polynomial p;
  p.Degree = degree;
  const double scale = Uniform(rng, 0.5, 1.1) / m * (rng() % 2 ? 1.0 : -1.0);
  for (int j = 0; j <= degree; ++j)
  {
    p.C[j] = c[j] * scale / std::pow(length, j);
  }
  p.C[0] += 0.5;
  return p;
}

/// Derivative in long double arithmetic's input form (double coefficients).
inline hov::Polynomial DerivativeOf(const hov::Polynomial& s)
{
  hov::Polynomial d;
  d.Degree = std::max(s.Degree - 1, 0);
  for (int i = 1; i <= s.Degree; ++i)
  {
    d.C[i - 1] = i * s.C[i];
  }
  return d;
}

/// Every t in (t0, t1) where p(t) = level, by a uniform scan and bisection.
inline void ScanLevel(const hov::Polynomial& p, long double level, long double t0, long double t1,
  int grid, std::vector<long double>& ts)
{
  long double prevT = t0, prev = EvalLd(p, t0) - level;
  for (int i = 1; i <= grid; ++i)
  {
    const long double t = t0 + (t1 - t0) * i / grid;
    const long double v = EvalLd(p, t) - level;
    if ((prev < 0) != (v < 0))
    {
      long double a = prevT, b = t;
      const bool negA = prev < 0;
      for (int it = 0; it < 200; ++it)
      {
        const long double m = 0.5L * (a + b);
        ((EvalLd(p, m) - level < 0) == negA ? a : b) = m;
      }
      ts.push_back(0.5L * (a + b));
    }
    prevT = t;
    prev = v;
  }
}

inline long double RefTau(const RefTransferFunction& tf, long double opacity)
{
  switch (tf.Semantics)
  {
    case RefSemantics::GPU:
      return opacity >= 1.0L ? std::numeric_limits<long double>::infinity()
                             : -std::log1p(-opacity) / tf.Unit;
    case RefSemantics::Unstructured:
      return opacity / tf.Unit;
    default:
      return opacity;
  }
}

/**
 * Premultiplied RGBA of the range [t0, t1] of a ray (as a segment starting at
 * t0): extinction from @p ext at s1(t), colour from @p col at s2(t).
 */
inline RefRGBA ReferenceTwoFieldRange(const RefTransferFunction& ext, const hov::Polynomial& s1,
  const RefTransferFunction& col, const hov::Polynomial& s2, long double t0, long double t1,
  RefEmission emission, int grid = 2000)
{
  using boost::math::quadrature::gauss;
  using boost::math::quadrature::gauss_kronrod;
  std::vector<long double> ts{ t0, t1 };
  ScanLevel(DerivativeOf(s1), 0.0L, t0, t1, grid, ts);
  ScanLevel(DerivativeOf(s2), 0.0L, t0, t1, grid, ts);
  for (const RefTransferFunction* tf : { &ext, &col })
  {
    for (const hov::Polynomial* s : { &s1, &s2 })
    {
      for (double x : tf->ColorX)
      {
        ScanLevel(*s, x, t0, t1, grid, ts);
      }
      for (double x : tf->OpacityX)
      {
        ScanLevel(*s, x, t0, t1, grid, ts);
      }
    }
  }
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  std::vector<long double> op(ext.Opacity.begin(), ext.Opacity.end());
  std::vector<long double> rgb[3];
  for (const auto& c : col.Color)
  {
    for (int ch = 0; ch < 3; ++ch)
    {
      rgb[ch].push_back(c[ch]);
    }
  }
  const bool wm = emission == RefEmission::WilliamsMax;
  RefRGBA out;
  long double depth = 0.0L;
  for (size_t p = 0; p + 1 < ts.size(); ++p)
  {
    const long double a = ts[p], b = ts[p + 1];
    const long double hint1 = EvalLd(s1, 0.5L * (a + b)), hint2 = EvalLd(s2, 0.5L * (a + b));
    auto tau = [&](long double t) {
      return RefTau(ext, PwlAt(ext.OpacityX, op, EvalLd(s1, t), hint1));
    };
    auto depthTo = [&](long double t) {
      return t > a ? gauss<long double, 20>::integrate(tau, a, t) : 0.0L;
    };
    for (int ch = 0; ch < 3; ++ch)
    {
      auto f = [&](long double t) -> long double {
        const long double c = PwlAt(col.ColorX, rgb[ch], EvalLd(s2, t), hint2);
        const long double src = wm ? c * tau(t) : col.EmissionScale / col.Unit * c;
        return src * std::exp(-(depth + depthTo(t)));
      };
      long double err = 0.0L;
      (ch == 0 ? out.R : (ch == 1 ? out.G : out.B)) +=
        gauss_kronrod<long double, 61>::integrate(f, a, b, 5, 1e-15L, &err);
    }
    depth += depthTo(b);
  }
  out.A = -std::expm1(-depth);
  return out;
}

/// Front-to-back "over" in long double (the reference's own compositing).
inline void RefCompositeBehind(RefRGBA& accum, const RefRGBA& behind)
{
  const long double t = 1.0L - accum.A;
  accum.R += t * behind.R;
  accum.G += t * behind.G;
  accum.B += t * behind.B;
  accum.A += t * behind.A;
}
}

#endif
