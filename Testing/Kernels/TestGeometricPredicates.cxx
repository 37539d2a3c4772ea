// Tests of hovGeometricPredicates: exact signs of Orient2d / Orient3d /
// Orient3dDirection against an independent integer evaluation (every double is
// m 2^e; all coordinates of a case are scaled by a common power of two into
// cpp_int, so the determinant is an exact integer), on random, near-degenerate
// (one ulp off coplanar/collinear), huge and tiny inputs; antisymmetry.
#include "hovGeometricPredicates.h"

#include <boost/multiprecision/cpp_int.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace
{
using Int = boost::multiprecision::cpp_int;

/// Exact integers v_i = x_i 2^K for a common K (all x_i finite).
std::vector<Int> ToIntegers(const std::vector<double>& x)
{
  int minExp = std::numeric_limits<int>::max();
  for (double v : x)
  {
    if (v != 0)
    {
      int e;
      std::frexp(v, &e);
      minExp = std::min(minExp, e - 53);
    }
  }
  std::vector<Int> out;
  for (double v : x)
  {
    if (v == 0 || minExp == std::numeric_limits<int>::max())
    {
      out.emplace_back(0);
      continue;
    }
    int e;
    const double f = std::frexp(v, &e);
    Int m(static_cast<long long>(std::ldexp(f, 53))); // exact 53-bit mantissa
    out.push_back(m << (e - 53 - minExp));
  }
  return out;
}

int Sign(const Int& v)
{
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

int Ref2(const double a[2], const double b[2], const double c[2])
{
  const auto v = ToIntegers({ a[0], a[1], b[0], b[1], c[0], c[1] });
  return Sign((v[0] - v[4]) * (v[3] - v[5]) - (v[1] - v[5]) * (v[2] - v[4]));
}

int Det3(const Int m[3][3])
{
  return Sign(m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
    m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]));
}

int Ref3(const double a[3], const double b[3], const double c[3], const double d[3])
{
  const auto v = ToIntegers({ a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2] });
  Int m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      m[i][j] = v[3 * i + j] - v[9 + j];
  return Det3(m);
}

int Ref3Dir(const double a[3], const double b[3], const double c[3], const double w[3])
{
  const auto v = ToIntegers({ a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], w[0], w[1], w[2] });
  Int m[3][3];
  for (int j = 0; j < 3; ++j)
  {
    m[0][j] = v[3 + j] - v[j];
    m[1][j] = v[6 + j] - v[j];
    m[2][j] = v[9 + j];
  }
  return -Det3(m);
}

double Ulp(double x, int k)
{
  for (int i = 0; i < std::abs(k); ++i)
    x = std::nextafter(x, k > 0 ? HUGE_VAL : -HUGE_VAL);
  return x;
}

void Check3(const double a[3], const double b[3], const double c[3], const double d[3])
{
  const int ref = Ref3(a, b, c, d);
  ASSERT_EQ(hov::Orient3d(a, b, c, d), ref)
    << "a=(" << a[0] << "," << a[1] << "," << a[2] << ") d=(" << d[0] << "," << d[1] << ","
    << d[2] << ")";
  ASSERT_EQ(hov::Orient3dExact(a, b, c, d), ref);
  // Antisymmetry under swaps, invariance under cyclic permutation of a, b, c.
  ASSERT_EQ(hov::Orient3d(b, a, c, d), -ref);
  ASSERT_EQ(hov::Orient3d(a, c, b, d), -ref);
  ASSERT_EQ(hov::Orient3d(b, c, a, d), ref);
}

void Check2(const double a[2], const double b[2], const double c[2])
{
  const int ref = Ref2(a, b, c);
  ASSERT_EQ(hov::Orient2d(a, b, c), ref);
  ASSERT_EQ(hov::Orient2dExact(a, b, c), ref);
  ASSERT_EQ(hov::Orient2d(b, a, c), -ref);
  ASSERT_EQ(hov::Orient2d(b, c, a), ref);
}
}

