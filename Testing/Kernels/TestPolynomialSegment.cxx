// Tests of hovPolynomialSegment against the independent long double reference
// of hovPolynomialTestSupport.h (breakpoints by grid + bisection, raw
// integrand by adaptive Gauss-Kronrod 61 with nested Gauss-Legendre optical
// depth): quadratics with interior extrema crossing several breakpoints,
// higher degrees, all opacity semantics and both emission models, and the
// error estimate against the true error on 1000 random segments.

#include "hovPolynomialSegment.h"

#include "hovRayIntegrator.h"
#include "hovTransferFunction.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestUtilities.h"
#include "hovPolynomialTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using hovtest::Str;
using hovtest::Worst;

namespace
{
/// Kernel vs reference: 1e-9 relative to the colour scale (the issue asks
/// 1e-7 per pixel; the kernel's default tolerance is 1e-9 absolute).
constexpr double SegmentRelTol = 1e-9;

hov::TransferFunctionSpec RandomSpec(std::mt19937_64& rng, hov::OpacitySemantics semantics, int nodes)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = semantics;
  spec.UnitDistance = hovtest::LogUniform(rng, 0.2, 5.0);
  spec.EmissionScale = hovtest::LogUniform(rng, 0.5, 2.0);
  spec.GPUTolerance = 1e-6;
  auto positions = [&](int n) {
    std::vector<double> x;
    for (int i = 0; i < n; ++i)
    {
      x.push_back(hovtest::Uniform(rng, 0, 1));
    }
    std::sort(x.begin(), x.end());
    return x;
  };
  for (double x : positions(nodes))
  {
    spec.Color.push_back(
      { x, hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1) });
  }
  for (double x : positions(nodes))
  {
    spec.Opacity.push_back({ x, hovtest::Uniform(rng, 0, 0.95) });
  }
  return spec;
}

/// s(t) = peak - curv (t - tm)^2 scaled so that s spans about [0, 1.1] on [0, L]
/// with its maximum inside: every node in the range is crossed twice.
hov::Polynomial QuadraticWithPeak(std::mt19937_64& rng, double length)
{
  const double tm = length * hovtest::Uniform(rng, 0.2, 0.8);
  const double peak = hovtest::Uniform(rng, 0.7, 1.1);
  const double low = hovtest::Uniform(rng, -0.1, 0.3);
  const double curv = (peak - low) / std::pow(std::max(tm, length - tm), 2);
  const double sign = rng() % 2 ? 1.0 : -1.0; // maximum or (mirrored) minimum
  const double off = sign > 0 ? 0.0 : 1.0;
  return hov::Polynomial::FromCoefficients(
    { off + sign * (peak - curv * tm * tm), sign * 2 * curv * tm, -sign * curv });
}

/// Random polynomial of the given degree with values roughly in [-0.2, 1.2] on [0, L].
hov::Polynomial RandomField(std::mt19937_64& rng, int degree, double length)
{
  if (degree == 2)
  {
    return QuadraticWithPeak(rng, length);
  }
  // Product of (x - r_i) in x = t/L with roots in [-0.3, 1.3], scaled.
  std::vector<double> c{ 1.0 };
  for (int i = 0; i < degree; ++i)
  {
    const double r = hovtest::Uniform(rng, -0.3, 1.3);
    std::vector<double> n(c.size() + 1, 0.0);
    for (size_t j = 0; j < c.size(); ++j)
    {
      n[j + 1] += c[j];
      n[j] -= r * c[j];
    }
    c = n;
  }
  double m = 0.0;
  for (int i = 0; i <= 64; ++i)
  {
    double v = 0.0;
    for (int j = degree; j >= 0; --j)
    {
      v = v * (i / 64.0) + c[j];
    }
    m = std::max(m, std::fabs(v));
  }
  hov::Polynomial p;
  p.Degree = degree;
  const double scale = hovtest::Uniform(rng, 0.6, 1.2) / m;
  for (int j = 0; j <= degree; ++j)
  {
    p.C[j] = c[j] * scale / std::pow(length, j);
  }
  p.C[0] += 0.5;
  return p;
}

