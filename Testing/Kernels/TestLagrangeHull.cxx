// The Bernstein-Bezier hull of a Lagrange cell's field (hovLagrangeHull.h):
//  - the coefficients reproduce the Lagrange interpolant at random points
//    (sum_a b_a B_a(pc) == sum_i f_i w_i(pc): an independent evaluation of
//    the same polynomial through another basis);
//  - the Bernstein basis is a partition of unity and non-negative on the cell;
//  - dense samples of curved fields never leave the hull, and the hull is
//    tight for smooth fields sampled at the nodes (node noise, i.e. high
//    frequencies, makes the Bernstein net of high orders much looser: still
//    rigorous, not tested for tightness);
//  - a linear field's hull is its vertex range (to rounding);
//  - the special cells are refused.
#include "hovLagrangeHull.h"

#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"
#include "hovLagrangeTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace
{
using hovtest::AllLagrangeCases;
using hovtest::LagrangeCase;

double Field(const double* x)
{
  return std::sin(1.7 * x[0]) + x[1] * std::cos(2.1 * x[2]) + 0.3 * x[0] * x[2];
}

TEST(LagrangeHull, CoefficientsReproduceTheInterpolant)
{
  std::mt19937_64 rng(2020);
  hovtest::Worst worst, unity;
  for (const LagrangeCase& c : AllLagrangeCases(8))
  {
    hovtest::LagrangeTestCell cell;
    ASSERT_TRUE(hovtest::InitBasis(c, cell.Basis)) << c.Name();
    hov::LagrangeHull hull;
    if (c.NodeCount)
    {
      EXPECT_FALSE(hull.Initialize(cell.Basis)) << c.Name() << ": special cells are refused";
      continue;
    }
    ASSERT_TRUE(hull.Initialize(cell.Basis)) << c.Name();
    hovtest::PlaceNodes(cell, hovtest::RandomMap(rng, 0.1), 0.02, rng, Field);
    const int n = cell.Basis.GetNodeCount();
    std::vector<double> b(n);
    hull.Coefficients(cell.Scalars.data(), b.data());
    double scale = 0.0;
    for (double f : cell.Scalars)
    {
      scale = std::max(scale, std::abs(f));
    }
    for (int trial = 0; trial < 20; ++trial)
    {
      double pc[3];
      hovtest::RandomPC(cell.Basis, rng, 0.0, pc);
      double viaBernstein = 0.0, sum = 0.0;
      for (int a = 0; a < n; ++a)
      {
        const double B = hull.BasisFunction(a, pc);
        ASSERT_GE(B, 0.0) << c.Name() << " basis " << a;
        viaBernstein += b[a] * B;
        sum += B;
      }
      const double viaLagrange = hov::EvaluateLagrangeScalar(cell.View(), pc);
      const double err = std::abs(viaBernstein - viaLagrange) / scale;
      worst.Add(err, c.Name());
      unity.Add(std::abs(sum - 1.0), c.Name());
      EXPECT_LE(err, hovtest::Tolerances.HullReproductionRel)
        << c.Name() << " at " << pc[0] << " " << pc[1] << " " << pc[2];
      EXPECT_NEAR(sum, 1.0, hovtest::Tolerances.HullReproductionRel) << c.Name();
    }
  }
  hovtest::ReportMeasured("LagrangeHull.ReproductionRel", worst);
  hovtest::ReportMeasured("LagrangeHull.UnityError", unity);
}

TEST(LagrangeHull, ContainsDenseSamplesAndIsTight)
{
  std::mt19937_64 rng(7);
  hovtest::Worst overshoot;
  double worstLooseness = 0.0;
  for (const LagrangeCase& c : AllLagrangeCases(6))
  {
    if (c.NodeCount)
    {
      continue;
    }
    hovtest::LagrangeTestCell cell;
    ASSERT_TRUE(hovtest::InitBasis(c, cell.Basis)) << c.Name();
    hov::LagrangeHull hull;
    ASSERT_TRUE(hull.Initialize(cell.Basis));
    hovtest::PlaceNodes(cell, hovtest::RandomMap(rng, 0.12), 0.0, rng, Field);
    double lo, hi;
    hull.Hull(cell.Scalars.data(), lo, hi);
    double sLo = 1e300, sHi = -1e300;
    for (int trial = 0; trial < 4000; ++trial)
    {
      double pc[3];
      hovtest::RandomPC(cell.Basis, rng, 0.0, pc);
      const double f = hov::EvaluateLagrangeScalar(cell.View(), pc);
      sLo = std::min(sLo, f);
      sHi = std::max(sHi, f);
      ASSERT_GE(f, lo) << c.Name();
      ASSERT_LE(f, hi) << c.Name();
    }
    for (int i = 0; i < cell.Basis.GetNodeCount(); ++i)
    {
      ASSERT_GE(cell.Scalars[i], lo) << c.Name() << " node " << i;
      ASSERT_LE(cell.Scalars[i], hi) << c.Name() << " node " << i;
    }
    // Tight: the hull exceeds the sampled range by a small fraction (the
    // Bernstein net of a smooth, slowly varying field is close to it).
    const double looseness = ((hi - lo) - (sHi - sLo)) / (sHi - sLo);
    worstLooseness = std::max(worstLooseness, looseness);
    overshoot.Add(looseness, c.Name());
    EXPECT_LE(looseness, hovtest::Tolerances.HullLoosenessRel) << c.Name();
  }
  hovtest::ReportMeasured("LagrangeHull.Looseness", overshoot);
}

TEST(LagrangeHull, LinearFieldGivesTheVertexRange)
{
  std::mt19937_64 rng(11);
  hovtest::Worst widening;
  for (const LagrangeCase& c : AllLagrangeCases(5))
  {
    if (c.NodeCount)
    {
      continue;
    }
    hovtest::LagrangeTestCell cell;
    ASSERT_TRUE(hovtest::InitBasis(c, cell.Basis));
    hov::LagrangeHull hull;
    ASSERT_TRUE(hull.Initialize(cell.Basis));
    // f linear in pc on an affine cell: its extremes are vertex values.
    hovtest::PlaceNodes(cell, hovtest::RandomMap(rng, 0.0), 0.0, rng,
      [](const double* x) { return 0.5 + 2.0 * x[0] - 1.5 * x[1] + 0.7 * x[2]; });
    double lo, hi, vLo = 1e300, vHi = -1e300;
    hull.Hull(cell.Scalars.data(), lo, hi);
    const int corners = c.Shape == hov::LagrangeShape::Tetra ? 4
      : c.Shape == hov::LagrangeShape::Wedge                 ? 6
                                                             : 8;
    for (int i = 0; i < corners; ++i)
    {
      vLo = std::min(vLo, cell.Scalars[i]);
      vHi = std::max(vHi, cell.Scalars[i]);
    }
    EXPECT_LE(lo, vLo) << c.Name();
    EXPECT_GE(hi, vHi) << c.Name();
    EXPECT_NEAR(lo, vLo, hovtest::Tolerances.HullLinearAbs * (vHi - vLo)) << c.Name();
    EXPECT_NEAR(hi, vHi, hovtest::Tolerances.HullLinearAbs * (vHi - vLo)) << c.Name();
    widening.Add(std::max(vLo - lo, hi - vHi) / (vHi - vLo), c.Name());
  }
  hovtest::ReportMeasured("LagrangeHull.LinearWidening", widening);
}
}
