// Tests of hovPolynomial: evaluation, calculus and composition against 50-digit
// arithmetic; real-root isolation against polynomials built from known roots
// (exact coefficients where the case needs them: double, triple and clustered
// roots, roots at the interval ends), degenerate quadratics, extreme scales,
// and a random sweep checking residuals, completeness and the absence of NaN.

#include "hovPolynomial.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestUtilities.h"
#include "hovPolynomialTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using hovtest::Mp;
using hovtest::PolyTol;
using hovtest::Str;
using hovtest::Worst;

namespace
{
std::vector<double> Roots(const hov::Polynomial& p, double level, double lo, double hi)
{
  double r[hov::Polynomial::MaxDegree];
  const int n = hov::FindRoots(p, level, lo, hi, r);
  return std::vector<double>(r, r + n);
}

std::string Describe(const std::vector<double>& v)
{
  std::string s = "{";
  for (double x : v)
  {
    s += " " + Str(x);
  }
  return s + " }";
}

/// Checks that FindRoots on prod (t - r_i) * scale over [lo, hi] returns
/// exactly @p expected (distinct values) within @p tol; coefficients must be exact.
void ExpectRoots(const std::vector<double>& constructed, const std::vector<double>& expected,
  double lo, double hi, double tol, Worst& worst, double scale = 1.0)
{
  bool exact = false;
  const hov::Polynomial p = hovtest::ToPolynomial(hovtest::PolyFromRoots(constructed), scale, &exact);
  ASSERT_TRUE(exact) << "test polynomial not exact in double: " << Describe(constructed);
  const std::vector<double> got = Roots(p, 0.0, lo, hi);
  ASSERT_EQ(got.size(), expected.size())
    << "roots " << Describe(constructed) << " scale " << scale << " got " << Describe(got);
  for (size_t i = 0; i < got.size(); ++i)
  {
    EXPECT_NEAR(got[i], expected[i], tol) << Describe(constructed) << " scale " << scale;
    worst.Add(std::fabs(got[i] - expected[i]), Describe(constructed));
    if (i > 0)
    {
      EXPECT_LT(got[i - 1], got[i]);
    }
  }
}
}

TEST(PolynomialBasics, EvaluationCalculusCompositionMatch50Digits)
{
  std::mt19937_64 rng(11);
  Worst evalErr, compErr, compensated;
  for (int trial = 0; trial < 200; ++trial)
  {
    hov::Polynomial p;
    p.Degree = 1 + trial % 8;
    for (int i = 0; i <= p.Degree; ++i)
    {
      p.C[i] = hovtest::Uniform(rng, -1, 1);
    }
    const double t = hovtest::Uniform(rng, -1.5, 1.5);
    const Mp ref = hovtest::EvalMp(p, t);
    const double mag = hovtest::Magnitude(p, t);
    evalErr.Add(hovtest::AbsErr(hov::Evaluate(p, t), ref) / mag, Str(t));
    double bound = 0.0;
    const double c = hov::EvaluateCompensated(p, t, 0.25, &bound);
    const double cErr = hovtest::AbsErr(c, ref - Mp(0.25));
    EXPECT_LE(cErr, bound) << "compensated Horner error above its bound at t=" << Str(t);
    // Compensated Horner: error <= ~eps |p| (final rounding) + O(eps^2) magnitude.
    const double refAbs = std::fabs(static_cast<double>(ref - Mp(0.25)));
    compensated.Add(cErr / (2.2e-16 * refAbs + 4.9e-32 * (mag + 0.25)), Str(t));

    // Derivative and antiderivative: exact relations on the coefficients.
    const hov::Polynomial d = hov::Derivative(p);
    hov::Polynomial a;
    ASSERT_TRUE(hov::Antiderivative(p, a));
    EXPECT_EQ(a.C[0], 0.0);
    for (int i = 0; i < p.Degree; ++i)
    {
      EXPECT_DOUBLE_EQ(d.C[i], (i + 1) * p.C[i + 1]);
    }
    for (int i = 0; i <= p.Degree; ++i)
    {
      EXPECT_DOUBLE_EQ(a.C[i + 1] * (i + 1), p.C[i]);
    }
    // Composition q(x) = p(o + h x) against p evaluated in 50 digits.
    const double o = hovtest::Uniform(rng, -1, 1), h = hovtest::Uniform(rng, -2, 2);
    const hov::Polynomial q = hov::ComposeAffine(p, o, h);
    const double x = hovtest::Uniform(rng, -1, 1);
    const Mp tRef = Mp(o) + Mp(h) * Mp(x);
    compErr.Add(hovtest::AbsErr(hov::Evaluate(q, x), hovtest::EvalMp(p, tRef)) /
        (hovtest::Magnitude(p, static_cast<double>(tRef)) + hovtest::Magnitude(q, x)),
      Str(o) + " " + Str(h));
  }
  hovtest::ReportMeasured("Polynomial.HornerRel", evalErr);
  hovtest::ReportMeasured("Polynomial.CompensatedRel", compensated);
  hovtest::ReportMeasured("Polynomial.ComposeRel", compErr);
  EXPECT_LT(evalErr.Value, 20 * 2.2e-16);
  EXPECT_LT(compensated.Value, 4.0); // in units of eps|p| + eps^2 magnitude
  EXPECT_LT(compErr.Value, 20 * 2.2e-16);
  // Degree 9 has no antiderivative in the fixed storage.
  hov::Polynomial top;
  top.Degree = hov::Polynomial::MaxDegree;
  top.C[top.Degree] = 1.0;
  hov::Polynomial out;
  EXPECT_FALSE(hov::Antiderivative(top, out));
}

