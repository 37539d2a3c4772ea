// Lagrange shape functions (hovLagrangeBasis.h): partition of unity, nodal
// interpolation, reproduction of polynomials of the cell's degree,
// derivatives against central differences, orders and bad input.
// (The cross-check against VTK's own functions is Testing/Cxx/TestLagrangeVTKShapes.)
#include "hovLagrangeBasis.h"
#include "hovLagrangeCell.h"

#include "hovKernelTestUtilities.h"
#include "hovLagrangeTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
using hov::LagrangeShape;
using hovtest::AllLagrangeCases;
using hovtest::LagrangeCase;

TEST(LagrangeBasis, PartitionOfUnityAndNodalInterpolation)
{
  std::mt19937_64 rng(61);
  hovtest::Worst unity, nodal;
  for (const LagrangeCase& c : AllLagrangeCases(8))
  {
    hov::LagrangeBasis b;
    ASSERT_TRUE(hovtest::InitBasis(c, b)) << c.Name();
    const int n = b.GetNodeCount();
    std::vector<double> w(n);
    for (int trial = 0; trial < 20; ++trial)
    {
      double pc[3];
      hovtest::RandomPC(b, rng, 0.0, pc);
      b.Functions(pc, w.data());
      double sum = 0.0;
      for (double v : w)
      {
        sum += v;
      }
      unity.Add(std::abs(sum - 1.0), c.Name());
      EXPECT_NEAR(sum, 1.0, 1e-12) << c.Name();
    }
    for (int j = 0; j < n; ++j)
    {
      double pc[3];
      b.NodeParametricCoords(j, pc);
      EXPECT_LE(b.DistanceOutside(pc), 1e-15) << c.Name() << " node " << j;
      b.Functions(pc, w.data());
      for (int i = 0; i < n; ++i)
      {
        const double err = std::abs(w[i] - (i == j ? 1.0 : 0.0));
        nodal.Add(err, c.Name());
        ASSERT_LE(err, 1e-12) << c.Name() << " w" << i << " at node " << j;
      }
    }
  }
  hovtest::ReportMeasured("LagrangeBasis.UnityError", unity);
  hovtest::ReportMeasured("LagrangeBasis.NodalError", nodal);
}

/// A polynomial of the cell's own degree in each direction (hexahedra: r^p0 s^p1 t^p2 terms;
/// tetrahedra: total degree n; wedges: (r,s) total degree p times t^q).
double CellPolynomial(const LagrangeCase& c, const double* x)
{
  const double r = x[0], s = x[1], t = x[2];
  const int* p = c.Order;
  switch (c.Shape)
  {
    case LagrangeShape::Hexahedron:
      return std::pow(r + 0.3, p[0]) * std::pow(0.7 - s, p[1]) * std::pow(t + 0.1, p[2]) + r * s;
    case LagrangeShape::Wedge:
      return (std::pow(r + 0.5 * s + 0.2, p[0]) - s) * std::pow(t - 0.4, p[2]);
    default:
      return std::pow(0.3 + r - 0.7 * s + 0.2 * t, p[0]) + std::pow(s + t, p[0]);
  }
}

TEST(LagrangeBasis, ReproducesPolynomialsOfItsDegree)
{
  std::mt19937_64 rng(62);
  hovtest::Worst worst;
  for (const LagrangeCase& c : AllLagrangeCases(8))
  {
    if (c.NodeCount)
    {
      continue; // the special cells do not span the full space (checked against VTK)
    }
    hov::LagrangeBasis b;
    ASSERT_TRUE(hovtest::InitBasis(c, b));
    const int n = b.GetNodeCount();
    std::vector<double> f(n);
    for (int i = 0; i < n; ++i)
    {
      double pc[3];
      b.NodeParametricCoords(i, pc);
      f[i] = CellPolynomial(c, pc);
    }
    for (int trial = 0; trial < 20; ++trial)
    {
      double pc[3], v, g[3];
      hovtest::RandomPC(b, rng, 0.0, pc);
      b.Interpolate(pc, f.data(), 1, &v, g);
      const double err = std::abs(v - CellPolynomial(c, pc));
      worst.Add(err, c.Name());
      EXPECT_LE(err, 1e-11) << c.Name();
    }
  }
  hovtest::ReportMeasured("LagrangeBasis.PolynomialReproduction", worst);
}

TEST(LagrangeBasis, DerivativesMatchCentralDifferences)
{
  std::mt19937_64 rng(63);
  hovtest::Worst worst;
  for (const LagrangeCase& c : AllLagrangeCases(8))
  {
    hov::LagrangeBasis b;
    ASSERT_TRUE(hovtest::InitBasis(c, b));
    const int n = b.GetNodeCount();
    std::vector<double> d(3 * n), w(n), wp(n), wm(n), w2(n);
    for (int trial = 0; trial < 5; ++trial)
    {
      double pc[3];
      hovtest::RandomPC(b, rng, 0.02, pc);
      b.FunctionsAndDerivatives(pc, w.data(), d.data());
      b.Functions(pc, w2.data());
      for (int k = 0; k < 3; ++k)
      {
        // 4th-order central difference, h = 1e-3: truncation ~h^4 |w^(5)| ~ 1e-9 for p <= 8.
        const double h = 1e-3;
        double q[4][3];
        std::vector<double> wq[4] = { std::vector<double>(n), std::vector<double>(n),
          std::vector<double>(n), std::vector<double>(n) };
        const double off[4] = { -2 * h, -h, h, 2 * h };
        for (int m = 0; m < 4; ++m)
        {
          std::copy(pc, pc + 3, q[m]);
          q[m][k] += off[m];
          b.Functions(q[m], wq[m].data());
        }
        double scale = 1.0;
        for (int i = 0; i < n; ++i)
        {
          scale = std::max(scale, std::abs(d[k * n + i]));
        }
        for (int i = 0; i < n; ++i)
        {
          ASSERT_EQ(w[i], w2[i]) << c.Name();
          const double fd = (wq[0][i] - 8 * wq[1][i] + 8 * wq[2][i] - wq[3][i]) / (12 * h);
          const double err = std::abs(fd - d[k * n + i]) / scale;
          worst.Add(err, c.Name());
          ASSERT_LE(err, 1e-6) << c.Name() << " node " << i << " dir " << k;
        }
      }
    }
  }
  hovtest::ReportMeasured("LagrangeBasis.DerivativeVsFD", worst);
}

