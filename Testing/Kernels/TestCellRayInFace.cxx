// Rays lying EXACTLY in the plane of a face shared by two cells
// (hovRayCell.h, "Rays lying in a face plane"): the symbolic displacement
// must give the ray to exactly one of the two cells, so that along the ray
// every point of the union is covered once (no crack, no double counting) and
// the total inside length equals the union's chord, computed independently by
// clipping the ray against the union's own half-spaces.
#include "hovRayCell.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace
{
using hov::CellShape;

struct Cell
{
  CellShape Shape;
  std::vector<double> Points; ///< 3 per node
  std::vector<std::int64_t> Ids;
};

using P3 = std::array<double, 3>;

/// A cell from global points and ids (corners only; quadratic tetrahedra get
/// their edge midpoints, which RayCellIntervals does not read for geometry).
Cell MakeCell(CellShape shape, const std::vector<P3>& pts, const std::vector<std::int64_t>& ids)
{
  Cell c{ shape, {}, ids };
  for (const std::int64_t id : ids)
  {
    c.Points.insert(c.Points.end(), pts[id].begin(), pts[id].end());
  }
  if (shape == CellShape::QuadraticTetra)
  {
    const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
    for (const auto& e : edges)
    {
      for (int k = 0; k < 3; ++k)
      {
        c.Points.push_back(0.5 * (pts[ids[e[0]]][k] + pts[ids[e[1]]][k]));
      }
    }
  }
  return c;
}

/// The six Kuhn tetrahedra of the unit cube (points i = x + 2y + 4z), as
/// quadratic tetrahedra, positively oriented. Their faces lie in x = y, y = z,
/// x = z.
std::vector<Cell> KuhnCube(std::vector<P3>& pts)
{
  pts.clear();
  for (int i = 0; i < 8; ++i)
  {
    pts.push_back({ double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1) });
  }
  std::vector<Cell> cells;
  int perm[3] = { 0, 1, 2 };
  do
  {
    const std::int64_t a = 1 << perm[0], b = a + (1 << perm[1]);
    std::vector<std::int64_t> ids = { 0, a, b, 7 };
    const P3 &p0 = pts[0], &p1 = pts[a], &p2 = pts[b], &p3 = pts[7];
    const double det =
      (p1[0] - p0[0]) * ((p2[1] - p0[1]) * (p3[2] - p0[2]) - (p2[2] - p0[2]) * (p3[1] - p0[1])) -
      (p1[1] - p0[1]) * ((p2[0] - p0[0]) * (p3[2] - p0[2]) - (p2[2] - p0[2]) * (p3[0] - p0[0])) +
      (p1[2] - p0[2]) * ((p2[0] - p0[0]) * (p3[1] - p0[1]) - (p2[1] - p0[1]) * (p3[0] - p0[0]));
    if (det < 0.0)
    {
      std::swap(ids[1], ids[2]);
    }
    cells.push_back(MakeCell(CellShape::QuadraticTetra, pts, ids));
  } while (std::next_permutation(perm, perm + 3));
  return cells;
}

/// Chord [t0, t1] of the ray in the region {x : a.x <= b for every (a, b)}.
bool Chord(const std::vector<std::array<double, 4>>& halfSpaces, const double o[3],
  const double d[3], double tMax, double& t0, double& t1)
{
  t0 = 0.0;
  t1 = tMax;
  for (const auto& h : halfSpaces)
  {
    const double den = h[0] * d[0] + h[1] * d[1] + h[2] * d[2];
    const double num = h[3] - (h[0] * o[0] + h[1] * o[1] + h[2] * o[2]);
    if (den == 0.0)
    {
      if (num < 0.0)
      {
        return false;
      }
      continue;
    }
    (den > 0.0 ? t1 : t0) = den > 0.0 ? std::min(t1, num / den) : std::max(t0, num / den);
  }
  return t0 < t1;
}

std::vector<std::array<double, 4>> Box(const double lo[3], const double hi[3])
{
  std::vector<std::array<double, 4>> h;
  for (int k = 0; k < 3; ++k)
  {
    std::array<double, 4> a = { 0, 0, 0, hi[k] }, b = { 0, 0, 0, -lo[k] };
    a[k] = 1.0;
    b[k] = -1.0;
    h.push_back(a);
    h.push_back(b);
  }
  return h;
}

struct Coverage
{
  double Total = 0.0; ///< sum of all cells' interval lengths
  int WorstCount = 1; ///< a sample point covered by != 1 cells (or 1)
  int Samples = 0;
};

