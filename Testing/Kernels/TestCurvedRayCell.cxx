// Ray vs curved Lagrange cell (hovCurvedFaces.h, hovCurvedRayCell.h):
//  - affine / trilinear geometry: the intervals equal hovRayCell's
//    RayCellIntervals (straight-sided cells) to ~1e-12;
//  - curved cells: the intervals agree with a brute-force inside test
//    (Newton inversion at dense points along the ray);
//  - a bent (arch-shaped) hexahedron: a ray that leaves and re-enters it
//    (2 intervals), rays grazing its inner face from inside (1 interval),
//    just below (2 intervals, tiny gap), and grazing its outer face (none).
#include "hovCurvedRayCell.h"
#include "hovRayCell.h"

#include "hovKernelTestUtilities.h"
#include "hovLagrangeTestSupport.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <random>

namespace
{
using hov::LagrangeShape;

double Zero(const double*)
{
  return 0.0;
}

/// Nodes of a Lagrange cell placed by an arbitrary map of the parametric coordinates.
void PlaceByMap(hovtest::LagrangeTestCell& cell, const std::function<void(const double*, double*)>& map)
{
  const int n = cell.Basis.GetNodeCount();
  cell.Points.resize(3 * n);
  cell.Scalars.assign(n, 0.0);
  for (int i = 0; i < n; ++i)
  {
    double pc[3];
    cell.Basis.NodeParametricCoords(i, pc);
    map(pc, &cell.Points[3 * i]);
  }
}

/// A random ray through the box [-0.5, 1.5]^3 region around the unit cell.
void RandomRay(std::mt19937_64& rng, double o[3], double d[3])
{
  std::uniform_real_distribution<double> u(-1.0, 1.0), p(0.1, 0.9);
  double target[3] = { p(rng), p(rng), p(rng) };
  double len = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    d[k] = u(rng);
    len += d[k] * d[k];
  }
  len = std::sqrt(len);
  for (int k = 0; k < 3; ++k)
  {
    d[k] /= len;
    o[k] = target[k] - 3.0 * d[k];
  }
}

/// Brute force: fraction of the dense samples whose inside status disagrees with the intervals
/// (samples within 1e-6 of an interval end are skipped).
int BruteForceDisagreements(const hov::LagrangeCellView& view, const double o[3], const double d[3],
  double tMin, double tMax, const hov::CurvedRayInterval* iv, int n)
{
  // Outside the nodes' box widened by half the extent, the point is outside
  // (the test cells bulge far less); saves hopeless inversions.
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (int i = 0; i < view.Basis->GetNodeCount(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], view.Points[3 * i + k]);
      hi[k] = std::max(hi[k], view.Points[3 * i + k]);
    }
  }
  const double pad = 0.5 * hov::LagrangeCellExtent(view);
  int bad = 0;
  double pc[3];
  view.Basis->ParametricCenter(pc);
  for (int i = 0; i <= 300; ++i)
  {
    const double t = tMin + (tMax - tMin) * (i + 0.5) / 301.0;
    bool inIntervals = false, nearEnd = false;
    for (int k = 0; k < n; ++k)
    {
      inIntervals = inIntervals || (t > iv[k].T0 && t < iv[k].T1);
      nearEnd = nearEnd || std::abs(t - iv[k].T0) < 1e-6 || std::abs(t - iv[k].T1) < 1e-6;
    }
    const double x[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
    bool far = false;
    for (int k = 0; k < 3; ++k)
    {
      far = far || x[k] < lo[k] - pad || x[k] > hi[k] + pad;
    }
    if (far)
    {
      bad += inIntervals ? 1 : 0;
      continue;
    }
    // Warm start from the previous sample; the full start set if that fails.
    hov::LagrangeInversionSettings quick;
    quick.UseStartGrid = false;
    hov::LagrangeInversionResult r = hov::InvertLagrangeGeometry(view, x, pc, quick);
    if (!r.Converged())
    {
      view.Basis->ParametricCenter(pc);
      r = hov::InvertLagrangeGeometry(view, x, pc);
    }
    const double dist = view.Basis->DistanceOutside(pc);
    if (!r.Converged())
    {
      view.Basis->ParametricCenter(pc);
    }
    if (!r.Converged() || std::abs(dist) < 1e-7 || nearEnd)
    {
      continue; // undecidable by sampling (a point far outside may not converge)
    }
    bad += ((dist < 0.0) != inIntervals) ? 1 : 0;
  }
  return bad;
}

