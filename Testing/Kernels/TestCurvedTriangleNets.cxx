// Triangular Bernstein nets of the curved face search (hovCurvedTriangleNets.h)
// and the corner-polygon exclusion (hovCurvedFaceNets.h), against independent
// evaluations:
//  - EquispacedTriangleBernstein recovers random control nets from their
//    values at the equispaced points, degrees 1..10 (the conversion's rounding
//    amplification is reported);
//  - EvaluateTriangleNet equals the explicit multinomial sum (factorials and
//    powers, written out here) and its derivatives equal central differences;
//  - SplitTriangleNet: each child's net, evaluated in its own coordinates,
//    equals the parent at the same point, for the three edges;
//  - SeparatedByCorners never excludes a net whose polynomial vanishes in the
//    triangle (random nets shifted to a random point of it), and excludes
//    nets shifted beyond their hull.
#include "hovCurvedFaceNets.h"
#include "hovCurvedTriangleNets.h"

#include "hovKernelTestUtilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
using hov::detail::TriangleNetIndex;
using hov::detail::TriangleNetSize;

double Factorial(int n)
{
  double f = 1.0;
  for (int k = 2; k <= n; ++k)
  {
    f *= k;
  }
  return f;
}

/// The explicit sum of n! / (i! j! k!) (1-u-v)^i u^j v^k b_{ijk}, one component.
double Explicit(const std::vector<double>& net, int n, int dim, int c, double u, double v)
{
  double s = 0.0;
  for (int j = 0; j <= n; ++j)
  {
    for (int k = 0; j + k <= n; ++k)
    {
      const int i = n - j - k;
      s += Factorial(n) / (Factorial(i) * Factorial(j) * Factorial(k)) * std::pow(1.0 - u - v, i) *
        std::pow(u, j) * std::pow(v, k) * net[dim * TriangleNetIndex(n, j, k) + c];
    }
  }
  return s;
}

std::vector<double> RandomNet(std::mt19937_64& rng, int n, int dim)
{
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  std::vector<double> net(dim * TriangleNetSize(n));
  for (double& x : net)
  {
    x = r(rng);
  }
  return net;
}

TEST(CurvedTriangleNets, EquispacedValuesConvertToTheirControlNet)
{
  std::mt19937_64 rng(301);
  double worst = 0.0;
  for (int n = 1; n <= 10; ++n)
  {
    const std::vector<double> net = RandomNet(rng, n, 3);
    std::vector<double> values(net.size()), back(net.size());
    for (int j = 0; j <= n; ++j)
    {
      for (int k = 0; j + k <= n; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          values[3 * TriangleNetIndex(n, j, k) + c] =
            Explicit(net, n, 3, c, static_cast<double>(j) / n, static_cast<double>(k) / n);
        }
      }
    }
    ASSERT_TRUE(hov::detail::EquispacedTriangleBernstein(n, values.data(), 3, 3, back.data()));
    double err = 0.0;
    for (size_t q = 0; q < net.size(); ++q)
    {
      err = std::max(err, std::abs(back[q] - net[q]));
    }
    EXPECT_LE(err, 1e-11) << "degree " << n;
    worst = std::max(worst, err);
  }
  std::vector<double> dummy(3 * TriangleNetSize(11));
  EXPECT_FALSE(hov::detail::EquispacedTriangleBernstein(0, dummy.data(), 3, 3, dummy.data()));
  EXPECT_FALSE(hov::detail::EquispacedTriangleBernstein(11, dummy.data(), 3, 3, dummy.data()));
  hovtest::ReportMeasured("CurvedTriangleNets.EquispacedRoundTrip", worst);
}

TEST(CurvedTriangleNets, EvaluationAndDerivativesMatchTheExplicitSum)
{
  std::mt19937_64 rng(302);
  std::uniform_real_distribution<double> p(-0.2, 1.0);
  double worstValue = 0.0, worstDerivative = 0.0;
  for (int n = 1; n <= 10; ++n)
  {
    const std::vector<double> net = RandomNet(rng, n, 3);
    for (int trial = 0; trial < 10; ++trial)
    {
      const double u = p(rng), v = p(rng) * (1.0 - u); // also a little outside
      double x[3], xu[3], xv[3];
      hov::detail::EvaluateTriangleNet(net.data(), n, u, v, x, xu, xv);
      const double h = 1e-6;
      for (int c = 0; c < 3; ++c)
      {
        const double fu =
          (Explicit(net, n, 3, c, u + h, v) - Explicit(net, n, 3, c, u - h, v)) / (2 * h);
        const double fv =
          (Explicit(net, n, 3, c, u, v + h) - Explicit(net, n, 3, c, u, v - h)) / (2 * h);
        const double ev = std::abs(x[c] - Explicit(net, n, 3, c, u, v));
        const double ed = std::max(std::abs(xu[c] - fu), std::abs(xv[c] - fv));
        EXPECT_LE(ev, 1e-12) << "degree " << n;
        EXPECT_LE(ed, 1e-6 * (1.0 + std::abs(fu) + std::abs(fv))) << "degree " << n;
        worstValue = std::max(worstValue, ev);
        worstDerivative = std::max(worstDerivative, ed);
      }
    }
  }
  hovtest::ReportMeasured("CurvedTriangleNets.EvaluationVsExplicit", worstValue);
  hovtest::ReportMeasured("CurvedTriangleNets.DerivativeVsCentralDifference", worstDerivative);
}