double ColorScale(const hov::TransferFunctionSpec& spec, double length, hov::EmissionModel m)
{
  return m == hov::EmissionModel::WilliamsMax ? 1.0
                                              : std::max(1.0, length * spec.EmissionScale / spec.UnitDistance);
}

hov::PolynomialSegmentResult IntegrateWith(const hov::TransferFunctionSpec& spec, const hov::Polynomial& s,
  double length, hov::EmissionModel model, double tol = 1e-9)
{
  hov::TransferFunction tf;
  EXPECT_TRUE(tf.Build(spec));
  hov::PolynomialSegmentSettings settings;
  settings.Emission = model;
  settings.Tolerance = tol;
  return hov::IntegratePolynomialScalar(tf, s, length, settings);
}

std::string Describe(const hov::TransferFunctionSpec& spec, const hov::Polynomial& s, double length)
{
  std::string d = hovtest::ToString(spec) + " L=" + Str(length) + " s={";
  for (int i = 0; i <= s.Degree; ++i)
  {
    d += " " + Str(s.C[i]);
  }
  return d + " }";
}

/// Max over channels of the colour error (divided by @p scale) and the opacity error.
double Compare(const hov::PolynomialSegmentResult& r, const hovtest::RefRGBA& ref, double scale)
{
  return hovtest::MaxAbsDiff(r.Color, ref, scale);
}
}

TEST(PolynomialSegment, QuadraticWithExtremumMatchesReference)
{
  std::mt19937_64 rng(7);
  Worst worst[2];
  int totalPieces = 0, maxPanels = 0;
  for (int trial = 0; trial < 60; ++trial)
  {
    const auto sem = trial % 2 ? hov::OpacitySemantics::RawExtinction : hov::OpacitySemantics::VTKUnstructured;
    const hov::TransferFunctionSpec spec = RandomSpec(rng, sem, 3 + trial % 5);
    const double length = hovtest::LogUniform(rng, 0.1, 10.0);
    const hov::Polynomial s = QuadraticWithPeak(rng, length);
    for (int m = 0; m < 2; ++m)
    {
      const auto model = m ? hov::EmissionModel::WilhelmsVanGelder : hov::EmissionModel::WilliamsMax;
      const hov::PolynomialSegmentResult r = IntegrateWith(spec, s, length, model);
      const hovtest::RefRGBA ref =
        hovtest::ReferencePolynomialRay(hovtest::ToReference(spec), s, length, hovtest::ToReference(model));
      const double err = Compare(r, ref, ColorScale(spec, length, model));
      worst[m].Add(err, Describe(spec, s, length));
      EXPECT_LE(err, SegmentRelTol) << Describe(spec, s, length) << " got " << hovtest::ToString(r.Color)
                                    << " ref " << hovtest::ToString(ref);
      EXPECT_TRUE(r.Converged);
      EXPECT_LE(r.ErrorEstimate, 1e-9 * (1 + 1e-12));
      totalPieces += r.Pieces;
      maxPanels = std::max(maxPanels, r.Panels);
    }
  }
  hovtest::ReportMeasured("PolynomialSegment.QuadraticWM", worst[0]);
  hovtest::ReportMeasured("PolynomialSegment.QuadraticWVG", worst[1]);
  hovtest::ReportMeasured("PolynomialSegment.QuadraticMeanPieces", totalPieces / 120.0);
  hovtest::ReportMeasured("PolynomialSegment.QuadraticMaxPanels", maxPanels);
  EXPECT_GT(totalPieces, 120 * 4); // the cases do cross several breakpoints
}