/// All cells' intervals on the ray; samples inside [t0, t1] must be covered
/// once.
Coverage Cover(const std::vector<Cell>& cells, const double o[3], const double d[3], double tMax,
  const hov::RayPerturbation* pert, double t0, double t1, bool planarKnown = true)
{
  Coverage cov;
  std::vector<hov::RayCellInterval> all;
  std::vector<int> owner;
  for (size_t c = 0; c < cells.size(); ++c)
  {
    hov::RayCellInterval iv[hov::MaxRayCellIntervals];
    const Cell& cell = cells[c];
    const unsigned mask = hov::PlanarFaceMask(cell.Shape, cell.Points.data());
    const int n = pert ? hov::RayCellIntervals(cell.Shape, cell.Points.data(), cell.Ids.data(), o,
                           d, 0.0, tMax, iv, mask, *pert)
                       : (planarKnown ? hov::RayCellIntervals(cell.Shape, cell.Points.data(),
                                          cell.Ids.data(), o, d, 0.0, tMax, iv, mask)
                                      : hov::RayCellIntervals(cell.Shape, cell.Points.data(),
                                          cell.Ids.data(), o, d, 0.0, tMax, iv));
    for (int i = 0; i < n; ++i)
    {
      cov.Total += iv[i].T1 - iv[i].T0;
      all.push_back(iv[i]);
      owner.push_back(static_cast<int>(c));
    }
  }
  for (int s = 1; s < 200; ++s)
  {
    const double t = t0 + (t1 - t0) * (s + 0.37) / 200.5;
    int count = 0;
    for (const auto& iv : all)
    {
      count += (iv.T0 < t && t < iv.T1) ? 1 : 0;
    }
    ++cov.Samples;
    if (count != 1)
    {
      cov.WorstCount = count;
    }
  }
  return cov;
}

hov::RayPerturbation RandomPerturbation(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  hov::RayPerturbation p;
  for (int k = 0; k < 3; ++k)
  {
    p.X[k] = u(rng);
    p.Y[k] = u(rng);
  }
  return p;
}

/// Runs @p rays in-plane rays (made by @p makeRay) through @p cells with the
/// default and random perturbations; expects coverage 1 and total == chord.
template <typename MakeRay>
void CheckInPlane(const std::vector<Cell>& cells, const std::vector<std::array<double, 4>>& union_,
  MakeRay makeRay, int rays, const char* what)
{
  std::mt19937_64 rng(20261122);
  int tested = 0;
  double worst = 0.0;
  for (int r = 0; r < rays; ++r)
  {
    double o[3], d[3];
    makeRay(rng, o, d);
    double t0, t1;
    if (!Chord(union_, o, d, 10.0, t0, t1))
    {
      continue;
    }
    ++tested;
    for (int variant = 0; variant < 3; ++variant)
    {
      const hov::RayPerturbation p = RandomPerturbation(rng);
      const Coverage cov =
        Cover(cells, o, d, 10.0, variant == 2 ? &p : nullptr, t0, t1, variant == 0);
      ASSERT_EQ(cov.WorstCount, 1) << what << " ray " << r << " variant " << variant;
      const double err = std::fabs(cov.Total - (t1 - t0));
      worst = std::max(worst, err);
      ASSERT_LE(err, 1e-12 * (t1 - t0) + 1e-15) << what << " ray " << r << " variant " << variant;
    }
  }
  EXPECT_GT(tested, rays / 3) << what;
  std::printf("[measured] %s: %d in-plane rays x 3 perturbations, worst "
              "|length - chord| = %.3g\n",
    what, tested, worst);
}
} // namespace

TEST(CellRayInFace, KuhnQuadraticTetsDiagonalPlanes)
{
  std::vector<P3> pts;
  const std::vector<Cell> cells = KuhnCube(pts);
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
  // Rays in x = y (axis-aligned along z and random in the plane), and in y = z.
  for (int plane = 0; plane < 2; ++plane)
  {
    CheckInPlane(
      cells, Box(lo, hi),
      [plane](std::mt19937_64& rng, double o[3], double d[3])
      {
        std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
        const double s = w(rng), r = w(rng);
        const bool axis = w(rng) < 0.3;
        const double a = axis ? 0.0 : u(rng), b = axis ? 1.0 : u(rng);
        // plane 0: (s, s, r) + t (a, a, b); plane 1: (r, s, s) + t (b, a, a)
        const double oo[3] = { s, s, r }, dd[3] = { a, a, b };
        for (int k = 0; k < 3; ++k)
        {
          o[k] = plane == 0 ? oo[k] : oo[(k + 2) % 3];
          d[k] = plane == 0 ? dd[k] : dd[(k + 2) % 3];
        }
        for (int k = 0; k < 3; ++k)
        {
          o[k] -= 3.0 * d[k]; // start outside
        }
      },
      300, plane == 0 ? "Kuhn x=y" : "Kuhn y=z");
  }
}

