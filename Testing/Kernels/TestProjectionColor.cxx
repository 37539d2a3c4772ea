// Tests of hovProjectionColor: the per-vertex colour methods M0-M3 of the
// OpenGL cell projection, the M2 table and the opacity texture lookup
// (against 1 - exp(-L tau) in double; the GLSL port repeats the lookup).

#include "hovProjectionColor.h"

#include <boost/math/quadrature/tanh_sinh.hpp> // the reference of GPUAverageExtinction
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

namespace
{
hov::SegmentEnd End(double tau, double r, double g, double b)
{
  hov::SegmentEnd e;
  e.Tau = tau;
  e.Color[0] = r;
  e.Color[1] = g;
  e.Color[2] = b;
  return e;
}
}

TEST(ProjectionColor, OpacityTextureSweep)
{
  const std::vector<float> texels = hov::OpacityTexture::Texels();
  ASSERT_EQ(texels.size(), static_cast<size_t>(hov::OpacityTexture::Size) * hov::OpacityTexture::Size);
  double worst = 0.0, worstL = 0.0, worstTau = 0.0;
  // Log-uniform over 24 decades of length and extinction: thin, thick, dense,
  // transparent and every combination; the scale far from both.
  const double scale = 3.7;
  for (int i = 0; i <= 240; ++i)
  {
    for (int j = 0; j <= 240; ++j)
    {
      const double length = scale * std::pow(10.0, -12.0 + 0.1 * i);
      const double tau = std::pow(10.0, -12.0 + 0.1 * j) / scale;
      const double got = hov::OpacityFromTexture(texels, length, tau, scale);
      const double exact = -std::expm1(-length * tau);
      ASSERT_TRUE(std::isfinite(got)) << length << " " << tau;
      ASSERT_GE(got, 0.0);
      ASSERT_LE(got, 1.0);
      const double err = std::fabs(got - exact);
      if (err > worst)
      {
        worst = err;
        worstL = length;
        worstTau = tau;
      }
    }
  }
  std::cout << "[measured] opacity texture max |error| = " << worst << " at L = " << worstL
            << ", tau = " << worstTau << "\n";
  EXPECT_LE(worst, 2e-4); // bilinear between nodes 0.047 apart in log units (file doc)
  // Degenerate inputs: no opacity, no NaN.
  EXPECT_EQ(hov::OpacityFromTexture(texels, 0.0, 5.0, 1.0), 0.0);
  EXPECT_EQ(hov::OpacityFromTexture(texels, 1.0, 0.0, 1.0), 0.0);
  EXPECT_EQ(hov::OpacityFromTexture(texels, NAN, 1.0, 1.0), 0.0);
  EXPECT_EQ(hov::OpacityFromTexture(texels, 1e30, 1e30, 1.0), 1.0);
}

TEST(ProjectionColor, ExactMethodIsTheSegmentKernel)
{
  const hov::SegmentColorTable table;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int em = 0; em < 2; ++em)
  {
    const auto emission = static_cast<hov::EmissionModel>(em);
    for (int trial = 0; trial < 200; ++trial)
    {
      const double length = std::pow(10.0, -3.0 + 4.0 * u(rng));
      const hov::SegmentEnd f = End(3.0 * u(rng), u(rng), u(rng), u(rng));
      const hov::SegmentEnd b = End(3.0 * u(rng), u(rng), u(rng), u(rng));
      const hov::RGBA c =
        hov::IntegrateSegment(length, f, b, emission, hov::SegmentMethod::Exact);
      const hov::ProjectionVertexColor v = hov::ComputeProjectionVertex(
        hov::ProjectionColorMethod::ExactColor, emission, length, f, b, table);
      EXPECT_NEAR(v.Alpha, c.A, 1e-14 + 1e-12 * c.A);
      const double got[3] = { v.Color[0], v.Color[1], v.Color[2] };
      const double want[3] = { c.R, c.G, c.B };
      for (int k = 0; k < 3; ++k)
      {
        // Williams-Max: k = C / A, so k A reproduces C; Wilhelms-Van Gelder:
        // the effective glow times L phi(D) = L A / D reproduces C.
        const double depth = 0.5 * (f.Tau + b.Tau) * length;
        const double phi = depth > 1e-8 ? -std::expm1(-depth) / depth : 1.0;
        const double g = em == 0 ? got[k] * c.A : got[k] * length * phi;
        EXPECT_NEAR(g, want[k], 1e-13 + 1e-11 * std::fabs(want[k])) << "trial " << trial;
      }
    }
  }
}