TEST(PolynomialSegment, HigherDegreesAndAllSemanticsMatchReference)
{
  std::mt19937_64 rng(99);
  Worst worst;
  Worst gpu;
  for (int trial = 0; trial < 48; ++trial)
  {
    const auto sem = static_cast<hov::OpacitySemantics>(trial % 3);
    const int degree = 2 + (trial / 3) % 7; // 2..8
    const hov::TransferFunctionSpec spec = RandomSpec(rng, sem, 2 + trial % 4);
    const double length = hovtest::LogUniform(rng, 0.1, 10.0);
    const hov::Polynomial s = RandomField(rng, degree, length);
    for (int m = 0; m < 2; ++m)
    {
      const auto model = m ? hov::EmissionModel::WilhelmsVanGelder : hov::EmissionModel::WilliamsMax;
      const hov::PolynomialSegmentResult r = IntegrateWith(spec, s, length, model);
      const hovtest::RefRGBA ref =
        hovtest::ReferencePolynomialRay(hovtest::ToReference(spec), s, length, hovtest::ToReference(model));
      const double scale = ColorScale(spec, length, model);
      const double err = Compare(r, ref, scale);
      // GPU-compatible semantics linearise -ln(1-a): image bound 2 GPUTolerance
      // (colour, WM) per unit of colour scale; see hovTransferFunction.h.
      const bool isGpu = sem == hov::OpacitySemantics::GPUCompatible;
      const double tol = isGpu ? 2 * spec.GPUTolerance * (m ? std::max(1.0, length / spec.UnitDistance) : 1.0)
                               : SegmentRelTol;
      (isGpu ? gpu : worst).Add(err, Describe(spec, s, length));
      EXPECT_LE(err, tol) << "degree " << degree << " model " << m << " " << Describe(spec, s, length)
                          << " got " << hovtest::ToString(r.Color) << " ref " << hovtest::ToString(ref);
      EXPECT_TRUE(hovtest::AllFinite(r.Color));
    }
  }
  hovtest::ReportMeasured("PolynomialSegment.Degree2to8", worst);
  hovtest::ReportMeasured("PolynomialSegment.GPUSemantics(bound 2e-6)", gpu);
}

TEST(PolynomialSegment, ErrorEstimateBoundsTrueError)
{
  // 1000 random segments at loose tolerances, so that the quadrature error is
  // far above the reference's (~1e-18) and the kernel's rounding (~1e-16).
  std::mt19937_64 rng(1234);
  Worst ratio, estimateOverTol;
  int violations = 0;
  double below = 0.0, count = 0.0;
  for (int trial = 0; trial < 1000; ++trial)
  {
    const auto sem = trial % 2 ? hov::OpacitySemantics::RawExtinction : hov::OpacitySemantics::VTKUnstructured;
    hov::TransferFunctionSpec spec = RandomSpec(rng, sem, 2 + trial % 2);
    // Larger extinction so that e^-D varies strongly inside pieces.
    for (auto& n : spec.Opacity)
    {
      n.Opacity *= sem == hov::OpacitySemantics::RawExtinction ? 50.0 : 1.0;
    }
    const double length = hovtest::LogUniform(rng, 1.0, 50.0);
    const hov::Polynomial s = RandomField(rng, 2 + trial % 7, length);
    const auto model = trial % 4 < 2 ? hov::EmissionModel::WilliamsMax : hov::EmissionModel::WilhelmsVanGelder;
    const double tol = std::pow(10.0, -2.0 - (trial % 5));
    const hov::PolynomialSegmentResult r = IntegrateWith(spec, s, length, model, tol);
    const hovtest::RefRGBA ref =
      hovtest::ReferencePolynomialRay(hovtest::ToReference(spec), s, length, hovtest::ToReference(model));
    const double actual = std::max({ std::fabs(r.Color.R - static_cast<double>(ref.R)),
      std::fabs(r.Color.G - static_cast<double>(ref.G)), std::fabs(r.Color.B - static_cast<double>(ref.B)) });
    // Stated factor: actual <= 1 x estimate, plus a rounding floor of 1e-14
    // (colour scale up to ~40 for WVG).
    const double floor = 1e-14 * ColorScale(spec, length, model);
    if (actual > r.ErrorEstimate + floor)
    {
      ++violations;
      ADD_FAILURE() << "actual " << actual << " > estimate " << r.ErrorEstimate << " " << Describe(spec, s, length);
    }
    if (r.ErrorEstimate > 10 * floor)
    {
      ratio.Add(actual / r.ErrorEstimate, Describe(spec, s, length));
      below += actual / r.ErrorEstimate < 1e-3;
      count += 1;
    }
    estimateOverTol.Add(r.ErrorEstimate / tol, Describe(spec, s, length));
    EXPECT_TRUE(r.Converged);
  }
  hovtest::ReportMeasured("PolynomialSegment.MaxActualOverEstimate", ratio);
  hovtest::ReportMeasured("PolynomialSegment.FractionActualBelow1e-3Estimate", count > 0 ? below / count : 0.0);
  hovtest::ReportMeasured("PolynomialSegment.MaxEstimateOverTolerance", estimateOverTol);
  EXPECT_EQ(violations, 0);
  EXPECT_LE(estimateOverTol.Value, 1.0 + 1e-12);
  // The estimate is exercised: with this seed 65 segments have an estimate
  // above 10x the floor (the kernel is usually far below every tolerance).
  EXPECT_GT(count, 50);
}

