// Tests of hovSplat: the quadratic B-spline weights against the independent
// definition B = box * triangle (partition of unity, symmetry, moments,
// continuity), the splat of a uniform sub-pixel cube against the exact
// optical depth of the same cube integrated over the image plane
// (orthographic: exactly the same total, per pixel O(s^2) with observed
// order; perspective: ray-by-ray chord lengths, O((a/z)^2)), the emission
// models' limits, and a no-NaN sweep.

#include "hovSplat.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestUtilities.h"

#include <boost/math/quadrature/gauss.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using hovtest::Str;
using hovtest::Worst;

namespace
{
constexpr double Eps = 2.220446049250313e-16;

/// B(d) = int_{d-1/2}^{d+1/2} tri(u) du, tri(u) = max(0, 1 - |u|): the box
/// convolved with the triangle (= box * box), by Gauss-Legendre on the
/// linear pieces of tri (exact).
double ReferenceB(double d)
{
  using G = boost::math::quadrature::gauss<double, 4>;
  const double knots[3] = { -1.0, 0.0, 1.0 };
  double a = d - 0.5, b = d + 0.5, sum = 0.0;
  double lo = a;
  for (int k = 0; k <= 3; ++k)
  {
    const double hi = k < 3 ? std::min(std::max(knots[k], a), b) : b;
    if (hi > lo)
    {
      sum += G::integrate([](double u) { return std::max(0.0, 1.0 - std::fabs(u)); }, lo, hi);
    }
    lo = std::max(lo, hi);
  }
  return sum;
}

/// int_{x0}^{x1} B(u - i) du with B from its piecewise quadratic formula,
/// by Gauss-Legendre on the pieces between B's knots (exact).
double IntegralB(double x0, double x1, int i)
{
  using G = boost::math::quadrature::gauss<double, 3>;
  auto b = [](double d) {
    d = std::fabs(d);
    return d <= 0.5 ? 0.75 - d * d : (d <= 1.5 ? 0.5 * (d - 1.5) * (d - 1.5) : 0.0);
  };
  const double knots[4] = { i - 1.5, i - 0.5, i + 0.5, i + 1.5 };
  double lo = x0, sum = 0.0;
  for (int k = 0; k <= 4; ++k)
  {
    const double hi = k < 4 ? std::min(std::max(knots[k], x0), x1) : x1;
    if (hi > lo)
    {
      sum += G::integrate([&](double u) { return b(u - i); }, lo, hi);
    }
    lo = std::max(lo, hi);
  }
  return sum;
}

/// Chord length of the ray t (dx, dy, 1), t > 0, through the box |x - c| <= h.
double Chord(double dx, double dy, const double c[3], double h)
{
  const double d[3] = { dx, dy, 1.0 };
  double t0 = 0.0, t1 = INFINITY;
  for (int k = 0; k < 3; ++k)
  {
    if (d[k] == 0.0)
    {
      if (std::fabs(c[k]) > h)
      {
        return 0.0;
      }
      continue;
    }
    double a = (c[k] - h) / d[k], b = (c[k] + h) / d[k];
    if (a > b)
    {
      std::swap(a, b);
    }
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t1 > t0 ? (t1 - t0) * std::sqrt(dx * dx + dy * dy + 1.0) : 0.0;
}
}

TEST(Splat, BSplineWeightsPartitionOfUnityAndReference)
{
  std::mt19937_64 rng(1);
  Worst sum, ref, moment1, moment2;
  for (int trial = 0; trial < 100000; ++trial)
  {
    const double x = trial % 10 == 0 ? hovtest::Uniform(rng, -1e6, 1e6) : hovtest::Uniform(rng, -3, 3);
    double w[3];
    const int c = hov::QuadraticBSplineWeights(x, w);
    ASSERT_LE(std::fabs(x - c), 0.5);
    sum.Add(std::fabs((w[0] + w[1] + w[2]) - 1.0), "x=" + Str(x));
    double m1 = 0.0, m2 = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      ASSERT_GE(w[i], 0.0);
      const double d = (c - 1 + i) - x;
      m1 += w[i] * d;
      m2 += w[i] * d * d;
      if (trial < 2000 && std::fabs(x) < 10)
      {
        ref.Add(std::fabs(w[i] - ReferenceB(d)), "x=" + Str(x));
      }
    }
    moment1.Add(std::fabs(m1), "x=" + Str(x));
    if (std::fabs(x) < 10)
    {
      moment2.Add(std::fabs(m2 - 0.25), "x=" + Str(x));
    }
  }
  hovtest::ReportMeasured("Splat.WeightSumMinusOne", sum);
  hovtest::ReportMeasured("Splat.WeightsVsBoxTriangle", ref);
  hovtest::ReportMeasured("Splat.FirstMoment", moment1);
  hovtest::ReportMeasured("Splat.SecondMomentMinusQuarter", moment2);
  EXPECT_LE(sum.Value, 2 * Eps);
  EXPECT_LE(ref.Value, 1e-15);
  EXPECT_LE(moment1.Value, 1e-10); // |x| up to 1e6: the offsets carry rounding of x - c
  EXPECT_LE(moment2.Value, 1e-15);
  // Centred: (1/8, 3/4, 1/8) exactly; symmetric; continuous across x = k + 1/2.
  double w[3], v[3];
  EXPECT_EQ(hov::QuadraticBSplineWeights(4.0, w), 4);
  EXPECT_EQ(w[0], 0.125);
  EXPECT_EQ(w[1], 0.75);
  EXPECT_EQ(w[2], 0.125);
  for (double f : { 0.1, 0.25, 0.4999 })
  {
    hov::QuadraticBSplineWeights(7.0 + f, w);
    hov::QuadraticBSplineWeights(7.0 - f, v);
    EXPECT_NEAR(w[0], v[2], 1e-16);
    EXPECT_NEAR(w[1], v[1], 1e-16);
  }
  for (double k : { -3.0, 0.0, 5.0 })
  {
    const double below = std::nextafter(k + 0.5, -INFINITY);
    const int cb = hov::QuadraticBSplineWeights(below, w);
    const int ca = hov::QuadraticBSplineWeights(k + 0.5, v);
    // Pixel c gets w[1] from below, v[0] from above (ca = cb + 1).
    EXPECT_EQ(ca, cb + 1);
    EXPECT_NEAR(w[1], v[0], 1e-15);
    EXPECT_NEAR(w[2], v[1], 1e-15);
    EXPECT_NEAR(w[0], 0.0, 1e-15);
    EXPECT_EQ(v[2], 0.0);
  }
  // 2D: products, sum 1.
  const hov::SplatWeights s = hov::BiquadraticSplatWeights(10.3, -2.7);
  EXPECT_EQ(s.X0, 9);
  EXPECT_EQ(s.Y0, -4);
  double total = 0.0;
  for (const auto& row : s.W)
  {
    for (double x : row)
    {
      total += x;
    }
  }
  EXPECT_NEAR(total, 1.0, 4 * Eps);
}