/// Interpolate() (sum-factorised for hexahedra, tetrahedra and wedges) against
/// the weighted sum of FunctionsAndDerivatives() (the node loop), for 1-4
/// components, every shape and order up to MaxLagrangeOrder.
TEST(LagrangeBasis, InterpolateMatchesWeights)
{
  std::mt19937_64 rng(64);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  hovtest::Worst worst;
  int cases = 0;
  for (const LagrangeCase& c : AllLagrangeCases(hov::MaxLagrangeOrder))
  {
    hov::LagrangeBasis b;
    ASSERT_TRUE(hovtest::InitBasis(c, b)) << c.Name();
    const int n = b.GetNodeCount();
    std::vector<double> w(n), d(3 * n), values(4 * n);
    for (double& v : values)
    {
      v = value(rng);
    }
    for (int trial = 0; trial < 4; ++trial)
    {
      double pc[3];
      hovtest::RandomPC(b, rng, 0.0, pc);
      b.FunctionsAndDerivatives(pc, w.data(), d.data());
      // The scale of the sums: sum |w_i| and sum |dw_i| (the values are in [-1, 1]).
      double scaleW = 0.0, scaleD = 0.0;
      for (int i = 0; i < n; ++i)
      {
        scaleW += std::abs(w[i]);
        scaleD += std::abs(d[i]) + std::abs(d[n + i]) + std::abs(d[2 * n + i]);
      }
      for (int comps = 1; comps <= 4; ++comps)
      {
        double v[4], g[12], vOnly[4];
        b.Interpolate(pc, values.data(), comps, v, g);
        b.Interpolate(pc, values.data(), comps, vOnly, nullptr);
        ++cases;
        for (int k = 0; k < comps; ++k)
        {
          double ref = 0.0, refG[3] = { 0.0, 0.0, 0.0 };
          for (int i = 0; i < n; ++i)
          {
            const double x = values[static_cast<size_t>(i) * comps + k];
            ref += w[i] * x;
            for (int m = 0; m < 3; ++m)
            {
              refG[m] += d[m * n + i] * x;
            }
          }
          const double ev = std::abs(v[k] - ref) / scaleW;
          worst.Add(ev, c.Name());
          ASSERT_LE(ev, 1e-14) << c.Name() << " components " << comps;
          ASSERT_LE(std::abs(vOnly[k] - ref) / scaleW, 1e-14) << c.Name() << " without gradient";
          for (int m = 0; m < 3; ++m)
          {
            const double eg = std::abs(g[3 * k + m] - refG[m]) / scaleD;
            worst.Add(eg, c.Name());
            ASSERT_LE(eg, 1e-14) << c.Name() << " components " << comps << " d/dpc" << m;
          }
        }
      }
    }
  }
  EXPECT_GT(cases, 100);
  hovtest::ReportMeasured("LagrangeBasis.InterpolateVsWeights", worst);
}

TEST(LagrangeBasis, OrdersFromPointCountsAndDegrees)
{
  hov::LagrangeBasis b;
  std::string msg;
  ASSERT_TRUE(b.Initialize(LagrangeShape::Tetra, 35));
  EXPECT_EQ(b.GetOrder()[0], 4);
  EXPECT_EQ(b.GetLineDegree(), 4);
  ASSERT_TRUE(b.Initialize(LagrangeShape::Hexahedron, 125));
  EXPECT_EQ(b.GetOrder()[2], 4);
  EXPECT_EQ(b.GetLineDegree(), 12);
  const int degrees[3] = { 2, 3, 1 };
  ASSERT_TRUE(b.Initialize(LagrangeShape::Hexahedron, 24, degrees));
  EXPECT_EQ(b.GetOrder()[1], 3);
  ASSERT_TRUE(b.Initialize(LagrangeShape::Wedge, 40)); // (p+1)(p+2)/2 (p+1) = 40 at p = 3
  EXPECT_EQ(b.GetOrder()[0], 3);
  EXPECT_EQ(b.GetLineDegree(), 6);
  // Bad input: messages, not crashes.
  EXPECT_FALSE(b.Initialize(LagrangeShape::Tetra, 11, nullptr, &msg));
  EXPECT_NE(msg.find("11 nodes"), std::string::npos) << msg;
  EXPECT_FALSE(b.IsInitialized());
  const int bad[3] = { 2, 3, 2 };
  EXPECT_FALSE(b.Initialize(LagrangeShape::Wedge, 36, bad, &msg));
  EXPECT_NE(msg.find("differ"), std::string::npos) << msg;
  EXPECT_FALSE(b.Initialize(static_cast<LagrangeShape>(74), 5, nullptr, &msg));
  EXPECT_NE(msg.find("74"), std::string::npos) << msg;
  const int tooHigh[3] = { 11, 11, 11 };
  EXPECT_FALSE(b.Initialize(LagrangeShape::Hexahedron, 1728, tooHigh, &msg));
  EXPECT_FALSE(b.Initialize(LagrangeShape::Hexahedron, 27, degrees, &msg)); // 24 != 27
}
}
