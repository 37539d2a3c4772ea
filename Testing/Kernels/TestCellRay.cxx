// Ray entry/exit (hovRayCell.h): intervals against a brute-force inside test
// (Newton inversion at many points along the ray), canonical face crossings
// (bit-identical whatever the corner order), two hexahedra sharing a
// non-planar face (exit of one == entry of the other, exactly), degenerate
// rays.
#include "hovRayCell.h"

#include "hovCellRestriction.h"
#include "hovCellTestSupport.h"
#include "hovKernelTestUtilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
using hov::CellShape;
using hovtest::ShapeName;

bool BruteInside(const hovtest::TestCell& cell, const double x[3])
{
  double pc[3];
  hov::CellParametricCenter(cell.Shape, pc);
  return hov::InvertGeometry(cell.Shape, cell.Points.data(), x, pc) &&
    hov::ParametricDistanceOutside(cell.Shape, pc) <= 0.0;
}

/// Random rays near the cell; every sample farther than the margin from an
/// interval end must agree with the brute-force test. Returns disagreements.
int CompareWithBruteForce(const hovtest::TestCell& cell, std::mt19937_64& rng, int rays,
  int& intervalsSeen, int& multiSeen)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int bad = 0;
  for (int r = 0; r < rays; ++r)
  {
    double pc[3], x[3], d[3], o[3];
    hovtest::RandomInteriorPC(cell.Shape, rng, -0.1, pc); // near, maybe outside
    hov::EvaluateGeometry(cell.Shape, cell.Points.data(), pc, x, nullptr);
    for (int k = 0; k < 3; ++k)
    {
      d[k] = u(rng);
      o[k] = x[k] - 2.0 * d[k];
    }
    hov::RayCellInterval iv[hov::MaxRayCellIntervals];
    const int n =
      hov::RayCellIntervals(cell.Shape, cell.Points.data(), cell.Ids.data(), o, d, 0.0, 4.0, iv);
    intervalsSeen += n;
    multiSeen += n > 1;
    for (int i = 0; i < n; ++i)
    {
      EXPECT_LT(iv[i].T0, iv[i].T1);
      EXPECT_TRUE(i == 0 || iv[i - 1].T1 < iv[i].T0);
    }
    for (int j = 0; j <= 400; ++j)
    {
      const double t = 4.0 * j / 400.0;
      bool inInterval = false, nearEnd = false;
      for (int i = 0; i < n; ++i)
      {
        inInterval = inInterval || (t >= iv[i].T0 && t <= iv[i].T1);
        nearEnd = nearEnd || std::fabs(t - iv[i].T0) < 1e-7 || std::fabs(t - iv[i].T1) < 1e-7;
      }
      const double xt[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
      if (!nearEnd && inInterval != BruteInside(cell, xt))
      {
        ++bad;
        ADD_FAILURE() << ShapeName(cell.Shape) << " ray " << r << " t " << t << " intervals "
                      << n;
      }
    }
  }
  return bad;
}

TEST(CellRay, PlanarCellsMatchBruteForce)
{
  std::mt19937_64 rng(31);
  for (CellShape shape : { CellShape::Tetra, CellShape::Voxel, CellShape::Hexahedron,
         CellShape::Wedge, CellShape::Pyramid, CellShape::QuadraticTetra })
  {
    int seen = 0, multi = 0;
    for (int c = 0; c < 10; ++c)
    {
      const hovtest::TestCell cell = hovtest::MakeRandomCell(shape, rng, 0.0);
      EXPECT_EQ(CompareWithBruteForce(cell, rng, 20, seen, multi), 0);
    }
    EXPECT_GT(seen, 50) << ShapeName(shape); // most rays hit
    EXPECT_EQ(multi, 0);                     // convex: one interval at most
  }
}