/// Orthographic projection, unit pixels, a cube of side s pixels seen along
/// an axis: the exact optical depth is tau s on the square footprint. Total
/// depth: exact. Per pixel: the kernel filtered over the footprint vs the
/// kernel at the centre: O(s^2).
TEST(Splat, OrthographicCubeAgainstExactFootprint)
{
  const double tau = 0.05;
  Worst total;
  double errPrev = 0.0;
  for (double side : { 0.4, 0.2, 0.1, 0.05 })
  {
    double worstPixel = 0.0;
    for (int trial = 0; trial < 20; ++trial)
    {
      const double cx = 3.0 + 0.05 * trial, cy = -1.0 + 0.037 * trial;
      hov::SplatCell cell;
      cell.Volume = side * side * side;
      cell.Tau = tau;
      cell.Color[0] = 1.0;
      const hov::SplatFootprint f =
        hov::SplatCellContribution(cell, hov::OrthographicPixelArea(1.0, 1.0), cx, cy, hov::EmissionModel::WilhelmsVanGelder);
      const double m = cell.Volume * tau;
      double sum = 0.0;
      for (int j = 0; j < 3; ++j)
      {
        for (int i = 0; i < 3; ++i)
        {
          const double d = -std::log1p(-f.Pixel[j][i].A); // the pixel's optical depth
          sum += d;
          const double exact = tau * side * IntegralB(cx - side / 2, cx + side / 2, f.X0 + i) *
            IntegralB(cy - side / 2, cy + side / 2, f.Y0 + j);
          worstPixel = std::max(worstPixel, std::fabs(d - exact) / m);
        }
      }
      total.Add(std::fabs(sum - m) / m, "side=" + Str(side));
    }
    hovtest::ReportMeasured("Splat.OrthoPixelError.side" + Str(side), worstPixel);
    if (errPrev > 0.0)
    {
      const double order = std::log2(errPrev / worstPixel);
      hovtest::ReportMeasured("Splat.OrthoPixelOrder.side" + Str(side), order);
      EXPECT_NEAR(order, 2.0, 0.1) << side;
    }
    errPrev = worstPixel;
  }
  hovtest::ReportMeasured("Splat.OrthoTotalDepthRel", total);
  EXPECT_LE(total.Value, 1e-12); // log1p of the opacity: a few ulp relative to D
}

