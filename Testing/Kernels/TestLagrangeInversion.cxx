// Geometry map of Lagrange cells and its Newton inversion (hovLagrangeCell.h):
// Jacobian against finite differences, round trips x(pc) -> pc on curved
// cells (bent maps plus perturbed edge/face/interior nodes) of every type and
// order, points outside, degenerate and non-finite input.
#include "hovLagrangeCell.h"

#include "hovKernelTestUtilities.h"
#include "hovLagrangeTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace
{
using hov::LagrangeShape;
using hovtest::LagrangeCase;

double Field(const double* x)
{
  return std::sin(x[0]) + x[1] * x[2];
}

/// A curved cell: bent map plus noise on the non-corner nodes (relative to size 1).
void MakeCurved(const LagrangeCase& c, hovtest::LagrangeTestCell& cell, std::mt19937_64& rng,
  double bend, double noise)
{
  ASSERT_TRUE(hovtest::InitBasis(c, cell.Basis));
  const hovtest::SmoothMap map = hovtest::RandomMap(rng, bend);
  // Noise scaled down with the order: equispaced interpolation amplifies node
  // noise (Lebesgue constant), and the map must stay injective.
  const int* o = cell.Basis.GetOrder();
  const int p = std::max(std::max(o[0], o[2]), 1);
  hovtest::PlaceNodes(cell, map, noise / (p * p * p), rng, Field);
  const double ratio = hovtest::MinJacobianRatio(cell.View(), rng);
  ASSERT_GT(ratio, 0.2) << c.Name() << " ratio " << ratio;
}

TEST(LagrangeInversion, JacobianMatchesCentralDifferences)
{
  std::mt19937_64 rng(71);
  hovtest::Worst worst;
  for (const LagrangeCase& c : hovtest::AllLagrangeCases(6))
  {
    hovtest::LagrangeTestCell cell;
    MakeCurved(c, cell, rng, 0.12, 0.05);
    const hov::LagrangeCellView view = cell.View();
    for (int trial = 0; trial < 5; ++trial)
    {
      double pc[3], x[3], J[9], g[3];
      hovtest::RandomPC(cell.Basis, rng, 0.01, pc);
      hov::EvaluateLagrangePosition(view, pc, x, J);
      hov::EvaluateLagrangeScalar(view, pc, g);
      for (int k = 0; k < 3; ++k)
      {
        const double h = 1e-6;
        double p1[3] = { pc[0], pc[1], pc[2] }, p0[3] = { pc[0], pc[1], pc[2] }, x1[3], x0[3];
        p1[k] += h;
        p0[k] -= h;
        hov::EvaluateLagrangePosition(view, p1, x1);
        hov::EvaluateLagrangePosition(view, p0, x0);
        for (int i = 0; i < 3; ++i)
        {
          const double err = std::abs((x1[i] - x0[i]) / (2 * h) - J[3 * i + k]);
          worst.Add(err, c.Name());
          EXPECT_LE(err, 1e-6) << c.Name();
        }
        const double fd = (hov::EvaluateLagrangeScalar(view, p1) -
                            hov::EvaluateLagrangeScalar(view, p0)) / (2 * h);
        EXPECT_NEAR(fd, g[k], 1e-6) << c.Name();
      }
    }
  }
  hovtest::ReportMeasured("LagrangeInversion.JacobianVsFD", worst);
}

TEST(LagrangeInversion, RoundTripOnCurvedCells)
{
  std::mt19937_64 rng(72);
  hovtest::Worst pcErr, iterations;
  int total = 0, fromCentre = 0;
  for (const LagrangeCase& c : hovtest::AllLagrangeCases(8))
  {
    hovtest::LagrangeTestCell cell;
    MakeCurved(c, cell, rng, 0.12, 0.08);
    const hov::LagrangeCellView view = cell.View();
    // Curved unless it is a linear tetrahedron (always affine).
    ASSERT_EQ(hov::IsLagrangeGeometryAffine(view),
      c.Shape == LagrangeShape::Tetra && c.Order[0] == 1 && !c.NodeCount)
      << c.Name();
    for (int trial = 0; trial < 30; ++trial)
    {
      double pc[3], x[3];
      hovtest::RandomPC(cell.Basis, rng, 0.0, pc);
      hov::EvaluateLagrangePosition(view, pc, x);
      double found[3] = { std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0 }; // no guess
      const hov::LagrangeInversionResult res = hov::InvertLagrangeGeometry(view, x, found);
      ASSERT_TRUE(res.Converged()) << c.Name() << " " << hov::InversionStatusName(res.Status)
                                   << " pc " << pc[0] << " " << pc[1] << " " << pc[2];
      const double err = std::max(std::max(std::abs(found[0] - pc[0]), std::abs(found[1] - pc[1])),
        std::abs(found[2] - pc[2]));
      pcErr.Add(err, c.Name());
      iterations.Add(res.Iterations, c.Name());
      EXPECT_LE(err, 1e-12) << c.Name();
      fromCentre += res.Starts == 1;
      ++total;
    }
  }
  hovtest::ReportMeasured("LagrangeInversion.RoundTripPC", pcErr);
  hovtest::ReportMeasured("LagrangeInversion.MaxIterations", iterations);
  std::cout << "[measured] LagrangeInversion: " << fromCentre << " of " << total
            << " converged from the first start" << std::endl;
}

TEST(LagrangeInversion, PointsOutsideAreReportedOutside)
{
  std::mt19937_64 rng(73);
  for (const LagrangeCase& c : hovtest::AllLagrangeCases(4))
  {
    hovtest::LagrangeTestCell cell;
    MakeCurved(c, cell, rng, 0.08, 0.03);
    const hov::LagrangeCellView view = cell.View();
    // A point beyond a face: pc pushed 0.05 outside, mapped by the (extended) polynomial map.
    double centre[3], pc[3], x[3];
    cell.Basis.ParametricCenter(centre);
    for (int k = 0; k < 3; ++k)
    {
      pc[k] = centre[k];
    }
    pc[2] = -0.05;
    hov::EvaluateLagrangePosition(view, pc, x);
    double found[3] = { centre[0], centre[1], centre[2] };
    const hov::LagrangeInversionResult res = hov::InvertLagrangeGeometry(view, x, found);
    ASSERT_TRUE(res.Converged()) << c.Name();
    EXPECT_NEAR(cell.Basis.DistanceOutside(found), 0.05, 1e-10) << c.Name();
  }
}

TEST(LagrangeInversion, BadInputIsReportedNotNaN)
{
  hovtest::LagrangeTestCell cell;
  ASSERT_TRUE(cell.Basis.Initialize(LagrangeShape::Hexahedron, 27));
  std::mt19937_64 rng(74);
  hovtest::PlaceNodes(cell, hovtest::SmoothMap(), 0.0, rng, Field);
  double pc[3] = { 0.5, 0.5, 0.5 };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double xBad[3] = { nan, 0.0, 0.0 };
  hov::LagrangeInversionResult res = hov::InvertLagrangeGeometry(cell.View(), xBad, pc);
  EXPECT_EQ(res.Status, hov::InversionStatus::InvalidInput);
  EXPECT_TRUE(std::isfinite(pc[0]));
  // A flat cell (every node in the plane z = 0): singular Jacobian everywhere.
  for (size_t i = 2; i < cell.Points.size(); i += 3)
  {
    cell.Points[i] = 0.0;
  }
  const double x[3] = { 0.3, 0.3, 0.0 };
  res = hov::InvertLagrangeGeometry(cell.View(), x, pc);
  EXPECT_EQ(res.Status, hov::InversionStatus::SingularJacobian);
  EXPECT_TRUE(std::isfinite(pc[0]) && std::isfinite(pc[1]) && std::isfinite(pc[2]));
  EXPECT_NE(std::string(hov::InversionStatusName(res.Status)).find("singular"), std::string::npos);
}
/// A pyramid as an order-1 hexahedron whose top face is collapsed to the apex
/// (how the ray caster takes VTK pyramids): the Jacobian is singular at the
/// apex, yet points at and near it invert (to a point mapping to them to
/// rounding) instead of failing with "singular Jacobian".
TEST(LagrangeInversion, CollapsedTopFaceInvertsAtTheApex)
{
  hovtest::LagrangeTestCell cell;
  ASSERT_TRUE(cell.Basis.Initialize(LagrangeShape::Hexahedron, 8));
  cell.Points.resize(24);
  cell.Scalars.assign(8, 1.0);
  for (int k = 0; k < 8; ++k)
  {
    double pc[3];
    cell.Basis.NodeParametricCoords(k, pc);
    const bool top = pc[2] == 1.0;
    cell.Points[3 * k] = top ? 0.5 : pc[0];
    cell.Points[3 * k + 1] = top ? 0.5 : pc[1];
    cell.Points[3 * k + 2] = top ? 1.0 : 0.0;
  }
  for (double below : { 0.0, 1e-14, 1e-10, 1e-6 })
  {
    const double x[3] = { 0.5, 0.5, 1.0 - below };
    double pc[3] = { 0.5, 0.5, 0.5 };
    const hov::LagrangeInversionResult res = hov::InvertLagrangeGeometry(cell.View(), x, pc);
    EXPECT_EQ(res.Status, hov::InversionStatus::Converged) << "below apex " << below;
    double y[3];
    hov::EvaluateLagrangePosition(cell.View(), pc, y, nullptr);
    EXPECT_NEAR(y[2], x[2], 1e-12) << "below apex " << below;
    EXPECT_NEAR(pc[2], 1.0 - below, 1e-8) << "below apex " << below;
  }
}
}