TEST(CurvedRayCell, AgreesWithStraightSidedCells)
{
  std::mt19937_64 rng(101);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  hovtest::Worst worst;
  struct Kind
  {
    LagrangeShape Lagrange;
    hov::CellShape Linear;
    int Corners;
  };
  const Kind kinds[3] = { { LagrangeShape::Tetra, hov::CellShape::Tetra, 4 },
    { LagrangeShape::Hexahedron, hov::CellShape::Hexahedron, 8 },
    { LagrangeShape::Wedge, hov::CellShape::Wedge, 6 } };
  int rays = 0, hits = 0;
  for (const Kind& kind : kinds)
  {
    for (int order = 1; order <= 4; ++order)
    {
      // Corners: reference corners moved by up to 0.15 (non-planar quads), nodes on
      // the linear cell's map (trilinear hexahedron, linear wedge, affine tetrahedron).
      std::vector<double> corners(3 * kind.Corners);
      std::int64_t ids[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
      for (int c = 0; c < kind.Corners; ++c)
      {
        hov::CellNodeParametricCoords(kind.Linear, c, &corners[3 * c]);
        for (int k = 0; k < 3; ++k)
        {
          corners[3 * c + k] += 0.15 * u(rng);
        }
      }
      hovtest::LagrangeTestCell cell;
      const int degrees[3] = { order, order, order };
      ASSERT_TRUE(cell.Basis.Initialize(kind.Lagrange,
        hov::LagrangeNodeCount(kind.Lagrange, degrees), degrees));
      PlaceByMap(cell, [&](const double* pc, double* x) {
        hov::EvaluateGeometry(kind.Linear, corners.data(), pc, x, nullptr);
      });
      const hov::LagrangeCellView view = cell.View();
      hov::CurvedCellFaces faces;
      ASSERT_TRUE(hov::BuildCurvedFaces(view, faces));
      for (int trial = 0; trial < 60; ++trial)
      {
        double o[3], d[3];
        RandomRay(rng, o, d);
        hov::RayCellInterval ref[hov::MaxRayCellIntervals];
        const int nRef = hov::RayCellIntervals(kind.Linear, corners.data(), ids, o, d, 0.0, 10.0, ref);
        hov::CurvedRayInterval got[8];
        hov::CurvedRayStatus status;
        const int n = hov::RayCurvedCellIntervals(view, faces, o, d, 0.0, 10.0, got, 8, {}, &status);
        ++rays;
        hits += nRef > 0;
        EXPECT_TRUE(status.Complete);
        ASSERT_EQ(n, nRef) << "shape " << static_cast<int>(kind.Lagrange) << " order " << order
                           << " trial " << trial;
        for (int k = 0; k < n; ++k)
        {
          const double e = std::max(std::abs(got[k].T0 - ref[k].T0), std::abs(got[k].T1 - ref[k].T1));
          worst.Add(e, "shape " + std::to_string(static_cast<int>(kind.Lagrange)) + " order " +
              std::to_string(order));
          EXPECT_LE(e, 1e-12) << "trial " << trial;
        }
      }
    }
  }
  hovtest::ReportMeasured("CurvedRayCell.VsStraightSided", worst);
  std::cout << "[measured] CurvedRayCell: " << hits << " of " << rays << " rays hit" << std::endl;
}

TEST(CurvedRayCell, AgreesWithBruteForceOnCurvedCells)
{
  std::mt19937_64 rng(102);
  int disagreements = 0, rays = 0, multi = 0;
  double seconds = 0.0;
  for (const hovtest::LagrangeCase& c : hovtest::AllLagrangeCases(5))
  {
    hovtest::LagrangeTestCell cell;
    ASSERT_TRUE(hovtest::InitBasis(c, cell.Basis));
    const hovtest::SmoothMap map = hovtest::RandomMap(rng, 0.15);
    hovtest::PlaceNodes(cell, map, 0.0, rng, Zero);
    const hov::LagrangeCellView view = cell.View();
    hov::CurvedCellFaces faces;
    ASSERT_TRUE(hov::BuildCurvedFaces(view, faces));
    for (int trial = 0; trial < 6; ++trial)
    {
      double o[3], d[3], centre[3], x[3];
      // Rays aimed at a random point of the cell.
      hovtest::RandomPC(cell.Basis, rng, 0.05, centre);
      hov::EvaluateLagrangePosition(view, centre, x);
      RandomRay(rng, o, d);
      for (int k = 0; k < 3; ++k)
      {
        o[k] = x[k] - 3.0 * d[k];
      }
      hov::CurvedRayInterval got[8];
      hov::CurvedRayStatus status;
      const auto start = std::chrono::steady_clock::now();
      const int n = hov::RayCurvedCellIntervals(view, faces, o, d, 0.0, 6.0, got, 8, {}, &status);
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      ++rays;
      multi += n > 1;
      EXPECT_GE(n, 1) << c.Name() << " trial " << trial;
      EXPECT_TRUE(status.Complete);
      EXPECT_EQ(status.InversionFailures, 0) << c.Name();
      const int bad = BruteForceDisagreements(view, o, d, 0.0, 6.0, got, n);
      disagreements += bad;
      EXPECT_EQ(bad, 0) << c.Name() << " trial " << trial;
    }
  }
  std::cout << "[measured] CurvedRayCell brute force: " << disagreements << " disagreements on "
            << rays << " rays (" << multi << " with several intervals); "
            << 1e6 * seconds / rays << " us per ray-cell (unoptimised, shared machine)"
            << std::endl;
}

/// An arch: hexahedron of order 4, x = 2r - 1, y = s * 0.3 + A (1 - (2r-1)^2), z = t.
void MakeArch(hovtest::LagrangeTestCell& cell, double A)
{
  ASSERT_TRUE(cell.Basis.Initialize(LagrangeShape::Hexahedron, 125));
  PlaceByMap(cell, [A](const double* pc, double* x) {
    const double a = 2 * pc[0] - 1;
    x[0] = a;
    x[1] = 0.3 * pc[1] + A * (1 - a * a);
    x[2] = pc[2];
  });
}

TEST(CurvedRayCell, ReentryAndGrazingOnAnArch)
{
  hovtest::LagrangeTestCell cell;
  MakeArch(cell, 0.6); // lower face y = 0.6 (1 - a^2), apex 0.6 at a = 0
  const hov::LagrangeCellView view = cell.View();
  hov::CurvedCellFaces faces;
  ASSERT_TRUE(hov::BuildCurvedFaces(view, faces));
  const double d[3] = { 1.0, 0.0, 0.0 };
  hov::CurvedRayInterval got[8];
  hov::CurvedRayStatus status;
  // y = 0.5: inside where 0.6(1-a^2) <= 0.5 <= 0.6(1-a^2) + 0.3: |a| in [sqrt(1/3), sqrt(1/6)]...
  // i.e. sqrt(1/6) <= |a| <= sqrt(2/3): two intervals (leaves and re-enters).
  const double o1[3] = { -2.0, 0.5, 0.5 };
  int n = hov::RayCurvedCellIntervals(view, faces, o1, d, 0.0, 4.0, got, 8, {}, &status);
  ASSERT_EQ(n, 2);
  const double a1 = std::sqrt(2.0 / 3.0), a2 = std::sqrt(1.0 / 6.0);
  EXPECT_NEAR(got[0].T0, 2.0 - a1, 1e-12);
  EXPECT_NEAR(got[0].T1, 2.0 - a2, 1e-12);
  EXPECT_NEAR(got[1].T0, 2.0 + a2, 1e-12);
  EXPECT_NEAR(got[1].T1, 2.0 + a1, 1e-12);
  EXPECT_EQ(BruteForceDisagreements(view, o1, d, 0.0, 4.0, got, n), 0);
  // y = 0.6: touches the lower face at the apex from inside: one interval |a| <= sqrt(0.5).
  const double o2[3] = { -2.0, 0.6, 0.5 };
  n = hov::RayCurvedCellIntervals(view, faces, o2, d, 0.0, 4.0, got, 8, {}, &status);
  ASSERT_EQ(n, 1) << "grazing from inside";
  EXPECT_NEAR(got[0].T0, 2.0 - std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(got[0].T1, 2.0 + std::sqrt(0.5), 1e-12);
  std::cout << "[measured] grazing ray: " << status.Crossings << " crossings, " << status.Grazing
            << " at the resolution limit, " << status.Patches << " sub-patches" << std::endl;
  // y = 0.6 - 1e-8: crosses the lower face twice near the apex (gap 2 sqrt(1e-8/0.6)).
  const double o3[3] = { -2.0, 0.6 - 1e-8, 0.5 };
  n = hov::RayCurvedCellIntervals(view, faces, o3, d, 0.0, 4.0, got, 8, {}, &status);
  ASSERT_EQ(n, 2) << "just below the apex";
  const double gap = 2.0 * std::sqrt(1e-8 / 0.6);
  EXPECT_NEAR(got[1].T0 - got[0].T1, gap, 1e-9);
  // y = 0.9: touches the upper face at its apex from outside: nothing of positive length.
  const double o4[3] = { -2.0, 0.9, 0.5 };
  n = hov::RayCurvedCellIntervals(view, faces, o4, d, 0.0, 4.0, got, 8, {}, &status);
  for (int k = 0; k < n; ++k)
  {
    EXPECT_LE(got[k].T1 - got[k].T0, 1e-6) << "grazing from outside";
  }
}
}

namespace
{
// A quadratic tetrahedron x = (r, s, t + a r s): its bottom face t = 0 is the
// saddle z = a x y (one triangular patch of total degree 2), its slanted face
// z = 1 - x - y + a x y; the other two are planes x = 0, y = 0.
TEST(CurvedRayCell, TriangularFacesCrossAndGrazeAsTheQuadraticSays)
{
  const double a = 0.8;
  hovtest::LagrangeTestCell cell;
  ASSERT_TRUE(cell.Basis.Initialize(LagrangeShape::Tetra, 10));
  PlaceByMap(cell, [a](const double* pc, double* x) {
    x[0] = pc[0];
    x[1] = pc[1];
    x[2] = pc[2] + a * pc[0] * pc[1];
  });
  const hov::LagrangeCellView view = cell.View();
  hov::CurvedCellFaces faces;
  ASSERT_TRUE(hov::BuildCurvedFaces(view, faces));
  EXPECT_EQ(faces.Faces.size(), 4u) << "one triangular patch per face";
  hov::CurvedRayInterval got[8];
  hov::CurvedRayStatus status;
  // Oblique rays from below: o = (x0, y0, -1), d = (dx, dy, 1). Entry where
  // -1 + t = a (x0 + t dx)(y0 + t dy), exit where -1 + t = 1 - x - y + a x y.
  std::mt19937_64 rng(305);
  std::uniform_real_distribution<double> p(0.15, 0.35), q(-0.05, 0.05);
  double worst = 0.0;
  for (int trial = 0; trial < 20; ++trial)
  {
    const double o[3] = { p(rng), p(rng), -1.0 }, d[3] = { q(rng), q(rng), 1.0 };
    // The root in [0.5, 3] of A t^2 + B t + C = 0 (A is small: the stable pair
    // q / A, C / q with q = -(B + sign(B) sqrt(B^2 - 4 A C)) / 2).
    auto root = [](double A, double B, double C) {
      const double q = -0.5 * (B + std::copysign(std::sqrt(B * B - 4 * A * C), B));
      const double r1 = C / q, r2 = A != 0.0 ? q / A : 1e300;
      return (r1 >= 0.5 && r1 <= 3.0) ? r1 : r2;
    };
    const double A = a * d[0] * d[1], B = a * (o[0] * d[1] + o[1] * d[0]), C = a * o[0] * o[1];
    const double tIn = root(A, B - 1.0, C + 1.0);
    const double tOut = root(A, B - 1.0 - d[0] - d[1], C + 2.0 - o[0] - o[1]);
    const int n = hov::RayCurvedCellIntervals(view, faces, o, d, 0.0, 4.0, got, 8, {}, &status);
    ASSERT_EQ(n, 1) << "trial " << trial;
    EXPECT_TRUE(status.Complete);
    const double e = std::max(std::abs(got[0].T0 - tIn), std::abs(got[0].T1 - tOut));
    EXPECT_LE(e, 1e-12) << "trial " << trial;
    worst = std::max(worst, e);
  }
  hovtest::ReportMeasured("CurvedRayCell.TriangularFaceAnalytic", worst);
  // Along x + y = k at height z0 = a k^2 / 4 the ray touches the saddle's
  // ridge at x = k / 2 from inside: one interval x in [0, k].
  const double k = 0.5, z0 = a * k * k / 4, d[3] = { 1.0, -1.0, 0.0 };
  const double o1[3] = { -1.0, k + 1.0, z0 };
  int n = hov::RayCurvedCellIntervals(view, faces, o1, d, 0.0, 4.0, got, 8, {}, &status);
  ASSERT_EQ(n, 1) << "grazing from inside";
  EXPECT_NEAR(got[0].T0, 1.0, 1e-12);
  EXPECT_NEAR(got[0].T1, 1.0 + k, 1e-12);
  // 1e-8 lower: it crosses the saddle twice, at x = k / 2 -+ sqrt(1e-8 / a).
  const double o2[3] = { -1.0, k + 1.0, z0 - 1e-8 };
  n = hov::RayCurvedCellIntervals(view, faces, o2, d, 0.0, 4.0, got, 8, {}, &status);
  ASSERT_EQ(n, 2) << "just below the ridge";
  EXPECT_NEAR(got[0].T1, 1.0 + k / 2 - std::sqrt(1e-8 / a), 1e-9);
  EXPECT_NEAR(got[1].T0, 1.0 + k / 2 + std::sqrt(1e-8 / a), 1e-9);
  EXPECT_EQ(BruteForceDisagreements(view, o2, d, 0.0, 4.0, got, n), 0);
}
}