TEST(CellRay, NonPlanarCellsMatchBruteForce)
{
  std::mt19937_64 rng(32);
  for (CellShape shape : { CellShape::Hexahedron, CellShape::Wedge, CellShape::Pyramid,
         CellShape::TriQuadraticHexahedron })
  {
    int seen = 0, multi = 0;
    for (int c = 0; c < 10; ++c)
    {
      const hovtest::TestCell cell = hovtest::MakeRandomCell(shape, rng, 0.25);
      EXPECT_EQ(CompareWithBruteForce(cell, rng, 20, seen, multi), 0);
    }
    EXPECT_GT(seen, 50) << ShapeName(shape);
    std::cout << "[measured] " << ShapeName(shape) << " rays with 2+ intervals: " << multi
              << std::endl;
  }
}

TEST(CellRay, FaceCrossingsAreOrderIndependent)
{
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int twice = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    double p[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
    for (auto& q : p)
    {
      for (double& v : q)
      {
        v += 0.3 * u(rng);
      }
    }
    const std::int64_t ids[4] = { 7, 3, 12, 5 };
    double o[3] = { 0.5 + 0.5 * u(rng), 0.5 + 0.5 * u(rng), -2.0 }, d[3] = { 0.4 * u(rng),
      0.4 * u(rng), 1.0 };
    if (trial % 4 == 0)
    {
      d[2] = 0.05 * u(rng); // grazing: two crossings are possible
    }
    double ref[2];
    const double* c0[4] = { p[0], p[1], p[2], p[3] };
    const int n0 = hov::FaceRayCrossings(4, c0, ids, o, d, ref);
    twice += n0 == 2;
    for (int rot = 0; rot < 4; ++rot)
    {
      for (int dir : { 1, 3 })
      {
        const double* c[4];
        std::int64_t id[4];
        for (int i = 0; i < 4; ++i)
        {
          c[i] = p[(rot + dir * i) % 4];
          id[i] = ids[(rot + dir * i) % 4];
        }
        double t[2];
        ASSERT_EQ(hov::FaceRayCrossings(4, c, id, o, d, t), n0);
        for (int i = 0; i < n0; ++i)
        {
          EXPECT_EQ(t[i], ref[i]) << "trial " << trial; // bit-identical
        }
      }
    }
  }
  std::cout << "[measured] quads crossed twice: " << twice << " of 2000" << std::endl;
}

TEST(CellRay, SaddlePatchIsCrossedTwice)
{
  // Hyperbolic paraboloid z = u + v - 2uv over the unit square; on the line
  // x + y = 1 it is z = 1 - 2u(1 - u), which z = 0.7 meets at
  // u = 1/2 +- sqrt(0.1).
  const double p[4][3] = { { 0, 0, 0 }, { 1, 0, 1 }, { 1, 1, 0 }, { 0, 1, 1 } };
  const double* c[4] = { p[0], p[1], p[2], p[3] };
  const std::int64_t ids[4] = { 4, 1, 9, 2 };
  const double o[3] = { -1.0, 2.0, 0.7 }, d[3] = { 1.0, -1.0, 0.0 };
  double t[2];
  ASSERT_EQ(hov::FaceRayCrossings(4, c, ids, o, d, t), 2);
  const double r = std::sqrt(0.1);
  EXPECT_NEAR(t[0], 1.5 - r, 1e-14);
  EXPECT_NEAR(t[1], 1.5 + r, 1e-14);
  // A cube whose top face is that saddle lifted by 1 (z = 1 + u + v - 2uv):
  // the ray z = 1.7 along x + y = 1 is inside, leaves, and re-enters.
  hovtest::TestCell cube;
  cube.Shape = CellShape::Hexahedron;
  const double corners[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 2 }, { 1, 1, 1 }, { 0, 1, 2 } };
  for (int i = 0; i < 8; ++i)
  {
    cube.Points.insert(cube.Points.end(), corners[i], corners[i] + 3);
    cube.Ids.push_back(i);
  }
  const double o2[3] = { 0.0, 1.0, 1.7 };
  hov::RayCellInterval iv[hov::MaxRayCellIntervals];
  ASSERT_EQ(hov::RayCellIntervals(
              CellShape::Hexahedron, cube.Points.data(), cube.Ids.data(), o2, d, -1.0, 2.0, iv),
    2);
  EXPECT_EQ(iv[0].T0, 0.0); // enters through the face x = 0 at t = 0
  EXPECT_NEAR(iv[0].T1, 0.5 - r, 1e-14);
  EXPECT_NEAR(iv[1].T0, 0.5 + r, 1e-14);
  EXPECT_NEAR(iv[1].T1, 1.0, 1e-14);
}