TEST(PolynomialRoots, QuadraticCases)
{
  Worst w;
  const double c27 = std::ldexp(1.0, -27); // ~7.5e-9
  ExpectRoots({ 0.25, 0.75 }, { 0.25, 0.75 }, 0, 1, PolyTol.SimpleRootAbs, w);
  ExpectRoots({ 0.0, 1.0 }, { 0.0, 1.0 }, 0, 1, 0.0, w);                 // at both ends
  ExpectRoots({ 0.5, 0.5 }, { 0.5 }, 0, 1, 0.0, w);                      // double root once
  ExpectRoots({ 0.5, 0.5 + c27 }, { 0.5, 0.5 + c27 }, 0, 1, 1e-16, w);   // clustered 7.5e-9
  // Extreme coefficient scales (powers of two, so the coefficients stay exact).
  ExpectRoots({ 0.5, 0.5 + c27 }, { 0.5, 0.5 + c27 }, 0, 1, 1e-16, w, std::ldexp(1.0, -830));
  ExpectRoots({ 0.5, 0.5 + c27 }, { 0.5, 0.5 + c27 }, 0, 1, 1e-16, w, std::ldexp(1.0, 830));
  ExpectRoots({ -0.5, 2.0 }, {}, 0, 1, 0.0, w);                          // none inside
  ExpectRoots({ 0.125, 3.0 }, { 0.125 }, 0, 1, 0.0, w, std::ldexp(1.0, -1000));

  // Touching without crossing: -(t - 0.5)^2 + 0.25 at level 0.25: one root 0.5.
  const hov::Polynomial touch = hov::Polynomial::FromCoefficients({ 0.0, 1.0, -1.0 });
  EXPECT_EQ(Roots(touch, 0.25, 0, 1), std::vector<double>{ 0.5 });
  // Just above the maximum: no root; just below: two roots ~ 0.5 -+ sqrt(d).
  EXPECT_TRUE(Roots(touch, 0.25 + 1e-12, 0, 1).empty());
  const double below = 0.25 - 1e-12;
  const std::vector<double> two = Roots(touch, below, 0, 1);
  ASSERT_EQ(two.size(), 2u);
  const Mp half = sqrt(Mp(0.25) - Mp(below)); // ~1e-6, from the rounded level
  EXPECT_LE(hovtest::AbsErr(two[0], Mp(0.5) - half), 1.2e-16);
  EXPECT_LE(hovtest::AbsErr(two[1], Mp(0.5) + half), 1.2e-16);

  // Nearly linear: a ~ 1e-18 (and exactly 0) gives the linear root, the other
  // root far outside; reference from the 50-digit quadratic formula.
  for (double a : { 1e-18, -1e-18, 1e-300, 0.0, 1e-9 })
  {
    const hov::Polynomial p = hov::Polynomial::FromCoefficients({ -0.3, 1.0, a });
    const std::vector<double> r = Roots(p, 0.0, 0, 1);
    ASSERT_EQ(r.size(), 1u) << "a=" << a;
    const Mp ref = a == 0.0 ? Mp(0.3) : Mp(2 * 0.3) / (Mp(1) + sqrt(Mp(1) + 4 * Mp(a) * Mp(0.3)));
    EXPECT_LE(hovtest::AbsErr(r[0], ref), 1.2e-16) << "a=" << a;
  }
  // Constant and identically-at-level polynomials: no roots, no NaN.
  EXPECT_TRUE(Roots(hov::Polynomial::FromCoefficients({ 2.0 }), 2.0, 0, 1).empty());
  EXPECT_TRUE(Roots(hov::Polynomial::FromCoefficients({ 2.0, 0.0, 0.0 }), 1.0, 0, 1).empty());
  // Bad intervals.
  EXPECT_TRUE(Roots(touch, 0.0, 1, 0).empty());
  EXPECT_TRUE(Roots(touch, 0.0, 0, INFINITY).empty());
  hovtest::ReportMeasured("PolynomialRoots.QuadraticAbs", w);
}

