// Shape functions of hovCellShapes.h: partition of unity, node interpolation,
// derivatives against central differences, expansion along lines against
// pointwise evaluation, geometry inversion.
#include "hovCellShapes.h"

#include "hovCellTestSupport.h"
#include "hovKernelTestUtilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
using hov::CellShape;
using hovtest::AllCellShapes;
using hovtest::ShapeName;

TEST(CellShapes, PartitionOfUnityAndNodeInterpolation)
{
  std::mt19937_64 rng(11);
  hovtest::Worst unity, nodal;
  for (CellShape shape : AllCellShapes())
  {
    const int n = hov::CellNodeCount(shape);
    for (int trial = 0; trial < 200; ++trial)
    {
      double pc[3], w[hov::MaxCellNodes];
      hovtest::RandomInteriorPC(shape, rng, 0.0, pc);
      hov::CellShapeFunctions(shape, pc, w);
      double sum = 0.0;
      for (int i = 0; i < n; ++i)
      {
        sum += w[i];
      }
      unity.Add(std::fabs(sum - 1.0), ShapeName(shape));
      EXPECT_NEAR(sum, 1.0, 1e-14) << ShapeName(shape);
    }
    for (int j = 0; j < n; ++j)
    {
      double pc[3], w[hov::MaxCellNodes];
      hov::CellNodeParametricCoords(shape, j, pc);
      hov::CellShapeFunctions(shape, pc, w);
      for (int i = 0; i < n; ++i)
      {
        nodal.Add(std::fabs(w[i] - (i == j ? 1.0 : 0.0)), ShapeName(shape));
        EXPECT_NEAR(w[i], i == j ? 1.0 : 0.0, 1e-15) << ShapeName(shape) << " node " << j;
      }
    }
  }
  hovtest::ReportMeasured("CellShapes.UnityError", unity);
  hovtest::ReportMeasured("CellShapes.NodalError", nodal);
}

TEST(CellShapes, DerivativesMatchCentralDifferences)
{
  std::mt19937_64 rng(12);
  hovtest::Worst worst;
  for (CellShape shape : AllCellShapes())
  {
    const int n = hov::CellNodeCount(shape);
    for (int trial = 0; trial < 50; ++trial)
    {
      double pc[3], d[3 * hov::MaxCellNodes];
      hovtest::RandomInteriorPC(shape, rng, 0.01, pc);
      hov::CellShapeDerivatives(shape, pc, d);
      for (int k = 0; k < 3; ++k)
      {
        const double h = 1e-5;
        double p1[3] = { pc[0], pc[1], pc[2] }, p0[3] = { pc[0], pc[1], pc[2] };
        p1[k] += h;
        p0[k] -= h;
        double w1[hov::MaxCellNodes], w0[hov::MaxCellNodes];
        hov::CellShapeFunctions(shape, p1, w1);
        hov::CellShapeFunctions(shape, p0, w0);
        double sum = 0.0;
        for (int i = 0; i < n; ++i)
        {
          const double fd = (w1[i] - w0[i]) / (2 * h);
          worst.Add(std::fabs(fd - d[k * n + i]), ShapeName(shape));
          EXPECT_NEAR(d[k * n + i], fd, 1e-8) << ShapeName(shape) << " node " << i;
          sum += d[k * n + i];
        }
        EXPECT_NEAR(sum, 0.0, 1e-13) << ShapeName(shape); // derivative of the unity
      }
    }
  }
  hovtest::ReportMeasured("CellShapes.DerivativeVsCentralDifference", worst);
}

// The linear cells' closed-form derivatives (Newton's inner loop) are the
// dual numbers' values (== also equates the two zeros), inside the cell and
// outside it (Newton's iterates stray), for every shape; the quadratic cells
// take the dual path itself.
TEST(CellShapes, ClosedFormDerivativesAreTheDualNumbers)
{
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(-1.5, 2.5);
  int compared = 0;
  for (CellShape shape : AllCellShapes())
  {
    const int n = hov::CellNodeCount(shape);
    for (int trial = 0; trial < 2000; ++trial)
    {
      double pc[3] = { u(rng), u(rng), u(rng) };
      if (trial < 8)
      {
        pc[0] = trial & 1; // the corners: exact zeros in the factors
        pc[1] = (trial >> 1) & 1;
        pc[2] = (trial >> 2) & 1;
      }
      double d[3 * hov::MaxCellNodes], ref[3 * hov::MaxCellNodes];
      hov::CellShapeDerivatives(shape, pc, d);
      hov::detail::CellShapeDerivativesDual(shape, pc, ref);
      for (int k = 0; k < 3 * n; ++k)
      {
        ASSERT_EQ(d[k], ref[k]) << ShapeName(shape) << " entry " << k << " trial " << trial;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 100000);
}

TEST(CellShapes, ExpansionAlongLineMatchesPointwise)
{
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  hovtest::Worst worst;
  for (CellShape shape : AllCellShapes())
  {
    const int n = hov::CellNodeCount(shape);
    for (int trial = 0; trial < 50; ++trial)
    {
      double start[3], step[3];
      hovtest::RandomInteriorPC(shape, rng, 0.0, start);
      for (double& v : step)
      {
        v = u(rng);
      }
      hov::Polynomial w[hov::MaxCellNodes];
      hov::CellShapeFunctionsAlongLine(shape, start, step, w);
      for (int j = 0; j <= 10; ++j)
      {
        const double y = 0.1 * j;
        const double pc[3] = { start[0] + y * step[0], start[1] + y * step[1],
          start[2] + y * step[2] };
        double direct[hov::MaxCellNodes];
        hov::CellShapeFunctions(shape, pc, direct);
        for (int i = 0; i < n; ++i)
        {
          EXPECT_LE(w[i].Degree, 6) << ShapeName(shape);
          const double e = std::fabs(hov::Evaluate(w[i], y) - direct[i]);
          worst.Add(e, ShapeName(shape));
          EXPECT_LT(e, 1e-13) << ShapeName(shape) << " node " << i << " y " << y;
        }
      }
    }
  }
  hovtest::ReportMeasured("CellShapes.AlongLineVsPointwise", worst);
}

TEST(CellShapes, InvertGeometryRoundTrip)
{
  std::mt19937_64 rng(14);
  hovtest::Worst worst;
  for (CellShape shape : AllCellShapes())
  {
    for (int trial = 0; trial < 40; ++trial)
    {
      const hovtest::TestCell cell = hovtest::MakeRandomCell(shape, rng, 0.15);
      double pc[3], x[3], back[3];
      hovtest::RandomInteriorPC(shape, rng, 0.02, pc);
      hov::EvaluateGeometry(shape, cell.Points.data(), pc, x, nullptr);
      hov::CellParametricCenter(shape, back);
      ASSERT_TRUE(hov::InvertGeometry(shape, cell.Points.data(), x, back)) << ShapeName(shape);
      for (int k = 0; k < 3; ++k)
      {
        worst.Add(std::fabs(back[k] - pc[k]), ShapeName(shape));
        EXPECT_NEAR(back[k], pc[k], 1e-12) << ShapeName(shape);
      }
    }
  }
  hovtest::ReportMeasured("CellShapes.InverseRoundTrip", worst);
}

TEST(CellShapes, SupportedTypes)
{
  for (CellShape shape : AllCellShapes())
  {
    EXPECT_TRUE(hov::IsSupportedCellType(static_cast<int>(shape)));
  }
  for (int t : { 0, 1, 5, 9, 15, 23, 28, 30, 71, 74 })
  {
    EXPECT_FALSE(hov::IsSupportedCellType(t)) << t;
  }
}
}