TEST(GeometricPredicates, SimpleSigns)
{
  const double a[3] = { 0, 0, 0 }, b[3] = { 1, 0, 0 }, c[3] = { 0, 1, 0 };
  const double up[3] = { 0, 0, 1 }, down[3] = { 0, 0, -1 }, in[3] = { 0.3, 0.3, 0 };
  EXPECT_EQ(hov::Orient3d(a, b, c, up), -1); // above = outside of a CCW face
  EXPECT_EQ(hov::Orient3d(a, b, c, down), 1);
  EXPECT_EQ(hov::Orient3d(a, b, c, in), 0);
  EXPECT_EQ(hov::Orient3dDirection(a, b, c, up), -1);
  EXPECT_EQ(hov::Orient3dDirection(a, b, c, down), 1);
  EXPECT_EQ(hov::Orient3dDirection(a, b, c, b), 0);
  EXPECT_EQ(hov::Orient2d(a, b, c), 1);
  EXPECT_EQ(hov::Orient2d(a, c, b), -1);
  const double nan[3] = { std::nan(""), 0, 0 };
  EXPECT_EQ(hov::Orient3d(a, b, c, nan), 0);
}

TEST(GeometricPredicates, RandomPoints)
{
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int n = 0; n < 5000; ++n)
  {
    double p[4][3];
    for (auto& q : p)
      for (double& v : q)
        v = u(rng);
    Check3(p[0], p[1], p[2], p[3]);
    Check2(p[0], p[1], p[2]);
    ASSERT_EQ(hov::Orient3dDirection(p[0], p[1], p[2], p[3]), Ref3Dir(p[0], p[1], p[2], p[3]));
  }
}