TEST(PolynomialRoots, HigherDegreeConstructedRoots)
{
  Worst simple, multiple;
  const double c27 = std::ldexp(1.0, -27);
  ExpectRoots({ 0.125, 0.5, 0.875 }, { 0.125, 0.5, 0.875 }, 0, 1, PolyTol.SimpleRootAbs, simple);
  ExpectRoots({ 0.0, 0.25, 1.0 }, { 0.0, 0.25, 1.0 }, 0, 1, PolyTol.SimpleRootAbs, simple);
  ExpectRoots({ 0.25, 0.25 + c27, 0.75 }, { 0.25, 0.25 + c27, 0.75 }, 0, 1, PolyTol.SimpleRootAbs, simple);
  ExpectRoots({ 0.25, 0.25 + c27, 0.75 }, { 0.25, 0.25 + c27, 0.75 }, 0, 1, PolyTol.SimpleRootAbs,
    simple, std::ldexp(1.0, 930));
  ExpectRoots({ 0.375, 0.375, 0.75 }, { 0.375, 0.75 }, 0, 1, PolyTol.DoubleRootAbs, multiple);
  ExpectRoots({ 0.5, 0.5, 0.5 }, { 0.5 }, 0, 1, PolyTol.TripleRootAbs, multiple);
  ExpectRoots({ 0.5, 0.5, 0.5, 0.0625 }, { 0.0625, 0.5 }, 0, 1, PolyTol.TripleRootAbs, multiple);
  ExpectRoots({ 0.25, 0.25, 0.75, 0.75 }, { 0.25, 0.75 }, 0, 1, PolyTol.DoubleRootAbs, multiple);
  ExpectRoots({ 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0 },
    { 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0 }, 0, 1, PolyTol.SimpleRootAbs, simple);
  ExpectRoots({ -1.0, 0.0625, 0.5, 2.0, 3.0 }, { 0.0625, 0.5 }, 0, 1, PolyTol.SimpleRootAbs, simple);
  ExpectRoots({ 1.0, 1.0, 0.5 }, { 0.5, 1.0 }, 0, 1, PolyTol.DoubleRootAbs, multiple); // double at end
  ExpectRoots({ 0.5, 0.5, 0.5 }, { 0.5 }, 0.5, 0.5, 0.0, multiple);                    // point interval
  // Tiny and huge t-scales: roots 1e-6 x and 1e6 x those of the unit case (dyadic).
  const double s = std::ldexp(1.0, -20), S = std::ldexp(1.0, 20);
  ExpectRoots({ 0.125 * s, 0.5 * s, 0.75 * s }, { 0.125 * s, 0.5 * s, 0.75 * s }, 0, s,
    PolyTol.SimpleRootAbs * s, simple);
  ExpectRoots({ 0.125 * S, 0.5 * S, 0.75 * S }, { 0.125 * S, 0.5 * S, 0.75 * S }, 0, S,
    PolyTol.SimpleRootAbs * S, simple);
  hovtest::ReportMeasured("PolynomialRoots.SimpleAbs", simple);
  hovtest::ReportMeasured("PolynomialRoots.MultipleAbs", multiple);
}

TEST(PolynomialRoots, TouchingHigherDegreeReportedOnce)
{
  // (t - 0.5)^2 (t + 1) touches 0 at 0.5; at level = its local max value the
  // cubic touches there too.
  bool exact = false;
  const hov::Polynomial p = hovtest::ToPolynomial(hovtest::PolyFromRoots({ 0.5, 0.5, -1.0 }), 1.0, &exact);
  ASSERT_TRUE(exact);
  EXPECT_EQ(Roots(p, 0.0, 0, 1), std::vector<double>{ 0.5 });
  // Local max of (t-0.5)^2 (t+1) is at t = -0.5 with value 0.5: on [-1, 0] the
  // level 0.5 is touched once at -0.5.
  const std::vector<double> r = Roots(p, 0.5, -1, 0);
  ASSERT_EQ(r.size(), 1u) << Describe(r);
  EXPECT_NEAR(r[0], -0.5, 1e-7); // tangency: sqrt(eps)-conditioned
}

