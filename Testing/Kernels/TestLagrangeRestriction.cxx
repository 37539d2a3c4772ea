// A Lagrange field along a parametric line in Bernstein form
// (hovLagrangeRestriction.h) against pointwise interpolation, for every
// type and order 1..10, lines inside and reaching outside the domain, and
// the stated rounding bound.
#include "hovLagrangeRestriction.h"

#include "hovKernelTestUtilities.h"
#include "hovLagrangeTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
using hovtest::LagrangeCase;

TEST(LagrangeRestriction, MatchesPointwiseInterpolation)
{
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  hovtest::Worst worst, boundRatio;
  for (const LagrangeCase& c : hovtest::AllLagrangeCases(10))
  {
    hov::LagrangeBasis b;
    ASSERT_TRUE(hovtest::InitBasis(c, b)) << c.Name();
    const int n = b.GetNodeCount();
    std::vector<double> f(n);
    double scale = 0.0;
    for (double& v : f)
    {
      v = u(rng);
      scale = std::max(scale, std::abs(v));
    }
    for (int trial = 0; trial < 6; ++trial)
    {
      double a[3], e[3], step[3];
      hovtest::RandomPC(b, rng, 0.0, a);
      hovtest::RandomPC(b, rng, 0.0, e);
      const double stretch = trial < 3 ? 1.0 : 1.3; // trials 3-5 leave the domain
      for (int k = 0; k < 3; ++k)
      {
        step[k] = stretch * (e[k] - a[k]);
      }
      hov::BernsteinPolynomial g;
      double rounding = 0.0;
      ASSERT_TRUE(hov::LagrangeFieldAlongLine(b, f.data(), a, step, g, &rounding));
      ASSERT_EQ(g.Degree, b.GetLineDegree()) << c.Name();
      double err = 0.0, pointScale = 0.0;
      for (int i = 0; i <= 40; ++i)
      {
        const double y = i / 40.0;
        const double pc[3] = { a[0] + y * step[0], a[1] + y * step[1], a[2] + y * step[2] };
        double v;
        b.Interpolate(pc, f.data(), 1, &v, nullptr);
        err = std::max(err, std::abs(hov::EvaluateBernstein(g, y) - v));
        pointScale = std::max(pointScale, std::abs(v));
      }
      // The pointwise interpolation has its own rounding (~ N eps sum|w_i| |f_i|):
      // compare on the scale of the node values, which bounds both.
      worst.Add(err / scale, c.Name());
      EXPECT_LE(err, 1e-11 * scale) << c.Name() << " trial " << trial;
      boundRatio.Add(rounding / scale, c.Name());
    }
  }
  hovtest::ReportMeasured("LagrangeRestriction.ErrorOverNodeScale", worst);
  hovtest::ReportMeasured("LagrangeRestriction.RoundingBoundOverNodeScale", boundRatio);
}

TEST(LagrangeRestriction, ExactForAPolynomialAlongAnAxisLine)
{
  // Hexahedron of order 8 with f = r^8 (only the r direction varies):
  // along r = y the Bernstein coefficients of y^8 are exactly (0, ..., 0, 1).
  hov::LagrangeBasis b;
  ASSERT_TRUE(b.Initialize(hov::LagrangeShape::Hexahedron, 729));
  std::vector<double> f(729);
  for (int i = 0; i < 729; ++i)
  {
    double pc[3];
    b.NodeParametricCoords(i, pc);
    f[i] = std::pow(pc[0], 8);
  }
  const double start[3] = { 0.0, 0.25, 0.5 }, step[3] = { 1.0, 0.0, 0.0 };
  hov::BernsteinPolynomial g;
  double rounding = 0.0;
  ASSERT_TRUE(hov::LagrangeFieldAlongLine(b, f.data(), start, step, g, &rounding));
  // Degree 24 representation of y^8: B[j] = C(j,8)/C(24,8).
  for (int j = 0; j <= 24; ++j)
  {
    const double expected = hov::Binomial(j, 8) / hov::Binomial(24, 8);
    EXPECT_NEAR(g.B[j], expected, 1e-14) << j;
    EXPECT_LE(std::abs(g.B[j] - expected), rounding + 1e-300) << j;
  }
}
}