namespace
{
/// The trilinear map of eight corners (VTK order) at @p pc: an independent evaluation.
void Trilinear(const double corners[8][3], const double pc[3], double x[3])
{
  const double r = pc[0], s = pc[1], t = pc[2];
  const double w[8] = { (1 - r) * (1 - s) * (1 - t), r * (1 - s) * (1 - t), r * s * (1 - t),
    (1 - r) * s * (1 - t), (1 - r) * (1 - s) * t, r * (1 - s) * t, r * s * t, (1 - r) * s * t };
  for (int i = 0; i < 3; ++i)
  {
    x[i] = 0.0;
    for (int k = 0; k < 8; ++k)
    {
      x[i] += w[k] * corners[k][i];
    }
  }
}
}

// Hexahedra of every order whose nodes lie on the trilinear map of random
// (non-parallelepiped) corners: detected, evaluated from the corners as the
// full interpolant evaluates them (position and Jacobian), inverted as
// precisely; one node moved by 1e-9 of the size, or another shape: not detected.
TEST(LagrangeInversion, TrilinearHexahedraAreDetectedAndEvaluatedFromTheirCorners)
{
  std::mt19937_64 rng(75);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  hovtest::Worst posErr, pcErr;
  for (const LagrangeCase& c : hovtest::AllLagrangeCases(6))
  {
    hovtest::LagrangeTestCell cell;
    ASSERT_TRUE(hovtest::InitBasis(c, cell.Basis));
    if (c.Shape != LagrangeShape::Hexahedron)
    {
      MakeCurved(c, cell, rng, 0.0, 0.0); // affine: not a hexahedron, never trilinear
      EXPECT_FALSE(hov::IsLagrangeGeometryTrilinear(cell.View())) << c.Name();
      continue;
    }
    double corners[8][3];
    for (int k = 0; k < 8; ++k)
    {
      double pc[3];
      cell.Basis.NodeParametricCoords(k, pc);
      for (int i = 0; i < 3; ++i)
      {
        corners[k][i] = pc[i] + u(rng);
      }
    }
    const int n = cell.Basis.GetNodeCount();
    hovtest::PlaceNodes(
      cell, [&corners](const double* pc, double* x) { Trilinear(corners, pc, x); }, 0.0, rng,
      Field);
    hov::LagrangeCellView full = cell.View();
    ASSERT_TRUE(hov::IsLagrangeGeometryTrilinear(full)) << c.Name();
    EXPECT_FALSE(hov::IsLagrangeGeometryAffine(full)) << c.Name();
    hov::LagrangeCellView fast = full;
    fast.Trilinear = true;
    for (int trial = 0; trial < 20; ++trial)
    {
      double pc[3], xa[3], xb[3], ja[9], jb[9];
      hovtest::RandomPC(cell.Basis, rng, 0.0, pc);
      hov::EvaluateLagrangePosition(full, pc, xa, ja);
      hov::EvaluateLagrangePosition(fast, pc, xb, jb);
      double e = 0.0;
      for (int i = 0; i < 3; ++i)
      {
        e = std::max(e, std::abs(xa[i] - xb[i]));
      }
      for (int i = 0; i < 9; ++i)
      {
        e = std::max(e, std::abs(ja[i] - jb[i]));
      }
      posErr.Add(e, c.Name());
      EXPECT_LE(e, 1e-12) << c.Name();
      double found[3] = { 0.5, 0.5, 0.5 };
      ASSERT_TRUE(hov::InvertLagrangeGeometry(fast, xa, found).Converged()) << c.Name();
      const double err = std::max(std::max(std::abs(found[0] - pc[0]), std::abs(found[1] - pc[1])),
        std::abs(found[2] - pc[2]));
      pcErr.Add(err, c.Name());
      EXPECT_LE(err, 1e-12) << c.Name();
    }
    if (n > 8)
    {
      cell.Points[3 * (n - 1)] += 1e-9; // the last node (interior or on a face) off the map
      EXPECT_FALSE(hov::IsLagrangeGeometryTrilinear(cell.View())) << c.Name();
    }
  }
  hovtest::ReportMeasured("LagrangeInversion.TrilinearVsFullMap", posErr);
  hovtest::ReportMeasured("LagrangeInversion.TrilinearRoundTripPC", pcErr);
}
