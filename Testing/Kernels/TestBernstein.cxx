// Bernstein-form polynomials (hovBernstein.h): evaluation against the
// monomial form, subdivision, range bounds (containment and tightening),
// products, degree elevation, the degree-8 approximation's rigorous bound,
// and root isolation (simple, clustered, tangent, end roots).
#include "hovBernstein.h"

#include "hovKernelTestUtilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace
{
using hov::BernsteinPolynomial;

BernsteinPolynomial RandomBernstein(int degree, std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  BernsteinPolynomial b;
  b.Degree = degree;
  for (int j = 0; j <= degree; ++j)
  {
    b.B[j] = u(rng);
  }
  return b;
}

/// prod (y - r_i) as a Bernstein polynomial (products of linear factors).
BernsteinPolynomial FromRoots(const std::vector<double>& roots, double scale)
{
  BernsteinPolynomial p;
  p.Degree = 0;
  p.B[0] = scale;
  for (double r : roots)
  {
    BernsteinPolynomial f;
    f.Degree = 1;
    f.B[0] = -r;
    f.B[1] = 1.0 - r;
    EXPECT_TRUE(hov::MultiplyBernstein(p, f, p));
  }
  return p;
}

double DirectProduct(const std::vector<double>& roots, double scale, double y)
{
  double v = scale;
  for (double r : roots)
  {
    v *= y - r;
  }
  return v;
}

TEST(Bernstein, EvaluationMatchesMonomialForm)
{
  std::mt19937_64 rng(81);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  hovtest::Worst worst;
  for (int degree = 0; degree <= 9; ++degree)
  {
    hov::Polynomial p;
    p.Degree = degree;
    for (int k = 0; k <= degree; ++k)
    {
      p.C[k] = u(rng);
    }
    const BernsteinPolynomial b = hov::BernsteinFromMonomial(p, degree + 3); // elevated too
    for (int i = 0; i <= 100; ++i)
    {
      const double y = i / 100.0;
      double v, s;
      hov::EvaluateBernsteinWithDerivative(b, y, v, s);
      const double err = std::abs(v - hov::Evaluate(p, y));
      worst.Add(err, "degree " + std::to_string(degree));
      EXPECT_LE(err, 1e-14);
      EXPECT_NEAR(s, hov::Evaluate(hov::Derivative(p), y), 1e-12);
      EXPECT_NEAR(hov::EvaluateBernstein(hov::BernsteinDerivative(b), y), s, 1e-12);
    }
  }
  hovtest::ReportMeasured("Bernstein.EvaluateVsMonomial", worst);
}

TEST(Bernstein, SubdivisionElevationAndProducts)
{
  std::mt19937_64 rng(82);
  for (int degree : { 1, 3, 8, 17, 30 })
  {
    const BernsteinPolynomial b = RandomBernstein(degree, rng);
    BernsteinPolynomial left, right;
    hov::SubdivideBernstein(b, 0.3, &left, &right);
    const BernsteinPolynomial mid = hov::RestrictBernstein(b, 0.2, 0.7);
    const BernsteinPolynomial high = hov::ElevateBernstein(b, std::min(degree + 5, 30));
    const BernsteinPolynomial other = RandomBernstein(std::min(4, 30 - degree), rng);
    BernsteinPolynomial prod;
    ASSERT_TRUE(hov::MultiplyBernstein(b, other, prod) || degree + other.Degree > 30);
    for (int i = 0; i <= 50; ++i)
    {
      const double y = i / 50.0, v = hov::EvaluateBernstein(b, y);
      EXPECT_NEAR(hov::EvaluateBernstein(left, y), hov::EvaluateBernstein(b, 0.3 * y), 1e-13);
      EXPECT_NEAR(hov::EvaluateBernstein(right, y), hov::EvaluateBernstein(b, 0.3 + 0.7 * y), 1e-13);
      EXPECT_NEAR(hov::EvaluateBernstein(mid, y), hov::EvaluateBernstein(b, 0.2 + 0.5 * y), 1e-13);
      EXPECT_NEAR(hov::EvaluateBernstein(high, y), v, 1e-13);
      if (degree + other.Degree <= 30)
      {
        EXPECT_NEAR(hov::EvaluateBernstein(prod, y), v * hov::EvaluateBernstein(other, y), 1e-13);
      }
    }
  }
  BernsteinPolynomial tooHigh = RandomBernstein(20, rng), out;
  EXPECT_FALSE(hov::MultiplyBernstein(tooHigh, tooHigh, out));
}

TEST(Bernstein, RangeContainsSamplesAndTightensQuadratically)
{
  std::mt19937_64 rng(83);
  hovtest::Worst ratio16;
  for (int trial = 0; trial < 40; ++trial)
  {
    const int degree = 2 + trial % 25;
    const BernsteinPolynomial b = RandomBernstein(degree, rng);
    double sampleLo = 1e300, sampleHi = -1e300;
    for (int i = 0; i <= 4000; ++i)
    {
      const double v = hov::EvaluateBernstein(b, i / 4000.0);
      sampleLo = std::min(sampleLo, v);
      sampleHi = std::max(sampleHi, v);
    }
    double over[3];
    const int pieces[3] = { 1, 4, 16 };
    for (int k = 0; k < 3; ++k)
    {
      double lo, hi;
      hov::BernsteinRangeSubdivided(b, pieces[k], lo, hi);
      ASSERT_LE(lo, sampleLo + 1e-15) << "degree " << degree << " pieces " << pieces[k];
      ASSERT_GE(hi, sampleHi - 1e-15);
      over[k] = (hi - lo) - (sampleHi - sampleLo);
    }
    // Overestimation O(h^2): 16x finer pieces -> <= 1/16 of the 4-piece excess (h^2 predicts 1/16... with slack).
    EXPECT_LE(over[2], over[1] / 4 + 1e-12 * (sampleHi - sampleLo)) << "degree " << degree;
    ratio16.Add((over[2]) / (sampleHi - sampleLo), "degree " + std::to_string(degree));
  }
  hovtest::ReportMeasured("Bernstein.RelativeOverestimate16Pieces", ratio16);
}

TEST(Bernstein, ApproximationBoundIsRigorousAndUseful)
{
  std::mt19937_64 rng(84);
  hovtest::Worst slack;
  for (int trial = 0; trial < 60; ++trial)
  {
    const int degree = 1 + trial % 30;
    // A smooth high-degree polynomial: Bernstein coefficients of exp(2y) sin(3y) (decaying series).
    BernsteinPolynomial b;
    b.Degree = degree;
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double shift = u(rng);
    for (int j = 0; j <= degree; ++j)
    {
      const double y = static_cast<double>(j) / degree;
      b.B[j] = std::exp(2.0 * y) * std::sin(3.0 * y + shift);
    }
    double bound = 0.0;
    const hov::Polynomial q = hov::ApproximateBernstein(b, 8, bound);
    double actual = 0.0;
    for (int i = 0; i <= 2000; ++i)
    {
      const double y = i / 2000.0;
      actual = std::max(actual, std::abs(hov::EvaluateBernstein(b, y) - hov::Evaluate(q, y)));
    }
    ASSERT_LE(actual, bound) << "degree " << degree;
    if (degree <= 8)
    {
      EXPECT_LE(bound, 1e-12) << "degree " << degree; // exact conversion (allowance only)
    }
    else
    {
      EXPECT_LE(bound, 1e4 * actual + 1e-13) << "degree " << degree;
      slack.Add(bound / actual, "degree " + std::to_string(degree));
    }
  }
  hovtest::ReportMeasured("Bernstein.ApproximationBoundOverActual", slack);
}

TEST(Bernstein, RootsOfKnownProducts)
{
  std::mt19937_64 rng(85);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  hovtest::Worst worst, conditioned;
  for (int trial = 0; trial < 200; ++trial)
  {
    std::vector<double> roots;
    const int count = 1 + trial % 12;
    for (int i = 0; i < count; ++i)
    {
      roots.push_back(u(rng));
    }
    roots.push_back(1.7); // one outside [0,1]
    std::sort(roots.begin(), roots.end());
    const BernsteinPolynomial b = FromRoots(roots, 3.0);
    double found[32];
    bool complete = false;
    const int n = hov::BernsteinRoots(b, 0.0, found, 32, {}, &complete);
    EXPECT_TRUE(complete);
    // Roots closer than the problem's conditioning allows may merge: compare with a tolerance.
    std::vector<double> inside(roots.begin(), roots.end() - 1);
    ASSERT_LE(n, count);
    for (int i = 0; i < n; ++i)
    {
      double nearest = 1.0;
      for (double r : inside)
      {
        nearest = std::min(nearest, std::abs(r - found[i]));
      }
      worst.Add(nearest, "trial " + std::to_string(trial));
      EXPECT_LE(nearest, 1e-6) << "trial " << trial;
      EXPECT_LE(std::abs(DirectProduct(roots, 3.0, found[i])), 1e-12);
    }
    // Every true root well separated from the others is found, to within its
    // conditioning: (rounding of the coefficients ~ eps max|B|) / |p'(r)|.
    double maxB = 0.0;
    for (int j = 0; j <= b.Degree; ++j)
    {
      maxB = std::max(maxB, std::abs(b.B[j]));
    }
    for (size_t i = 0; i < inside.size(); ++i)
    {
      const double gap = std::min(i > 0 ? inside[i] - inside[i - 1] : 1.0,
        i + 1 < inside.size() ? inside[i + 1] - inside[i] : 1.0);
      if (gap < 1e-3)
      {
        continue;
      }
      double slope = 3.0;
      for (size_t j = 0; j < roots.size(); ++j)
      {
        slope *= (j == i) ? 1.0 : inside[i] - roots[j];
      }
      const double tol = 1e-14 + 64 * 2.2e-16 * maxB / std::abs(slope);
      double nearest = 1.0;
      for (int k = 0; k < n; ++k)
      {
        nearest = std::min(nearest, std::abs(found[k] - inside[i]));
      }
      EXPECT_LE(nearest, tol) << "trial " << trial << " root " << inside[i];
      conditioned.Add(nearest / tol, "trial " + std::to_string(trial));
    }
  }
  hovtest::ReportMeasured("Bernstein.RootDistance", worst);
  hovtest::ReportMeasured("Bernstein.RootErrorOverConditioning", conditioned);
}

TEST(Bernstein, TangentEndAndNoRoots)
{
  // (y - 0.4)^2 (y - 0.9): the tangency at 0.4 is reported at most once (its
  // rounded coefficients may lift it off the axis), the simple root 0.9 always.
  const BernsteinPolynomial b = FromRoots({ 0.4, 0.4, 0.9 }, 1.0);
  double r[8];
  int n = hov::BernsteinRoots(b, 0.0, r, 8);
  ASSERT_TRUE(n == 1 || n == 2);
  if (n == 2)
  {
    EXPECT_NEAR(r[0], 0.4, 1e-6);
  }
  EXPECT_NEAR(r[n - 1], 0.9, 1e-14);
  // An exactly representable tangency, (y - 1/2)^2 = 0: one root at 1/2.
  BernsteinPolynomial t;
  t.Degree = 2;
  t.B[0] = 0.25;
  t.B[1] = -0.25;
  t.B[2] = 0.25;
  n = hov::BernsteinRoots(t, 0.0, r, 8);
  ASSERT_EQ(n, 1);
  EXPECT_EQ(r[0], 0.5);
  // Level equal to the value at both ends: y (1 - y) + 0.25 = 0.25 at y = 0 and 1.
  BernsteinPolynomial q;
  q.Degree = 2;
  q.B[0] = 0.25;
  q.B[1] = 0.75;
  q.B[2] = 0.25;
  n = hov::BernsteinRoots(q, 0.25, r, 8);
  ASSERT_EQ(n, 2);
  EXPECT_EQ(r[0], 0.0);
  EXPECT_EQ(r[1], 1.0);
  // No root: the maximum 0.5 is below the level 0.51.
  EXPECT_EQ(hov::BernsteinRoots(q, 0.51, r, 8), 0);
  // Equispaced Lagrange basis polynomials are nodal.
  for (int deg : { 1, 5, 12 })
  {
    for (int i = 0; i <= deg; ++i)
    {
      const BernsteinPolynomial l = hov::EquispacedLagrangeBernstein(deg, i);
      for (int m = 0; m <= deg; ++m)
      {
        EXPECT_NEAR(hov::EvaluateBernstein(l, static_cast<double>(m) / deg), m == i ? 1.0 : 0.0,
          1e-12);
      }
    }
  }
}
}