TEST(GeometricPredicates, NearDegenerate)
{
  // Points on a plane / line, then one coordinate moved by -2..2 ulps; at
  // scales from 1e-150 to 1e150 (tiny values exercise the underflow guard).
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> u(-1, 1);
  const double scales[] = { 1e-150, 1e-20, 1.0, 3.7e5, 1e20, 1e150 };
  int nonzero = 0, zero = 0;
  for (double s : scales)
  {
    for (int n = 0; n < 1000; ++n)
    {
      // a, b, c random; d = a + x (b - a) + y (c - a) rounded, then perturbed.
      double p[4][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          p[i][j] = s * u(rng);
      const double x = u(rng), y = u(rng);
      for (int j = 0; j < 3; ++j)
        p[3][j] = p[0][j] + x * (p[1][j] - p[0][j]) + y * (p[2][j] - p[0][j]);
      p[3][n % 3] = Ulp(p[3][n % 3], n % 5 - 2);
      // Exactly coplanar cases too: d on an axis-aligned plane with a, b, c.
      if (n % 7 == 0)
      {
        p[0][2] = p[1][2] = p[2][2] = p[3][2];
      }
      Check3(p[0], p[1], p[2], p[3]);
      (Ref3(p[0], p[1], p[2], p[3]) == 0 ? zero : nonzero)++;
      ASSERT_EQ(hov::Orient3dDirection(p[0], p[1], p[2], p[3]), Ref3Dir(p[0], p[1], p[2], p[3]));
      // 2D: c on the line ab, perturbed.
      double q[3][2] = { { p[0][0], p[0][1] }, { p[1][0], p[1][1] }, { 0, 0 } };
      for (int j = 0; j < 2; ++j)
        q[2][j] = q[0][j] + x * (q[1][j] - q[0][j]);
      q[2][n % 2] = Ulp(q[2][n % 2], n % 3 - 1);
      Check2(q[0], q[1], q[2]);
    }
  }
  // The generator must produce both exact zeros and one-ulp signs.
  EXPECT_GT(zero, 50);
  EXPECT_GT(nonzero, 1000);
}

TEST(GeometricPredicates, SharedFacePlanes)
{
  // Points of a perturbed grid: a face and a point of the same face give an
  // exact zero whatever the rounding of the coordinates.
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(0.1, 10);
  for (int n = 0; n < 2000; ++n)
  {
    double p[3][3];
    for (auto& q : p)
      for (double& v : q)
        v = u(rng) * 1e-3 + 1e3;
    EXPECT_EQ(hov::Orient3d(p[0], p[1], p[2], p[1]), 0);
    EXPECT_EQ(hov::Orient3d(p[2], p[0], p[1], p[0]), 0);
  }
}

TEST(GeometricPredicates, LargeIntegerNearDegenerate)
{
  // Integer coordinates up to 2^40 (differences exact, products far beyond 53
  // bits): exactly coplanar/collinear points and points moved by one unit,
  // where the double filter fails and the expansion stage decides.
  std::mt19937_64 rng(4242);
  std::uniform_int_distribution<long long> u(-(1LL << 40), 1LL << 40);
  std::uniform_int_distribution<int> small(-3, 3);
  int zero = 0, nonzero = 0;
  for (int n = 0; n < 3000; ++n)
  {
    double p[4][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        p[i][j] = static_cast<double>(u(rng) >> (n % 3 == 0 ? 20 : 0));
    const int s = small(rng), t = small(rng);
    for (int j = 0; j < 3; ++j)
      p[3][j] = p[0][j] + s * (p[1][j] - p[0][j]) + t * (p[2][j] - p[0][j]);
    p[3][n % 3] += n % 4 == 0 ? 0.0 : (n % 2 ? 1.0 : -1.0);
    Check3(p[0], p[1], p[2], p[3]);
    ASSERT_EQ(hov::Orient3dDirection(p[0], p[1], p[2], p[3]), Ref3Dir(p[0], p[1], p[2], p[3]));
    (Ref3(p[0], p[1], p[2], p[3]) == 0 ? zero : nonzero)++;
    double q[3][2] = { { p[0][0], p[0][1] }, { p[1][0], p[1][1] }, { 0, 0 } };
    for (int j = 0; j < 2; ++j)
      q[2][j] = q[0][j] + s * (q[1][j] - q[0][j]);
    q[2][n % 2] += n % 3 == 0 ? 0.0 : 1.0;
    Check2(q[0], q[1], q[2]);
  }
  EXPECT_GT(zero, 300);
  EXPECT_GT(nonzero, 1000);
}

TEST(GeometricPredicates, SmallGridPoints)
{
  // Points of integer and dyadic grids (the corners of meshes made from image
  // data, the heatsink benchmark): every product of the determinant is exact
  // in double, so the stage after the filter decides there without
  // expansions; exactly coplanar points, one grid step off, and mixes with a
  // coordinate of 53 significant bits (a product rounds: the expansions).
  std::mt19937_64 rng(777);
  std::uniform_int_distribution<int> u(-4096, 4096);
  std::uniform_int_distribution<int> small(-3, 3);
  const double scales[4] = { 1.0, 0.015625, std::ldexp(1.0, -70), std::ldexp(1.0, 60) };
  int zero = 0, nonzero = 0;
  for (int n = 0; n < 4000; ++n)
  {
    const double h = scales[n % 4];
    double p[4][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        p[i][j] = h * u(rng);
    const int s = small(rng), t = small(rng);
    for (int j = 0; j < 3; ++j)
      p[3][j] = p[0][j] + s * (p[1][j] - p[0][j]) + t * (p[2][j] - p[0][j]);
    p[3][n % 3] += n % 5 < 2 ? 0.0 : (n % 2 ? h : -h);
    if (n % 7 == 0)
    {
      p[n % 4][(n / 4) % 3] += h * 0.1; // 0.1 h: 53 significant bits
    }
    Check3(p[0], p[1], p[2], p[3]);
    (Ref3(p[0], p[1], p[2], p[3]) == 0 ? zero : nonzero)++;
  }
  EXPECT_GT(zero, 1000);
  EXPECT_GT(nonzero, 1500);
  // Determinant +-1 with products near 2^50 (still exact in double), where
  // the filter cannot decide: b - a = (X, 1, 0), c - a = (X + 1, 1, 0),
  // d - a = (Y, Z, +-1), axes permuted.
  std::uniform_int_distribution<long long> big(1LL << 23, 1LL << 25);
  const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
    { 2, 1, 0 } };
  for (int n = 0; n < 2000; ++n)
  {
    const double x = static_cast<double>(big(rng)), y = static_cast<double>(big(rng));
    const double z = static_cast<double>(big(rng)), w = n % 2 ? 1.0 : -1.0;
    const double rows[4][3] = { { 0, 0, 0 }, { x, 1, 0 }, { x + 1, 1, 0 }, { y, z, w } };
    const double a[3] = { 1.0 * u(rng), 1.0 * u(rng), 1.0 * u(rng) };
    double p[4][3];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 3; ++j)
        p[i][perms[n % 6][j]] = rows[i][j] + a[perms[n % 6][j]];
    ASSERT_NE(Ref3(p[0], p[1], p[2], p[3]), 0);
    Check3(p[0], p[1], p[2], p[3]);
  }
}

TEST(GeometricPredicates, AxisAlignedPlanes)
{
  // Triangles in a plane x_k = const (random, grid-aligned or degenerate), and
  // points on the plane, one ulp off it, or anywhere: AxisOrient3d must be
  // Orient3d's exact sign; non-aligned and non-finite triangles are refused.
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> grid(-4, 4);
  const double scales[] = { 1e-150, 1e-3, 1.0, 2.5e4, 1e150, 1e200 }; // 1e200: products overflow
  int counts[3] = { 0, 0, 0 }; // results -1, 0, 1
  for (double s : scales)
  {
    for (int n = 0; n < 2000; ++n)
    {
      const int k = n % 3;
      const bool onGrid = n % 4 == 0;
      double p[4][3];
      for (auto& q : p)
        for (double& v : q)
          v = onGrid ? s * 0.25 * grid(rng) : s * u(rng);
      p[1][k] = p[2][k] = p[0][k];
      if (n % 5 == 0)
      {
        p[3][k] = p[0][k]; // on the plane
      }
      else if (n % 5 == 1)
      {
        p[3][k] = Ulp(p[0][k], n % 2 ? 1 : -1);
      }
      if (n % 13 == 0)
      {
        // The plane x_k = 0 given with signed zeros (-0.0 == 0.0).
        p[0][k] = 0.0;
        p[1][k] = -0.0;
        p[2][k] = n % 2 ? -0.0 : 0.0;
        p[3][k] = n % 3 == 0 ? -0.0 : p[3][k];
      }
      if (n % 11 == 0)
      {
        // Degenerate: c on the line ab (sigma 0, every point "on" the plane).
        for (int j = 0; j < 3; ++j)
          p[2][j] = p[1][j];
      }
      int axis = -1, sigma = 2;
      ASSERT_TRUE(hov::AxisAlignedPlane(p[0], p[1], p[2], axis, sigma));
      const bool unique = !(p[0][(k + 1) % 3] == p[1][(k + 1) % 3] &&
        p[0][(k + 1) % 3] == p[2][(k + 1) % 3]) && !(p[0][(k + 2) % 3] == p[1][(k + 2) % 3] &&
        p[0][(k + 2) % 3] == p[2][(k + 2) % 3]);
      if (unique)
      {
        ASSERT_EQ(axis, k);
      }
      const int ref = Ref3(p[0], p[1], p[2], p[3]);
      ASSERT_EQ(hov::AxisOrient3d(axis, sigma, p[0], p[3]), ref) << "n " << n << " scale " << s;
      ASSERT_EQ(hov::Orient3d(p[0], p[1], p[2], p[3]), ref);
      ++counts[ref + 1];
    }
  }
  EXPECT_GT(counts[0], 1000); // all three outcomes occur
  EXPECT_GT(counts[1], 1000);
  EXPECT_GT(counts[2], 1000);
  // Not aligned, non-finite triangle, non-finite point.
  const double a[3] = { 0, 0, 0 }, b[3] = { 1, 0, 1 }, c[3] = { 0, 1, 0 };
  int axis = -1, sigma = 0;
  EXPECT_FALSE(hov::AxisAlignedPlane(a, b, c, axis, sigma));
  const double inf[3] = { 0, HUGE_VAL, 0 }, flat[3] = { 1, 0, 0 };
  EXPECT_FALSE(hov::AxisAlignedPlane(a, flat, inf, axis, sigma));
  ASSERT_TRUE(hov::AxisAlignedPlane(a, flat, c, axis, sigma));
  EXPECT_EQ(axis, 2);
  EXPECT_EQ(sigma, 1);
  const double nan[3] = { 0, std::nan(""), 1 }, infPoint[3] = { HUGE_VAL, 0, 1 };
  EXPECT_EQ(hov::AxisOrient3d(axis, sigma, a, nan), 0);
  EXPECT_EQ(hov::AxisOrient3d(axis, sigma, a, infPoint), 0);
  EXPECT_EQ(hov::Orient3d(a, flat, c, infPoint), 0);
}