/// Two hexahedra of a 3x2x2 perturbed grid sharing the non-planar face x ~ 1.
struct TwoHexes
{
  double Grid[12][3];
  hovtest::TestCell A, B;
};

int GridIndex(int i, int j, int k)
{
  return i + 3 * (j + 2 * k);
}

TwoHexes MakeTwoHexes(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  TwoHexes h;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
      {
        double* x = h.Grid[GridIndex(i, j, k)];
        x[0] = i + 0.2 * u(rng), x[1] = j + 0.2 * u(rng), x[2] = k + 0.2 * u(rng);
      }
  // A in the standard node order; B with its axes permuted cyclically
  // (r, s, t) -> grid (t, r, s) directions: another valid VTK ordering.
  for (int cellIndex = 0; cellIndex < 2; ++cellIndex)
  {
    hovtest::TestCell& cell = cellIndex == 0 ? h.A : h.B;
    cell.Shape = CellShape::Hexahedron;
    for (int n = 0; n < 8; ++n)
    {
      double pc[3];
      hov::CellNodeParametricCoords(CellShape::Hexahedron, n, pc);
      int g[3] = { int(pc[0]), int(pc[1]), int(pc[2]) };
      if (cellIndex == 1)
      {
        g[0] = 1 + int(pc[2]), g[1] = int(pc[0]), g[2] = int(pc[1]);
      }
      const int id = GridIndex(g[0], g[1], g[2]);
      cell.Points.insert(cell.Points.end(), h.Grid[id], h.Grid[id] + 3);
      cell.Ids.push_back(id);
      cell.Scalars.push_back(0.0);
    }
  }
  return h;
}