TEST(PolynomialSegment, DegreeOneEqualsLinearPath)
{
  std::mt19937_64 rng(5);
  Worst w, nearLinear;
  for (int trial = 0; trial < 200; ++trial)
  {
    const auto sem = static_cast<hov::OpacitySemantics>(trial % 3);
    const hov::TransferFunctionSpec spec = RandomSpec(rng, sem, 2 + trial % 6);
    hov::TransferFunction tf;
    ASSERT_TRUE(tf.Build(spec));
    const double length = hovtest::LogUniform(rng, 0.01, 10.0);
    const double s0 = hovtest::Uniform(rng, -0.2, 1.2), s1 = hovtest::Uniform(rng, -0.2, 1.2);
    const auto model = trial % 2 ? hov::EmissionModel::WilhelmsVanGelder : hov::EmissionModel::WilliamsMax;
    hov::IntegrationSettings lin;
    lin.Emission = model;
    const hov::RGBA ref = hov::IntegrateLinearScalar(tf, s0, s1, length, lin);
    hov::PolynomialSegmentSettings settings;
    settings.Emission = model;
    // Degree 1 (also stored with zero higher coefficients).
    hov::Polynomial p = hov::Polynomial::FromCoefficients({ s0, (s1 - s0) / length, 0.0, 0.0 });
    const hov::PolynomialSegmentResult r = hov::IntegratePolynomialScalar(tf, p, length, settings);
    w.Add(hovtest::MaxAbsDiff(r.Color, ref), Describe(spec, p, length));
    EXPECT_LE(hovtest::MaxAbsDiff(r.Color, ref), 1e-14) << Describe(spec, p, length);
    EXPECT_EQ(r.Panels, 0);
    // A quadratic with a 1e-13 relative curvature goes through the quadrature
    // path and must agree to the tolerance (continuity across the degree switch).
    p.C[2] = 1e-13 * (s1 - s0) / (length * length);
    p.Degree = 2;
    const hov::PolynomialSegmentResult q = hov::IntegratePolynomialScalar(tf, p, length, settings);
    const double scale = ColorScale(spec, length, model);
    nearLinear.Add(hovtest::MaxAbsDiff(q.Color, ref) / scale, Describe(spec, p, length));
    EXPECT_LE(hovtest::MaxAbsDiff(q.Color, ref) / scale, 2e-9) << Describe(spec, p, length);
  }
  hovtest::ReportMeasured("PolynomialSegment.DegreeOneVsLinear", w);
  hovtest::ReportMeasured("PolynomialSegment.NearlyLinearQuadraticVsLinear", nearLinear);
}