TEST(CurvedTriangleNets, SplitChildrenEqualTheParent)
{
  std::mt19937_64 rng(303);
  std::uniform_real_distribution<double> p(0.0, 1.0);
  const double corners[3][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
  double worst = 0.0;
  for (int n = 1; n <= 10; ++n)
  {
    const std::vector<double> net = RandomNet(rng, n, 1);
    for (int m = 0; m < 3; ++m)
    {
      std::vector<double> first(net.size()), second(net.size());
      hov::detail::SplitTriangleNet(net.data(), first.data(), second.data(), n, m);
      const int a = m == 0 ? 1 : 0, b = m == 2 ? 1 : 2;
      const double mid[2] = { 0.5 * (corners[a][0] + corners[b][0]),
        0.5 * (corners[a][1] + corners[b][1]) };
      for (int child = 0; child < 2; ++child)
      {
        double P[3][2];
        for (int q = 0; q < 3; ++q)
        {
          const bool moved = q == (child == 0 ? b : a);
          P[q][0] = moved ? mid[0] : corners[q][0];
          P[q][1] = moved ? mid[1] : corners[q][1];
        }
        const std::vector<double>& sub = child == 0 ? first : second;
        for (int trial = 0; trial < 5; ++trial)
        {
          double s = p(rng), t = p(rng);
          if (s + t > 1.0)
          {
            s = 1.0 - s;
            t = 1.0 - t;
          }
          const double u = P[0][0] + s * (P[1][0] - P[0][0]) + t * (P[2][0] - P[0][0]);
          const double v = P[0][1] + s * (P[1][1] - P[0][1]) + t * (P[2][1] - P[0][1]);
          const double e = std::abs(Explicit(sub, n, 1, 0, s, t) - Explicit(net, n, 1, 0, u, v));
          EXPECT_LE(e, 1e-12) << "degree " << n << " edge " << m << " child " << child;
          worst = std::max(worst, e);
        }
      }
    }
  }
  hovtest::ReportMeasured("CurvedTriangleNets.SplitVsParent", worst);
}

TEST(CurvedTriangleNets, CornerSeparationNeverExcludesAZero)
{
  std::mt19937_64 rng(304);
  std::uniform_real_distribution<double> p(0.0, 1.0);
  int excludedFar = 0, farCases = 0;
  for (int n = 1; n <= 8; ++n)
  {
    const int size = TriangleNetSize(n);
    const int corners[3] = { TriangleNetIndex(n, 0, 0), TriangleNetIndex(n, n, 0),
      TriangleNetIndex(n, 0, n) };
    for (int trial = 0; trial < 200; ++trial)
    {
      // A mildly curved 2D net (a perturbed affine map), shifted so that the
      // polynomial vanishes at a random point of the triangle.
      std::vector<double> net = RandomNet(rng, n, 2);
      for (int j = 0; j <= n; ++j)
      {
        for (int k = 0; j + k <= n; ++k)
        {
          double* q = &net[2 * TriangleNetIndex(n, j, k)];
          q[0] = 0.3 * q[0] + static_cast<double>(j) / n;
          q[1] = 0.3 * q[1] + static_cast<double>(k) / n;
        }
      }
      double s = p(rng), t = p(rng);
      if (s + t > 1.0)
      {
        s = 1.0 - s;
        t = 1.0 - t;
      }
      double x[3], xu[3], xv[3];
      std::vector<double> net3(3 * size, 0.0);
      for (int q = 0; q < size; ++q)
      {
        net3[3 * q] = net[2 * q];
        net3[3 * q + 1] = net[2 * q + 1];
      }
      hov::detail::EvaluateTriangleNet(net3.data(), n, s, t, x, xu, xv);
      std::vector<double> h0(size), h1(size);
      for (int q = 0; q < size; ++q)
      {
        h0[q] = net[2 * q] - x[0];
        h1[q] = net[2 * q + 1] - x[1];
      }
      const double* split[2] = { h0.data(), h1.data() };
      EXPECT_FALSE(hov::detail::SeparatedByCorners(split, size, corners, 3, 1e-12))
        << "degree " << n << " zero at (" << s << ", " << t << ")";
      // Stretched along x = -y and moved beyond the line x + y = 1: both
      // components change sign over the net (the axes do not separate it),
      // the normal of the corners' first edge does.
      for (int q = 0; q < size; ++q)
      {
        h0[q] = 5.0 * net[2 * q] - 2.0;
        h1[q] = 3.2 - 5.0 * net[2 * q] + 0.1 * net[2 * q + 1];
      }
      ++farCases;
      EXPECT_FALSE(hov::detail::OneSide(h0.data(), size, 1e-12) ||
        hov::detail::OneSide(h1.data(), size, 1e-12));
      excludedFar += hov::detail::SeparatedByCorners(split, size, corners, 3, 1e-12) ? 1 : 0;
    }
  }
  EXPECT_EQ(excludedFar, farCases);
  std::cout << "[measured] corner separation: " << excludedFar << " of " << farCases
            << " far nets excluded" << std::endl;
}
}