/// Perspective: rays from the origin through (u w1, v w1, 1); a cube of side
/// a at (X, Y, Z). The integral over the image plane (pixel units) of the
/// ray-by-ray optical depth tau * chord vs the splat's V tau / PerspectivePixelArea.
TEST(Splat, PerspectiveDepthIntegral)
{
  const double w1 = 0.002, tau = 1.0;
  double prev = 0.0;
  for (double rel : { 0.2, 0.1, 0.05 })
  {
    const double c[3] = { 0.6, -0.3, 2.0 };
    const double a = rel * c[2], h = a / 2;
    // Bounding rectangle of the projection (corners of the cube), in pixels.
    double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
    for (int k = 0; k < 8; ++k)
    {
      const double x = c[0] + (k & 1 ? h : -h), y = c[1] + (k & 2 ? h : -h), z = c[2] + (k & 4 ? h : -h);
      u0 = std::min(u0, x / z / w1);
      u1 = std::max(u1, x / z / w1);
      v0 = std::min(v0, y / z / w1);
      v1 = std::max(v1, y / z / w1);
    }
    // Composite midpoint rule, 1200 x 1200 (the integrand has kinks along the
    // projected edges: error ~1e-6 relative).
    const int n = 1200;
    const double du = (u1 - u0) / n, dv = (v1 - v0) / n;
    long double integral = 0.0L;
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double u = u0 + (i + 0.5) * du, v = v0 + (j + 0.5) * dv;
        integral += tau * Chord(u * w1, v * w1, c, h);
      }
    }
    integral *= du * dv;
    const double r = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    const double area = hov::PerspectivePixelArea(c[2], w1, w1, c[2] / r);
    const double splat = a * a * a * tau / area;
    const double err = std::fabs(splat - static_cast<double>(integral)) / static_cast<double>(integral);
    hovtest::ReportMeasured("Splat.PerspectiveDepthRel.a/z=" + Str(rel), err);
    EXPECT_LE(err, 0.5 * rel * rel) << rel; // O((a/z)^2): a^2/(2 z^2) in theory, 0.35 measured
    if (prev > 0.0)
    {
      hovtest::ReportMeasured("Splat.PerspectiveOrder.a/z=" + Str(rel), std::log2(prev / err));
      EXPECT_GT(std::log2(prev / err), 1.7);
    }
    prev = err;
  }
}