TEST(CellRayInFace, HexHexPlanarAndNonPlanar)
{
  // Two hexahedra sharing the face x = 1 (points listed in different VTK
  // orders); variant 1 bends the far faces (x = 0, x = 2) out of plane, so the
  // cells take the classified path while the shared face stays planar.
  for (int bent = 0; bent < 2; ++bent)
  {
    std::vector<P3> pts;
    for (int i = 0; i < 12; ++i) // i = x + 3 y + 6 z, x in {0, 1, 2}
    {
      pts.push_back({ double(i % 3), double((i / 3) % 2), double(i / 6) });
    }
    if (bent)
    {
      pts[0][0] = -0.2; // (0,0,0)
      pts[11][0] = 2.3; // (2,1,1)
    }
    std::vector<Cell> cells;
    cells.push_back(MakeCell(CellShape::Hexahedron, pts, { 0, 1, 4, 3, 6, 7, 10, 9 }));
    // The second cell starts from another corner: bottom face (1,2,5,4)
    // rotated.
    cells.push_back(MakeCell(CellShape::Hexahedron, pts, { 5, 4, 1, 2, 11, 10, 7, 8 }));
    ASSERT_EQ(hov::PlanarFaceMask(cells[0].Shape, cells[0].Points.data()) != 63u, bent == 1);
    const double lo[3] = { 0, 0, 0 }, hi[3] = { 2, 1, 1 };
    CheckInPlane(
      cells, Box(lo, hi),
      [](std::mt19937_64& rng, double o[3], double d[3])
      {
        std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
        o[0] = 1.0;
        o[1] = w(rng);
        o[2] = w(rng);
        d[0] = 0.0;
        d[1] = u(rng);
        d[2] = w(rng) < 0.3 ? 0.0 : u(rng);
        o[1] -= 3.0 * d[1];
        o[2] -= 3.0 * d[2];
      },
      300, bent ? "hex/hex bent" : "hex/hex planar");
  }
}

TEST(CellRayInFace, WedgeTetAndPyramidTet)
{
  // A wedge above z = 0 and a linear tetrahedron below share the triangle
  // (0,0,0) (1,0,0) (0,1,0); rays in z = 0 cross only that triangle.
  std::vector<P3> pts = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 },
    { 0, 1, 1 }, { 0.2, 0.2, -1 } };
  std::vector<Cell> cells;
  cells.push_back(MakeCell(CellShape::Wedge, pts, { 0, 1, 2, 3, 4, 5 }));
  cells.push_back(MakeCell(CellShape::Tetra, pts, { 6, 2, 1, 0 }));
  const std::vector<std::array<double, 4>> triangle = { { 0, 0, 1, 0 }, { 0, 0, -1, 0 },
    { -1, 0, 0, 0 }, { 0, -1, 0, 0 }, { 1, 1, 0, 1 } };
  const auto inZ0 = [](std::mt19937_64& rng, double o[3], double d[3])
  {
    std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
    o[0] = w(rng) * 0.5;
    o[1] = w(rng) * 0.5;
    o[2] = 0.0;
    d[0] = u(rng);
    d[1] = u(rng);
    d[2] = 0.0;
    o[0] -= 3.0 * d[0];
    o[1] -= 3.0 * d[1];
  };
  CheckInPlane(cells, triangle, inZ0, 300, "wedge/tet z=0");
  // A pyramid and a quadratic tetrahedron outside it sharing its triangle
  // (0,1,4).
  std::vector<P3> pp = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0.5, 0.5, 1 },
    { 0.5, -1, 0.3 } };
  std::vector<Cell> pyr;
  pyr.push_back(MakeCell(CellShape::Pyramid, pp, { 0, 1, 2, 3, 4 }));
  pyr.push_back(MakeCell(CellShape::QuadraticTetra, pp, { 0, 4, 1, 5 }));
  // Plane of (0,0,0) (1,0,0) (0.5,0.5,1): 2y - z = 0. Rays (s, u, 2u) + t (a,
  // b, 2b). In the plane: y >= 0 (z >= 0), y <= x (-2x + z <= 0), x + y <= 1
  // (2x + z <= 2).
  const std::vector<std::array<double, 4>> tri = { { 0, 2, -1, 0 }, { 0, -2, 1, 0 },
    { 0, 0, -1, 0 }, { -2, 0, 1, 0 }, { 2, 0, 1, 2 } };
  CheckInPlane(
    pyr, tri,
    [](std::mt19937_64& rng, double o[3], double d[3])
    {
      std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
      const double s = w(rng), v = 0.25 * w(rng);
      const double a = u(rng), b = u(rng);
      o[0] = s - 3.0 * a;
      o[1] = v - 3.0 * b;
      o[2] = 2.0 * o[1];
      d[0] = a;
      d[1] = b;
      d[2] = 2.0 * b;
    },
    300, "pyramid/tet 2y=z");
}