TEST(CellRay, SharedNonPlanarFaceIsExact)
{
  std::mt19937_64 rng(34);
  int checked = 0, rays = 0;
  for (int mesh = 0; mesh < 20; ++mesh)
  {
    const TwoHexes h = MakeTwoHexes(rng);
    double pc[3];
    for (int r = 0; r < 100; ++r, ++rays)
    {
      double xa[3], xb[3], d[3];
      hovtest::RandomInteriorPC(CellShape::Hexahedron, rng, 0.05, pc);
      hov::EvaluateGeometry(CellShape::Hexahedron, h.A.Points.data(), pc, xa, nullptr);
      hovtest::RandomInteriorPC(CellShape::Hexahedron, rng, 0.05, pc);
      hov::EvaluateGeometry(CellShape::Hexahedron, h.B.Points.data(), pc, xb, nullptr);
      for (int k = 0; k < 3; ++k)
      {
        d[k] = xb[k] - xa[k];
      }
      hov::RayCellInterval ia[hov::MaxRayCellIntervals], ib[hov::MaxRayCellIntervals];
      const int na = hov::RayCellIntervals(
        CellShape::Hexahedron, h.A.Points.data(), h.A.Ids.data(), xa, d, 0.0, 1.0, ia);
      const int nb = hov::RayCellIntervals(
        CellShape::Hexahedron, h.B.Points.data(), h.B.Ids.data(), xa, d, 0.0, 1.0, ib);
      ASSERT_GE(na, 1);
      ASSERT_GE(nb, 1);
      // The segment starts in A and ends in B: the A-part starting at 0 ends
      // where the B-part ending at 1 begins, unless the ray leaves the pair
      // in between (then it leaves through another face of A or B).
      if (ia[0].T0 == 0.0 && ib[nb - 1].T1 == 1.0 && na == 1 && nb == 1 &&
        ia[0].T1 <= ib[0].T0)
      {
        const double tShared = ia[0].T1;
        const double xm[3] = { xa[0] + tShared * d[0], xa[1] + tShared * d[1],
          xa[2] + tShared * d[2] };
        (void)xm;
        if (ia[0].T1 == ib[0].T0)
        {
          ++checked;
        }
        else
        {
          // A gap is only allowed if the ray really leaves both cells there.
          const double tm = 0.5 * (ia[0].T1 + ib[0].T0);
          double pcm[3];
          hov::CellParametricCenter(CellShape::Hexahedron, pcm);
          const double x[3] = { xa[0] + tm * d[0], xa[1] + tm * d[1], xa[2] + tm * d[2] };
          const bool inA = hov::InvertGeometry(CellShape::Hexahedron, h.A.Points.data(), x, pcm) &&
            hov::ParametricDistanceOutside(CellShape::Hexahedron, pcm) < 0.0;
          EXPECT_FALSE(inA) << "gap between shared-face crossings, mesh " << mesh << " ray " << r;
        }
      }
      EXPECT_FALSE(na >= 1 && nb >= 1 && ia[na - 1].T1 > ib[0].T0) << "overlap (double counting)";
    }
  }
  std::cout << "[measured] shared non-planar face: exit == entry exactly on " << checked << " of "
            << rays << " rays" << std::endl;
  EXPECT_GT(checked, rays * 8 / 10);
}

TEST(CellRay, DegenerateRaysGiveNoNaN)
{
  std::mt19937_64 rng(35);
  for (CellShape shape : hovtest::AllCellShapes())
  {
    for (double distortion : { 0.0, 0.2 })
    {
      const hovtest::TestCell cell = hovtest::MakeRandomCell(shape, rng, distortion);
      const int nc = hov::CellCornerCount(shape);
      const double* p = cell.Points.data();
      for (int i = 0; i < nc; ++i)
      {
        for (int j = 0; j < nc; ++j)
        {
          // Through corner i towards corner j (edges, diagonals), and parallel
          // to that edge through corner (i+1)%nc (in a face plane when i, j,
          // i+1 share a face).
          for (int variant = 0; variant < 2; ++variant)
          {
            double d[3], o[3];
            const double* base = p + 3 * (variant == 0 ? i : (i + 1) % nc);
            for (int k = 0; k < 3; ++k)
            {
              d[k] = p[3 * j + k] - p[3 * i + k];
              o[k] = base[k] - 2.0 * d[k];
            }
            if (i == j)
            {
              d[0] = 1.0;
            }
            hov::RayCellInterval iv[hov::MaxRayCellIntervals];
            const int n = hov::RayCellIntervals(shape, p, cell.Ids.data(), o, d, 0.0, 5.0, iv);
            for (int q = 0; q < n; ++q)
            {
              ASSERT_TRUE(std::isfinite(iv[q].T0) && std::isfinite(iv[q].T1));
              ASSERT_LT(iv[q].T0, iv[q].T1);
              std::vector<hov::RestrictedPiece> pieces;
              hov::RestrictCellScalar(shape, p, cell.Scalars.data(), o, d, iv[q].T0, iv[q].T1,
                hov::CellRestrictionSettings(), pieces);
              for (const auto& piece : pieces)
              {
                for (int c = 0; c <= piece.S.Degree; ++c)
                {
                  ASSERT_TRUE(std::isfinite(piece.S.C[c])) << ShapeName(shape);
                }
                ASSERT_TRUE(std::isfinite(piece.ErrorBound));
              }
            }
          }
        }
      }
    }
  }
}
}