TEST(Splat, EmissionModelsAndLimits)
{
  hov::SplatCell cell;
  cell.Volume = 0.5;
  cell.Color[0] = 0.8;
  cell.Color[1] = 0.4;
  cell.Color[2] = 0.2;
  // No extinction: WVG deposits g w V / a, WM nothing.
  cell.Tau = 0.0;
  const hov::SplatWeights w = hov::BiquadraticSplatWeights(0.2, 0.1);
  const hov::SplatFootprint e = hov::SplatCellContribution(cell, 2.0, 0.2, 0.1, hov::EmissionModel::WilhelmsVanGelder);
  const hov::SplatFootprint z = hov::SplatCellContribution(cell, 2.0, 0.2, 0.1, hov::EmissionModel::WilliamsMax);
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_NEAR(e.Pixel[j][i].R, 0.8 * w.W[j][i] * 0.25, 1e-17);
      EXPECT_EQ(e.Pixel[j][i].A, 0.0);
      EXPECT_EQ(z.Pixel[j][i].R, 0.0);
    }
  }
  // Williams-Max: colour = c A; A = 1 - exp(-w V tau / a).
  cell.Tau = 3.0;
  const hov::SplatFootprint m = hov::SplatCellContribution(cell, 2.0, 0.2, 0.1, hov::EmissionModel::WilliamsMax);
  const hov::SplatFootprint g = hov::SplatCellContribution(cell, 2.0, 0.2, 0.1, hov::EmissionModel::WilhelmsVanGelder);
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      const double d = w.W[j][i] * 0.25 * 3.0;
      EXPECT_NEAR(m.Pixel[j][i].A, 1 - std::exp(-d), 1e-16);
      EXPECT_NEAR(m.Pixel[j][i].G, 0.4 * (1 - std::exp(-d)), 1e-16);
      // WVG: a uniform slab of depth d and length d / tau: g (1 - e^-d) / tau.
      EXPECT_NEAR(g.Pixel[j][i].B, 0.2 * (1 - std::exp(-d)) / 3.0, 1e-16);
    }
  }
  // Opaque cell: WM gives the colour with A = 1 where the weight is non-zero.
  cell.Tau = INFINITY;
  const hov::SplatFootprint o = hov::SplatCellContribution(cell, 2.0, 0.0, 0.0, hov::EmissionModel::WilliamsMax);
  EXPECT_EQ(o.Pixel[1][1].A, 1.0);
  EXPECT_EQ(o.Pixel[1][1].R, 0.8);
  const hov::SplatFootprint og = hov::SplatCellContribution(cell, 2.0, 0.0, 0.0, hov::EmissionModel::WilhelmsVanGelder);
  EXPECT_EQ(og.Pixel[1][1].R, 0.0);
}

TEST(Splat, SweepHasNoNaN)
{
  std::mt19937_64 rng(9);
  auto odd = [&](double lo, double hi) {
    const int k = static_cast<int>(rng() % 8);
    return k == 0 ? 0.0 : k == 1 ? NAN : k == 2 ? INFINITY : k == 3 ? -1.0 : hovtest::LogUniform(rng, lo, hi);
  };
  for (int trial = 0; trial < 20000; ++trial)
  {
    hov::SplatCell cell;
    cell.Volume = odd(1e-300, 1e300);
    cell.Tau = odd(1e-300, 1e300);
    cell.Color[0] = hovtest::Uniform(rng, 0, 1);
    const double area = odd(1e-300, 1e300), x = odd(1e-3, 1e9), y = hovtest::Uniform(rng, -10, 10);
    for (int m = 0; m < 2; ++m)
    {
      const hov::SplatFootprint f = hov::SplatCellContribution(cell, area, x, y, static_cast<hov::EmissionModel>(m));
      for (const auto& row : f.Pixel)
      {
        for (const hov::RGBA& p : row)
        {
          ASSERT_TRUE(hovtest::AllFinite(p)) << cell.Volume << " " << cell.Tau << " " << area << " " << x;
          ASSERT_GE(p.A, 0.0);
          ASSERT_LE(p.A, 1.0);
        }
      }
    }
  }
}