TEST(PolynomialRoots, RandomSweepResidualsCompletenessNoNaN)
{
  std::mt19937_64 rng(2024);
  Worst residual, condRatio;
  int found = 0, checked = 0;
  for (int trial = 0; trial < 4000; ++trial)
  {
    const int degree = 1 + trial % 8;
    std::vector<double> roots;
    for (int i = 0; i < degree; ++i)
    {
      roots.push_back(hovtest::Uniform(rng, -0.5, 1.5));
    }
    const double scale = hovtest::LogUniform(rng, 1e-200, 1e200) * (trial % 3 == 0 ? -1 : 1);
    const double tScale = trial % 5 == 0 ? hovtest::LogUniform(rng, 1e-6, 1e6) : 1.0;
    for (double& r : roots)
    {
      r *= tScale;
    }
    const hov::Polynomial p = hovtest::ToPolynomial(hovtest::PolyFromRoots(roots), scale);
    const double level = trial % 4 == 0 ? hov::Evaluate(p, 0.3 * tScale) : 0.0;
    const double lo = 0.0, hi = tScale;
    const std::vector<double> got = Roots(p, level, lo, hi);
    const std::string where = "trial " + std::to_string(trial) + " roots " + Describe(roots) +
      " scale " + Str(scale) + " level " + Str(level);
    for (size_t i = 0; i < got.size(); ++i)
    {
      ASSERT_TRUE(std::isfinite(got[i])) << where;
      ASSERT_GE(got[i], lo);
      ASSERT_LE(got[i], hi);
      if (i > 0)
      {
        ASSERT_LT(got[i - 1], got[i]) << where;
      }
      const double res = hovtest::AbsErr(0.0, hovtest::EvalMp(p, got[i]) - Mp(level)) /
        (hovtest::Magnitude(p, got[i]) + std::fabs(level));
      residual.Add(res, where);
      EXPECT_LE(res, PolyTol.ResidualRel) << where << " root " << Str(got[i]);
    }
    if (level != 0.0)
    {
      continue;
    }
    // Completeness: every constructed root inside, well separated from the
    // others and from the ends, is found within its condition number.
    for (double r : roots)
    {
      double sep = std::min(r - lo, hi - r);
      for (double o : roots)
      {
        sep = o == r ? sep : std::min(sep, std::fabs(o - r));
      }
      if (sep < 1e-3 * tScale)
      {
        continue;
      }
      double v = 0.0, dv = 0.0;
      hov::EvaluateWithDerivative(p, r, v, dv);
      const double cond = 2.2e-16 * hovtest::Magnitude(p, r) / std::fabs(dv);
      double nearest = INFINITY;
      for (double g : got)
      {
        nearest = std::min(nearest, std::fabs(g - r));
      }
      ++checked;
      found += nearest <= PolyTol.ConditionFactor * cond + 4e-16 * tScale;
      condRatio.Add(nearest / (cond + 1e-300), where);
    }
  }
  hovtest::ReportMeasured("PolynomialRoots.SweepResidualRel", residual);
  hovtest::ReportMeasured("PolynomialRoots.SweepErrorOverCondition", condRatio);
  EXPECT_EQ(found, checked) << "worst at " << condRatio.Where;
  EXPECT_GT(checked, 3000);
}

TEST(PolynomialRoots, SolveMonotoneBracketsAndEnds)
{
  // Monotone cubic t^3 + t on [-1, 2] (Newton path) and quadratic t^2 on
  // [0.5, 3] (closed-form path): roots against 50 digits.
  const hov::Polynomial cubic = hov::Polynomial::FromCoefficients({ 0.0, 1.0, 0.0, 1.0 });
  const hov::Polynomial square = hov::Polynomial::FromCoefficients({ 0.0, 0.0, 1.0 });
  Worst w;
  for (double level : { -1.5, 0.0, 0.3, 1.0, 2.0, 9.0 })
  {
    const double r = hov::SolveMonotone(cubic, level, -1.0, 2.0);
    const Mp res = hovtest::EvalMp(cubic, r) - Mp(level);
    // |p(r)| / p'(r): distance to the true root to first order.
    const double dist = std::fabs(static_cast<double>(res)) / (3 * r * r + 1);
    w.Add(dist, Str(level));
    EXPECT_LE(dist, 2.3e-16 * std::max(1.0, std::fabs(r))) << level;
  }
  for (double level : { 0.25, 1.0, 2.0, 8.99 })
  {
    const double r = hov::SolveMonotone(square, level, 0.5, 3.0);
    EXPECT_LE(hovtest::AbsErr(r, sqrt(Mp(level))), 4.5e-16) << level;
  }
  // Not bracketed: the end nearer the level.
  EXPECT_EQ(hov::SolveMonotone(cubic, 100.0, -1.0, 2.0), 2.0);
  EXPECT_EQ(hov::SolveMonotone(cubic, -100.0, -1.0, 2.0), -1.0);
  // Degenerate interval.
  EXPECT_EQ(hov::SolveMonotone(cubic, 0.5, 0.25, 0.25), 0.25);
  hovtest::ReportMeasured("PolynomialRoots.SolveMonotoneDistance", w);
}