TEST(CellRayInFace, OppositeNormalsDecideOneSide)
{
  // The same shared triangle seen by two tetrahedra: for every perturbation
  // with n.X != 0 or n.Y != 0 exactly one of them holds a ray in its plane.
  std::vector<P3> pts = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0.3, 0.3, 1 },
    { 0.3, 0.2, -1 } };
  const Cell up = MakeCell(CellShape::Tetra, pts, { 0, 1, 2, 3 });
  const Cell down = MakeCell(CellShape::Tetra, pts, { 0, 2, 1, 4 });
  const double o[3] = { -1.0, 0.25, 0.0 }, d[3] = { 1.0, 0.0, 0.0 };
  std::mt19937_64 rng(7);
  for (int i = 0; i < 200; ++i)
  {
    hov::RayPerturbation p = RandomPerturbation(rng);
    if (i % 4 == 0)
    {
      p.X[2] = 0.0; // n.X == 0: decided by Y
    }
    hov::RayCellInterval a[hov::MaxRayCellIntervals], b[hov::MaxRayCellIntervals];
    const int na = hov::RayCellIntervals(up.Shape, up.Points.data(), up.Ids.data(), o, d, 0.0, 5.0,
      a, hov::PlanarFaceMask(up.Shape, up.Points.data()), p);
    const int nb = hov::RayCellIntervals(down.Shape, down.Points.data(), down.Ids.data(), o, d, 0.0,
      5.0, b, hov::PlanarFaceMask(down.Shape, down.Points.data()), p);
    ASSERT_EQ(na + nb, 1) << i;
    const bool expectUp = p.X[2] != 0.0 ? p.X[2] > 0.0 : p.Y[2] > 0.0;
    EXPECT_EQ(na == 1, expectUp) << i;
    const hov::RayCellInterval& iv = na ? a[0] : b[0];
    EXPECT_NEAR(iv.T0, 1.0,
      1e-14); // the base triangle's chord at y = 0.25: x in [0, 0.75]
    EXPECT_NEAR(iv.T1, 1.75, 1e-14);
  }
}

TEST(CellRayInFace, TriangleCrossingMatchesTetraFastPathBits)
{
  // The fast path's plane of a tetrahedron face (hov::CellSetup:
  // ascending ids, n = (x1 - x0) x (x2 - x0), Offset = n.x0, t = (Offset - n.o)
  // / n.d, dot products summed left to right) must give the general path's t
  // bit for bit.
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int compared = 0;
  for (int r = 0; r < 2000; ++r)
  {
    double x[3][3], o[3], d[3];
    std::int64_t ids[3] = { 40, 7, 19 };
    for (int k = 0; k < 3; ++k)
    {
      o[k] = 3.0 * u(rng);
      d[k] = u(rng);
      for (int v = 0; v < 3; ++v)
      {
        x[v][k] = u(rng) + 0.1 * v;
      }
    }
    // Reference (fast path): corners by ascending id: 7, 19, 40.
    const double* a = x[1];
    const double* b = x[2];
    const double* c = x[0];
    const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double n[3] = { e1[1] * e2[2] - e2[1] * e1[2], e1[2] * e2[0] - e2[2] * e1[0],
      e1[0] * e2[1] - e2[0] * e1[1] };
    const double offset = n[0] * a[0] + n[1] * a[1] + n[2] * a[2];
    const double den = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
    const double tRef = (offset - (n[0] * o[0] + n[1] * o[1] + n[2] * o[2])) / den;
    const double* corners[4] = { x[0], x[1], x[2], nullptr };
    for (int rot = 0; rot < 3; ++rot)
    {
      const double* cc[4] = { corners[rot], corners[(rot + 1) % 3], corners[(rot + 2) % 3],
        nullptr };
      const std::int64_t ii[4] = { ids[rot], ids[(rot + 1) % 3], ids[(rot + 2) % 3], 0 };
      double t[2];
      ASSERT_EQ(hov::FaceRayCrossings(3, cc, ii, o, d, t), 1);
      ASSERT_EQ(t[0], tRef) << r << " rotation " << rot;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 6000);
}