TEST(ProjectionColor, MethodOrderAndLimits)
{
  const hov::SegmentColorTable table;
  // Colour changing from red to blue along the segment, extinction rising.
  const hov::SegmentEnd f = End(0.5, 1.0, 0.0, 0.0), b = End(2.5, 0.0, 0.0, 1.0);
  const double length = 1.2;
  const hov::RGBA exact = hov::IntegrateSegment(
    length, f, b, hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
  double err[4];
  for (int m = 0; m < 4; ++m)
  {
    const auto v = hov::ComputeProjectionVertex(static_cast<hov::ProjectionColorMethod>(m),
      hov::EmissionModel::WilliamsMax, length, f, b, table);
    err[m] = std::fabs(v.Color[0] * exact.A - exact.R) + std::fabs(v.Color[2] * exact.A - exact.B);
    std::cout << "[measured] M" << m << " colour error " << err[m] << "\n";
  }
  EXPECT_EQ(err[0], err[1]); // M0 differs from M1 in the opacity only
  EXPECT_GT(err[1], 10.0 * err[2]);
  EXPECT_LT(err[2], 2e-3);
  EXPECT_LT(err[3], 1e-14);
  // Outside the table's range M2 is M1.
  const hov::SegmentEnd thick = End(20.0, 1.0, 0.0, 0.0);
  const auto m1 = hov::ComputeProjectionVertex(hov::ProjectionColorMethod::AverageColor,
    hov::EmissionModel::WilliamsMax, 1.0, thick, b, table);
  const auto m2 = hov::ComputeProjectionVertex(hov::ProjectionColorMethod::TableColor,
    hov::EmissionModel::WilliamsMax, 1.0, thick, b, table);
  EXPECT_EQ(m1.Color[0], m2.Color[0]);
  EXPECT_EQ(m1.Color[2], m2.Color[2]);
  // Zero length (silhouette vertices): no opacity, the average colour, no NaN.
  for (int m = 0; m < 4; ++m)
  {
    const auto v = hov::ComputeProjectionVertex(static_cast<hov::ProjectionColorMethod>(m),
      hov::EmissionModel::WilliamsMax, 0.0, f, b, table);
    EXPECT_EQ(v.Alpha, 0.0);
    EXPECT_DOUBLE_EQ(v.Color[0], 0.5);
    EXPECT_DOUBLE_EQ(v.Color[2], 0.5);
  }
  // Wilhelms-Van Gelder, constant glow and extinction: every method gives
  // the glow itself (the fragment's L phi(D) makes the exact radiance).
  const hov::SegmentEnd g = End(0.7, 0.3, 0.6, 0.9);
  const hov::SegmentEnd clear = End(0.0, 0.3, 0.6, 0.9);
  for (int m = 0; m < 4; ++m)
  {
    for (const hov::SegmentEnd& e : { g, clear })
    {
      const auto w = hov::ComputeProjectionVertex(static_cast<hov::ProjectionColorMethod>(m),
        hov::EmissionModel::WilhelmsVanGelder, 2.0, e, e, table);
      EXPECT_NEAR(w.Color[1], 0.6, 1e-3 * (m == 2) + 1e-13) << "M" << m << " tau " << e.Tau;
    }
  }
}

// GPU-compatible average extinction over a segment on which the opacity is
// linear (the projection's per-fragment formula, in double) against an
// independent reference: Boost.Math's tanh-sinh quadrature of -ln(1 - a(t))
// over the segment parameter t in [0, 1], in long double (it handles the log
// singularity where a reaches 1), over
// opacities from 1e-9 to 1 - 1e-9 and segment ranges from 1e-9 to the whole
// [0, 1); plus the limits (equal ends, an opaque end, both ends opaque).
TEST(ProjectionColor, GPUAverageExtinctionMatchesQuadrature)
{
  using LD = long double;
  boost::math::quadrature::tanh_sinh<LD> integrator;
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  double worst = 0.0;
  int cases = 0;
  for (int k = 0; k < 3000; ++k)
  {
    // Opacity a = 1 - 10^(-e) spread over 9 decades on both sides of 0.5.
    const auto draw = [&] {
      const double e = -9.0 * u01(rng);
      return u01(rng) < 0.5 ? std::pow(10.0, e) : 1.0 - std::pow(10.0, e);
    };
    const double a0 = draw();
    const double a1 = k % 3 == 0 ? a0 + (1.0 - a0) * std::pow(10.0, -9.0 * u01(rng)) * u01(rng)
                                 : draw();
    // In p = 1 - a (exact for a >= 0.5, Sterbenz), where the integrand keeps
    // its relative precision near a = 1.
    const LD lo = std::min(a0, a1), hi = std::max(a0, a1);
    const LD pBig = 1.0L - lo, pSmall = 1.0L - hi;
    LD reference;
    if (pBig - pSmall < 1e-300L)
    {
      reference = -std::log1p(-lo);
    }
    else
    {
      // The mean as an integral over the segment's parameter t in [0, 1].
      const LD width = pBig - pSmall;
      const auto f = [&](LD t) { return -std::log(pBig - width * t); };
      reference = integrator.integrate(f, 0.0L, 1.0L);
    }
    const double value = hov::GPUAverageExtinction(a0, a1);
    const double rel = std::abs(value - static_cast<double>(reference)) / static_cast<double>(reference);
    worst = std::max(worst, rel);
    ++cases;
    ASSERT_LT(rel, 1e-9) << "a0 " << a0 << " a1 " << a1 << " value " << value << " reference "
                         << static_cast<double>(reference);
  }
  std::cout << "[measured] GPUAverageExtinction: " << cases
            << " cases, max relative error vs tanh-sinh " << worst << std::endl;
  EXPECT_DOUBLE_EQ(hov::GPUAverageExtinction(0.3, 0.3), -std::log(0.7));
  EXPECT_DOUBLE_EQ(hov::GPUAverageExtinction(0.0, 0.0), 0.0);
  // Symmetric in its ends; a = 1 at one end: the mean of -ln(p), p from P to 0, is 1 - ln P.
  EXPECT_DOUBLE_EQ(hov::GPUAverageExtinction(0.2, 0.7), hov::GPUAverageExtinction(0.7, 0.2));
  EXPECT_NEAR(hov::GPUAverageExtinction(0.5, 1.0), 1.0 - std::log(0.5), 1e-10);
  EXPECT_TRUE(std::isinf(hov::GPUAverageExtinction(1.0, 1.0)));
}
