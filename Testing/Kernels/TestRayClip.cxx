// hov::ClipFourPlanes (hovRayClip.h), the ray/tetrahedron clip written once
// over the value type: the four-lane vector instantiation equals the double
// one bit for bit lane by lane; both equal taking the planes one after the
// other (the scalar loop the CPU projector had) on every hit; parallel faces
// are flagged; a closed form (a unit-cube corner tetrahedron) is met exactly.
#include "hovRayClip.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

namespace
{
/// The four face planes n . x <= h of the tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1).
struct Planes
{
  double NX[4] = { -1.0, 0.0, 0.0, 1.0 };
  double NY[4] = { 0.0, -1.0, 0.0, 1.0 };
  double NZ[4] = { 0.0, 0.0, -1.0, 1.0 };
  double H[4] = { 0.0, 0.0, 0.0, 1.0 };
};

/// The planes one after the other (std::min/std::max), as the scalar clip did.
bool Sequential(const Planes& p, const double o[3], const double d[3], double tMax, double& tIn,
  double& tOut)
{
  tIn = 0.0;
  tOut = tMax;
  for (int k = 0; k < 4; ++k)
  {
    const double denom = (p.NX[k] * d[0] + p.NY[k] * d[1]) + p.NZ[k] * d[2];
    const double num = p.H[k] - ((p.NX[k] * o[0] + p.NY[k] * o[1]) + p.NZ[k] * o[2]);
    if (denom > 0.0)
    {
      tOut = std::min(tOut, num / denom);
    }
    else if (denom < 0.0)
    {
      tIn = std::max(tIn, num / denom);
    }
    else if (num < 0.0)
    {
      return false;
    }
  }
  return tIn < tOut;
}

/// Random planes of a random tetrahedron.
Planes RandomPlanes(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Planes p;
  for (int k = 0; k < 4; ++k)
  {
    p.NX[k] = u(rng);
    p.NY[k] = u(rng);
    p.NZ[k] = u(rng);
    p.H[k] = 0.5 + 0.5 * std::abs(u(rng)); // the origin inside
  }
  return p;
}
}

TEST(RayClip, ClosedForm)
{
  const Planes p;
  const double o[3] = { 0.1, 0.2, -1.0 }, d[3] = { 0.0, 0.0, 1.0 };
  double tIn = 0.0, tOut = 0.0;
  bool parallel = false;
  hov::ClipFourPlanes(p.NX, p.NY, p.NZ, p.H, o[0], o[1], o[2], d[0], d[1], d[2], 10.0, tIn, tOut,
    parallel);
  EXPECT_TRUE(parallel); // the faces x = 0 and y = 0 contain the direction
  const double x[3] = { -0.5, 0.25, 0.25 }, dx[3] = { 1.0, 0.0, 0.0 };
  parallel = false;
  hov::ClipFourPlanes(p.NX, p.NY, p.NZ, p.H, x[0], x[1], x[2], dx[0], dx[1], dx[2], 10.0, tIn,
    tOut, parallel);
  EXPECT_TRUE(parallel);
  const double e[3] = { -1.0, -1.0, -1.0 }, de[3] = { 1.0, 1.0, 1.0 };
  parallel = false;
  hov::ClipFourPlanes(p.NX, p.NY, p.NZ, p.H, e[0], e[1], e[2], de[0], de[1], de[2], 10.0, tIn,
    tOut, parallel);
  EXPECT_FALSE(parallel);
  EXPECT_EQ(tIn, 1.0);          // enters at the origin
  EXPECT_EQ(tOut, 1.0 + 1.0 / 3.0); // leaves through x + y + z = 1
}

TEST(RayClip, LanesEqualScalarAndSequential)
{
#if defined(__GNUC__)
  typedef double V4 __attribute__((vector_size(4 * sizeof(double))));
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  long long hits = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    const Planes p = RandomPlanes(rng);
    double o[4][3], d[4][3], tMax[4];
    for (int l = 0; l < 4; ++l)
    {
      for (int c = 0; c < 3; ++c)
      {
        o[l][c] = u(rng);
        d[l][c] = u(rng);
      }
      tMax[l] = trial % 7 == 0 ? 0.0 : 3.0 * std::abs(u(rng)); // sometimes an empty range
    }
    V4 ox, oy, oz, dx, dy, dz, vMax;
    for (int l = 0; l < 4; ++l)
    {
      ox[l] = o[l][0];
      oy[l] = o[l][1];
      oz[l] = o[l][2];
      dx[l] = d[l][0];
      dy[l] = d[l][1];
      dz[l] = d[l][2];
      vMax[l] = tMax[l];
    }
    V4 vIn, vOut;
    auto parallel = V4{} < V4{};
    hov::ClipFourPlanes(p.NX, p.NY, p.NZ, p.H, ox, oy, oz, dx, dy, dz, vMax, vIn, vOut, parallel);
    for (int l = 0; l < 4; ++l)
    {
      double tIn, tOut;
      bool scalarParallel = false;
      hov::ClipFourPlanes(p.NX, p.NY, p.NZ, p.H, o[l][0], o[l][1], o[l][2], d[l][0], d[l][1],
        d[l][2], tMax[l], tIn, tOut, scalarParallel);
      ASSERT_EQ(std::memcmp(&tIn, &vIn[l], sizeof(double)), 0) << "trial " << trial;
      ASSERT_EQ(std::memcmp(&tOut, &vOut[l], sizeof(double)), 0) << "trial " << trial;
      ASSERT_EQ(scalarParallel, parallel[l] != 0);
      double sIn, sOut;
      const bool hit = Sequential(p, o[l], d[l], tMax[l], sIn, sOut);
      ASSERT_EQ(hit, tIn < tOut) << "trial " << trial;
      if (hit)
      {
        ++hits;
        ASSERT_EQ(std::memcmp(&tIn, &sIn, sizeof(double)), 0) << "trial " << trial;
        ASSERT_EQ(std::memcmp(&tOut, &sOut, sizeof(double)), 0) << "trial " << trial;
      }
    }
  }
  EXPECT_GT(hits, 10000);
#endif
}
