// Tests of hovSegmentIntegral: ExactSegmentWeights and IntegrateSegment.
//
// References: closed forms (constant extinction, zero extinction), limits,
// symmetries, and an independent 50-digit quadrature of the defining integrals
// (hovKernelTestReference.h). Tolerances: hovKernelTestTolerances.h.

#include "hovSegmentIntegral.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using hovtest::Mp;
using hovtest::Str;
using hovtest::Tolerances;
using hovtest::Worst;

namespace
{
constexpr double Inf = std::numeric_limits<double>::infinity();
constexpr double Denorm = std::numeric_limits<double>::denorm_min();

hov::SegmentEnd End(double tau, double r, double g, double b)
{
  hov::SegmentEnd e;
  e.Tau = tau;
  e.Color[0] = r;
  e.Color[1] = g;
  e.Color[2] = b;
  return e;
}

std::string Pair(double a, double c)
{
  return "a=" + Str(a) + " c=" + Str(c);
}

// Branch thresholds of hovSegmentIntegral.cxx (duplicated on purpose: if the
// kernel moves a threshold, the continuity tests still probe the old place and
// the reference tests still cover the new one through the grid).
constexpr double ThinDepth = 0.125;
constexpr double SmallSlope = 1.0 / 16.0;
constexpr double MomentUpwardFrom = 40.0;
constexpr double ZeroSlopeRelative = 1e-15;

/// Depth rates of the reference grid: 0, tiny, every decade that matters, and
/// both sides of the thresholds that depend on one rate alone.
const std::vector<double>& GridValues()
{
  static const std::vector<double> v = { 0.0, 1e-300, 1e-200, 1e-100, 1e-30, 1e-16, 1e-12, 1e-8,
    1e-4, 1e-2, 0.1, 0.124, 0.125, 0.126, 0.2, 0.2499, 0.25, 0.2501, 0.3, 0.5, 1.0, 2.0, 3.7, 5.0,
    10.0, 20.0, 39.0, 39.99, 40.0, 40.01, 41.0, 80.0, 100.0, 1e3, 1e4, 1e6, 1e12, 1e100, 1e300 };
  return v;
}

/// Pairs straddling each threshold that depends on both rates.
std::vector<std::pair<double, double>> ThresholdPairs()
{
  std::vector<std::pair<double, double>> p;
  // Total depth (a + c)/2 around ThinDepth, for several front/back ratios.
  for (double t : { ThinDepth * (1 - 1e-3), ThinDepth, std::nextafter(ThinDepth, 1.0),
         ThinDepth * (1 + 1e-3) })
  {
    for (double f : { 0.0, 0.1, 0.3, 0.5, 0.9, 1.0 })
    {
      p.emplace_back(2 * t * f, 2 * t * (1 - f));
    }
  }
  // |c - a|/2 around SmallSlope, both signs, at several depths (thin ones excluded
  // automatically by the kernel).
  for (double a : { 0.1, 0.2, 1.0, 3.0, 10.0, 39.9, 40.1, 100.0 })
  {
    for (double db : { SmallSlope * (1 - 1e-3), SmallSlope, SmallSlope * (1 + 1e-3) })
    {
      p.emplace_back(a, a + 2 * db);
      if (a - 2 * db >= 0)
      {
        p.emplace_back(a, a - 2 * db);
      }
    }
  }
  // MomentUpwardFrom on a with a small slope.
  for (double a : { 40.0 - 1e-9, 40.0, 40.0 + 1e-9 })
  {
    for (double dc : { -0.1, -0.05, -1e-6, 0.0, 1e-6, 0.05, 0.1 })
    {
      p.emplace_back(a, a + dc);
    }
  }
  // b around ZeroSlopeRelative * D(1) and through b = 0.
  for (double a : { 0.2, 1.0, 7.0, 50.0, 1e4 })
  {
    for (double rel : { -1e-9, -4e-15, -2.1e-15, -1.9e-15, 1.9e-15, 2.1e-15, 4e-15, 1e-9 })
    {
      p.emplace_back(a, a * (1 + rel));
    }
  }
  // Large depth with a comparatively small slope (closed-form K1 cancels).
  for (double a : { 1e3, 1e4 })
  {
    for (double dc : { -1.0, -0.2, 0.2, 1.0 })
    {
      p.emplace_back(a, a + dc);
    }
  }
  return p;
}

struct GridCase
{
  double A, C;
  hovtest::ReferenceWeights Ref;
};

/// The reference weights over the grid (computed once, ~3 ms per pair).
const std::vector<GridCase>& ReferenceGrid()
{
  static const std::vector<GridCase> grid = [] {
    std::vector<GridCase> g;
    for (double a : GridValues())
    {
      for (double c : GridValues())
      {
        g.push_back({ a, c, hovtest::ReferenceSegmentWeights(a, c) });
      }
    }
    for (const auto& p : ThresholdPairs())
    {
      g.push_back({ p.first, p.second, hovtest::ReferenceSegmentWeights(p.first, p.second) });
    }
    return g;
  }();
  return grid;
}
}

// ---------------------------------------------------------------------------
// The reference itself
// ---------------------------------------------------------------------------

// The default reference (30-point Gauss, panels at depth 1, 2, 4, ... 128) and
// a finer one (20-point Gauss, panels every 0.5 of depth) must agree far below
// the tolerances they are used to check; and both must reproduce known closed
// forms (constant extinction) far below that.
TEST(SegmentReference, SelfConsistent)
{
  Worst worst;
  for (double a : { 0.0, 1e-12, 0.3, 2.0, 41.0, 1e4, 1e300 })
  {
    for (double c : { 0.0, 1e-12, 0.5, 39.0, 1e4 })
    {
      const auto r1 = hovtest::ReferenceSegmentWeights(a, c);
      const auto r2 = hovtest::ReferenceSegmentWeights(a, c, true);
      for (auto m : { &hovtest::ReferenceWeights::WFront, &hovtest::ReferenceWeights::WBack,
             &hovtest::ReferenceWeights::VFront, &hovtest::ReferenceWeights::VBack })
      {
        const Mp& x = r1.*m;
        const Mp& y = r2.*m;
        const double rel = x == 0 && y == 0 ? 0.0 : static_cast<double>(abs(x - y) / (abs(x) + abs(y)));
        worst.Add(rel, Pair(a, c));
      }
    }
  }
  hovtest::ReportMeasured("reference self-consistency (relative)", worst);
  EXPECT_LT(worst.Value, Tolerances.ReferenceSelfRel) << worst.Where;

  // Constant extinction: K0 = (1 - e^-D)/D, VBack = (1 - (1 + D) e^-D)/D^2.
  for (double d : { 1e-20, 0.01, 1.0, 30.0, 1e5 })
  {
    const auto r = hovtest::ReferenceSegmentWeights(d, d);
    const Mp D = d;
    const Mp k0 = -boost::math::expm1(-D) / D;
    const Mp v1 = d < 1 ? Mp(0) : Mp((1 - (1 + D) * exp(-D)) / (D * D));
    EXPECT_LT(static_cast<double>(abs(r.K0 - k0) / k0), Tolerances.ReferenceSelfRel) << d;
    if (d >= 1)
    {
      EXPECT_LT(static_cast<double>(abs(r.VBack - v1) / v1), Tolerances.ReferenceSelfRel) << d;
    }
  }
}

// ---------------------------------------------------------------------------
// Against the high-precision reference
// ---------------------------------------------------------------------------

TEST(SegmentWeights, WilliamsMaxMatchesReference)
{
  Worst wAlpha, wT, wFront, wBack, wThin;
  for (const GridCase& g : ReferenceGrid())
  {
    SCOPED_TRACE(Pair(g.A, g.C));
    const hov::SegmentWeights w = hov::ExactSegmentWeights(g.A, g.C, false);
    const double eA = hovtest::RelErr(w.Alpha, g.Ref.Alpha);
    const double eT = hovtest::RelErr(w.Transmittance, g.Ref.Transmittance);
    // T(1) underflows below ~1e-308: compare it absolutely there.
    const double eTabs = g.Ref.Transmittance < 1e-290 ? hovtest::AbsErr(w.Transmittance, g.Ref.Transmittance) : eT;
    const double eF = hovtest::RelErr(w.WFront, g.Ref.WFront);
    const double eB = g.Ref.WBack < 1e-290 ? hovtest::AbsErr(w.WBack, g.Ref.WBack) : hovtest::RelErr(w.WBack, g.Ref.WBack);
    wAlpha.Add(eA, Pair(g.A, g.C));
    wT.Add(eTabs, Pair(g.A, g.C));
    wFront.Add(eF, Pair(g.A, g.C));
    wBack.Add(eB, Pair(g.A, g.C));
    // The thin branch (Taylor series, all terms positive) is held to a few ulp.
    const bool thin = 0.5 * (g.A + g.C) <= ThinDepth;
    const double tol = thin ? Tolerances.WeightsRelThin : Tolerances.WeightsRelWM;
    if (thin)
    {
      wThin.Add(std::max(std::max(eA, eTabs), std::max(eF, eB)), Pair(g.A, g.C));
    }
    EXPECT_LE(eA, tol) << "Alpha " << w.Alpha;
    EXPECT_LE(eTabs, tol) << "Transmittance " << w.Transmittance;
    EXPECT_LE(eF, tol) << "WFront " << w.WFront << " ref " << g.Ref.WFront;
    EXPECT_LE(eB, tol) << "WBack " << w.WBack << " ref " << g.Ref.WBack;
  }
  hovtest::ReportMeasured("WM Alpha relative error", wAlpha);
  hovtest::ReportMeasured("WM Transmittance relative error", wT);
  hovtest::ReportMeasured("WM WFront relative error", wFront);
  hovtest::ReportMeasured("WM WBack relative error", wBack);
  hovtest::ReportMeasured("WM weights relative error, thin branch (D1 <= 1/8)", wThin);
}

TEST(SegmentWeights, WilhelmsVanGelderMatchesReference)
{
  // VFront and VBack relative to K0 = VFront + VBack (the WVG colour is
  // L (VFront gF + VBack gB) <= L K0 max g, so this is the relative colour
  // error), reported separately where a closed form K1 = (A - a K0)/(2b)
  // would cancel (a > 64|b| >= 4). VBack on its own where it matters
  // (VBack > K0/100).
  Worst rel, relK1, relIll, absAll, relThin;
  for (const GridCase& g : ReferenceGrid())
  {
    SCOPED_TRACE(Pair(g.A, g.C));
    const hov::SegmentWeights w = hov::ExactSegmentWeights(g.A, g.C, true);
    const hov::SegmentWeights wm = hov::ExactSegmentWeights(g.A, g.C, false);
    // Requesting the emission weights must not change the others.
    EXPECT_EQ(w.Alpha, wm.Alpha);
    EXPECT_EQ(w.WFront, wm.WFront);
    EXPECT_EQ(w.WBack, wm.WBack);
    const Mp k0 = g.Ref.K0;
    const double b = 0.5 * (g.C - g.A);
    const double e0 = static_cast<double>(abs(Mp(w.VFront) - g.Ref.VFront) / k0);
    const double e1 = static_cast<double>(abs(Mp(w.VBack) - g.Ref.VBack) / k0);
    absAll.Add(std::max(hovtest::AbsErr(w.VFront, g.Ref.VFront), hovtest::AbsErr(w.VBack, g.Ref.VBack)), Pair(g.A, g.C));
    const bool wellConditioned = std::abs(b) < SmallSlope || g.A <= 64.0 * std::abs(b);
    const bool thin = 0.5 * (g.A + g.C) <= ThinDepth;
    const double tol = thin ? Tolerances.WeightsRelThin : Tolerances.WeightsRelWVG;
    if (thin)
    {
      relThin.Add(std::max(e0, e1), Pair(g.A, g.C));
    }
    (wellConditioned ? rel : relIll).Add(std::max(e0, e1), Pair(g.A, g.C));
    // K1 on its own, where it is not negligible against K0.
    if (g.Ref.VBack > 1e-2 * k0)
    {
      const double eK1 = hovtest::RelErr(w.VBack, g.Ref.VBack);
      relK1.Add(eK1, Pair(g.A, g.C));
      EXPECT_LE(eK1, Tolerances.WeightsRelK1) << "VBack " << w.VBack << " ref " << g.Ref.VBack;
    }
    EXPECT_LE(e0, tol) << "VFront " << w.VFront << " ref " << g.Ref.VFront << " K0 " << k0;
    EXPECT_LE(e1, tol) << "VBack " << w.VBack << " ref " << g.Ref.VBack << " K0 " << k0;
  }
  hovtest::ReportMeasured("WVG V relative to K0 (|b| < 1/16 or a <= 64|b|)", rel);
  hovtest::ReportMeasured("WVG V relative to K0 (a > 64|b| >= 4)", relIll);
  hovtest::ReportMeasured("WVG VBack relative to itself (VBack > K0/100)", relK1);
  hovtest::ReportMeasured("WVG V absolute", absAll);
  hovtest::ReportMeasured("WVG V relative to K0, thin branch (D1 <= 1/8)", relThin);
}

// Regression test. Large total depth with a slope that is small relative to
// the depth but >= SmallSlope. The kernels before commit a5a5c71 computed
// K1 = (A - a K0)/(2b) there, which cancels (error ~ eps a/|b| relative to K0:
// 2e-7 at a=1e8, c=1e8+0.2), and inside the zero-slope band (|b| <= 1e-15 D(1),
// possible once D(1) >= 6.25e13) it used K0 = A/D(1), whose 1e-15 relative
// error is amplified by a/(2|b|) >= 5e14 in K1: VBack = VFront = K0/2 whatever
// the truth (0.53 relative to K0 at a=1e14, c=1e14+0.125; VBack ~ K0/a).
TEST(SegmentWeights, WilhelmsVanGelderLargeDepthSmallSlope)
{
  Worst worst;
  const std::vector<std::pair<double, double>> cases = { { 1e6, 1e6 + 0.125 }, { 1e6, 1e6 - 0.2 },
    { 1e8, 1e8 + 0.2 }, { 1e8, 1e8 - 1.0 }, { 1e10, 1e10 + 0.13 }, { 1e14, 1e14 + 0.125 },
    { 1e14, 1e14 - 0.25 }, { 1e16, 1e16 + 4.0 }, { 1e200, 1e200 * (1 + 1.8e-15) },
    { 1e200, 1e200 * (1 + 3e-15) }, { 1e300, 1e300 * (1 - 1.8e-15) } };
  for (const auto& p : cases)
  {
    const double a = p.first, c = p.second;
    SCOPED_TRACE(Pair(a, c));
    const hovtest::ReferenceWeights ref = hovtest::ReferenceSegmentWeights(a, c);
    const hov::SegmentWeights w = hov::ExactSegmentWeights(a, c, true);
    const double e0 = static_cast<double>(abs(Mp(w.VFront) - ref.VFront) / ref.K0);
    const double e1 = static_cast<double>(abs(Mp(w.VBack) - ref.VBack) / ref.K0);
    worst.Add(std::max(e0, e1), Pair(a, c));
    EXPECT_LE(e0, Tolerances.WeightsRelWVG)
      << "VFront got " << Str(w.VFront) << " expected " << ref.VFront << " (K0 " << ref.K0 << ")";
    EXPECT_LE(e1, Tolerances.WeightsRelWVG)
      << "VBack got " << Str(w.VBack) << " expected " << ref.VBack << " (K0 " << ref.K0 << ")";
  }
  hovtest::ReportMeasured("WVG V relative to K0, large depth / small slope", worst);
}

// Full RGBA of IntegrateSegment against the reference, random colours.
TEST(SegmentIntegral, RGBAMatchesReference)
{
  std::mt19937_64 rng(20240611);
  Worst wm, wvg;
  for (const GridCase& g : ReferenceGrid())
  {
    const double length = hovtest::LogUniform(rng, 0.1, 10.0);
    double col[6];
    for (double& v : col)
    {
      v = hovtest::Uniform(rng, 0.0, 1.0);
    }
    const hov::SegmentEnd front = End(g.A / length, col[0], col[1], col[2]);
    const hov::SegmentEnd back = End(g.C / length, col[3], col[4], col[5]);
    // Depth rates must round-trip through tau * L for the comparison to be fair.
    const double a = front.Tau * length, c = back.Tau * length;
    const hovtest::ReferenceWeights ref =
      (a == g.A && c == g.C) ? g.Ref : hovtest::ReferenceSegmentWeights(a, c);
    SCOPED_TRACE(Pair(a, c) + " L=" + Str(length));
    const hov::RGBA pm = hov::IntegrateSegment(length, front, back, hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
    const hov::RGBA pv = hov::IntegrateSegment(length, front, back, hov::EmissionModel::WilhelmsVanGelder, hov::SegmentMethod::Exact);
    const double gmax = *std::max_element(col, col + 6);
    const double outM[3] = { pm.R, pm.G, pm.B };
    const double outV[3] = { pv.R, pv.G, pv.B };
    double em = hovtest::AbsErr(pm.A, ref.Alpha), ev = hovtest::AbsErr(pv.A, ref.Alpha);
    for (int ch = 0; ch < 3; ++ch)
    {
      const Mp cm = ref.WFront * col[ch] + ref.WBack * col[3 + ch];
      const Mp cv = Mp(length) * (ref.VFront * col[ch] + ref.VBack * col[3 + ch]);
      em = std::max(em, hovtest::AbsErr(outM[ch], cm));
      ev = std::max(ev, hovtest::AbsErr(outV[ch], cv) / (length * std::max(gmax, 1e-300)));
    }
    wm.Add(em, Pair(a, c));
    wvg.Add(ev, Pair(a, c));
    EXPECT_LE(em, Tolerances.SegmentRGBAAbs) << "WM " << hovtest::ToString(pm);
    EXPECT_LE(ev, Tolerances.SegmentRGBAAbs) << "WVG " << hovtest::ToString(pv);
  }
  hovtest::ReportMeasured("IntegrateSegment WM RGBA absolute error", wm);
  hovtest::ReportMeasured("IntegrateSegment WVG RGB error / (L max g)", wvg);
}

// ---------------------------------------------------------------------------
// Closed forms and limits
// ---------------------------------------------------------------------------

TEST(SegmentIntegral, ConstantExtinctionClosedForm)
{
  std::mt19937_64 rng(7);
  Worst worst;
  for (int i = 0; i < 2000; ++i)
  {
    const double tau = hovtest::LogUniform(rng, 1e-8, 1e3);
    const double length = hovtest::LogUniform(rng, 1e-3, 10.0);
    const double c0 = hovtest::Uniform(rng, 0, 1), c1 = hovtest::Uniform(rng, 0, 1);
    const double g = hovtest::Uniform(rng, 0, 1);
    // The kernel sees the depth tau * L rounded to double: so does the formula.
    const double depth = tau * length;
    SCOPED_TRACE("tau=" + Str(tau) + " L=" + Str(length));
    // Same colour at both ends: alpha = 1 - e^{-tau L}, C = c alpha (WM),
    // C = L g (1 - e^{-tau L})/(tau L) (WVG).
    const hov::RGBA m = hov::IntegrateSegment(length, End(tau, c0, c0, g), End(tau, c0, c0, g),
      hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
    const hov::RGBA v = hov::IntegrateSegment(length, End(tau, g, g, g), End(tau, g, g, g),
      hov::EmissionModel::WilhelmsVanGelder, hov::SegmentMethod::Exact);
    const Mp alpha = -boost::math::expm1(-Mp(depth));
    const double e1 = hovtest::RelErr(m.A, alpha);
    const double e2 = hovtest::RelErr(m.R, alpha * c0);
    const double e3 = hovtest::RelErr(v.R, Mp(length) * g * alpha / Mp(depth));
    const double e4 = hovtest::RelErr(v.A, alpha);
    worst.Add(std::max(std::max(e1, e2), std::max(e3, e4)), "tau=" + Str(tau) + " L=" + Str(length));
    EXPECT_LE(e1, Tolerances.ClosedFormRel);
    EXPECT_LE(e2, Tolerances.ClosedFormRel);
    EXPECT_LE(e3, Tolerances.ClosedFormRel);
    EXPECT_LE(e4, Tolerances.ClosedFormRel);
    // Linear colour, constant extinction: WFront = 1 - K0, WBack = K0 - T,
    // K0 = (1 - e^{-D})/D (evaluated in 50 digits, so no cancellation).
    const Mp k0 = alpha / Mp(depth);
    const hov::RGBA ml = hov::IntegrateSegment(length, End(tau, c0, 0, 0), End(tau, c1, 0, 0),
      hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
    const Mp ref = (1 - k0) * c0 + (k0 - exp(-Mp(depth))) * c1;
    const double e5 = hovtest::RelErr(ml.R, ref);
    EXPECT_LE(e5, Tolerances.WeightsRelWM) << "linear colour";
  }
  hovtest::ReportMeasured("constant-extinction closed form (relative)", worst);
}

TEST(SegmentIntegral, VanishingExtinction)
{
  // tau -> 0: A ~ tau L, WM C ~ A (c0 + c1)/2 -> 0, WVG C -> L (g0 + g1)/2.
  const double length = 3.0;
  const double g0 = 0.2, g1 = 0.9;
  Worst worst;
  for (double tau : { 0.0, 1e-300, 1e-200, 1e-30, 1e-16 })
  {
    SCOPED_TRACE("tau=" + Str(tau));
    const hov::RGBA v = hov::IntegrateSegment(length, End(tau, g0, g0, g0), End(tau, g1, g1, g1),
      hov::EmissionModel::WilhelmsVanGelder, hov::SegmentMethod::Exact);
    const hov::RGBA m = hov::IntegrateSegment(length, End(tau, g0, g0, g0), End(tau, g1, g1, g1),
      hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
    // C_WVG = L int (g0 (1-x) + g1 x) e^{-tau L x} dx = L (g0+g1)/2 (1 + O(tau L)).
    const double e = std::abs(v.R - length * 0.5 * (g0 + g1)) / (length * 0.5 * (g0 + g1));
    worst.Add(e, "tau=" + Str(tau));
    EXPECT_LE(e, Tolerances.ClosedFormRel + 2 * tau * length);
    const Mp alpha = -boost::math::expm1(-Mp(tau) * Mp(length));
    if (tau == 0.0)
    {
      EXPECT_EQ(m.A, 0.0);
      EXPECT_EQ(m.R, 0.0);
    }
    else
    {
      EXPECT_LE(hovtest::RelErr(m.A, alpha), Tolerances.ClosedFormRel);
      // WM with linear colour: C = tau L ((g0 + g1)/2 + O(tau L)).
      EXPECT_LE(hovtest::RelErr(m.R, alpha * Mp(0.5 * (g0 + g1))), Tolerances.ClosedFormRel + 2 * tau * length);
    }
  }
  hovtest::ReportMeasured("tau -> 0 limit (relative)", worst);
}

TEST(SegmentIntegral, ZeroExtinctionLinearEmission)
{
  // WVG with zero extinction: C = L (g0 + g1)/2 exactly; A = 0.
  std::mt19937_64 rng(11);
  for (int i = 0; i < 200; ++i)
  {
    const double length = hovtest::LogUniform(rng, 1e-6, 1e6);
    const double g0 = hovtest::Uniform(rng, 0, 2), g1 = hovtest::Uniform(rng, 0, 2);
    SCOPED_TRACE("L=" + Str(length) + " g0=" + Str(g0) + " g1=" + Str(g1));
    const hov::RGBA v = hov::IntegrateSegment(length, End(0.0, g0, 0, g1), End(0.0, g1, 0, g0),
      hov::EmissionModel::WilhelmsVanGelder, hov::SegmentMethod::Exact);
    const double ref = length * 0.5 * (g0 + g1);
    EXPECT_EQ(v.A, 0.0);
    EXPECT_LE(std::abs(v.R - ref), Tolerances.ClosedFormRel * ref);
    EXPECT_LE(std::abs(v.B - ref), Tolerances.ClosedFormRel * ref);
    EXPECT_EQ(v.G, 0.0);
  }
}

TEST(SegmentIntegral, ZeroOrInvalidLength)
{
  const hov::SegmentEnd f = End(2.0, 0.3, 0.4, 0.5), b = End(5.0, 0.6, 0.7, 0.8);
  for (double length : { 0.0, -0.0, -1.0, std::nan("") })
  {
    for (auto em : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      for (auto me : { hov::SegmentMethod::Exact, hov::SegmentMethod::Approximate })
      {
        SCOPED_TRACE("L=" + Str(length));
        const hov::RGBA out = hov::IntegrateSegment(length, f, b, em, me);
        EXPECT_EQ(out.R, 0.0);
        EXPECT_EQ(out.G, 0.0);
        EXPECT_EQ(out.B, 0.0);
        EXPECT_EQ(out.A, 0.0);
      }
    }
  }
  // Tiny length: A ~ (tauF + tauB) L / 2.
  const double tiny = 1e-300;
  const hov::RGBA t = hov::IntegrateSegment(tiny, f, b, hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
  EXPECT_NEAR(t.A / tiny, 3.5, 3.5 * Tolerances.ClosedFormRel);
}

TEST(SegmentIntegral, ReversalSymmetry)
{
  // Opacity depends on the total depth only; for a constant colour the WM
  // colour is c A in both directions.
  std::mt19937_64 rng(99);
  Worst worst;
  for (int i = 0; i < 20000; ++i)
  {
    const double t0 = i % 7 == 0 ? 0.0 : hovtest::LogUniform(rng, 1e-6, 1e4);
    const double t1 = i % 11 == 0 ? 0.0 : hovtest::LogUniform(rng, 1e-6, 1e4);
    const double length = hovtest::LogUniform(rng, 1e-3, 10.0);
    const double c = hovtest::Uniform(rng, 0, 1);
    SCOPED_TRACE("tau0=" + Str(t0) + " tau1=" + Str(t1) + " L=" + Str(length));
    const hov::RGBA fwd = hov::IntegrateSegment(length, End(t0, c, c, c), End(t1, c, c, c),
      hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
    const hov::RGBA rev = hov::IntegrateSegment(length, End(t1, c, c, c), End(t0, c, c, c),
      hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
    EXPECT_EQ(fwd.A, rev.A);
    const double e = std::max(std::abs(fwd.R - rev.R), std::abs(fwd.R - c * fwd.A)) / std::max(c * fwd.A, 1e-300);
    worst.Add(e, "tau0=" + Str(t0) + " tau1=" + Str(t1) + " L=" + Str(length));
    EXPECT_LE(e, Tolerances.ClosedFormRel);
    // WVG: the opacity is symmetric too.
    const hov::RGBA vf = hov::IntegrateSegment(length, End(t0, c, c, c), End(t1, c, c, c),
      hov::EmissionModel::WilhelmsVanGelder, hov::SegmentMethod::Exact);
    const hov::RGBA vr = hov::IntegrateSegment(length, End(t1, c, c, c), End(t0, c, c, c),
      hov::EmissionModel::WilhelmsVanGelder, hov::SegmentMethod::Exact);
    EXPECT_EQ(vf.A, vr.A);
  }
  hovtest::ReportMeasured("reversal, constant colour WM (relative)", worst);

  // The individual weights have no simple reversal relation (K0(c,a) =
  // T(1) int e^{D(y)} dy), but WFront + WBack = A in both directions: this is
  // what makes the constant-colour WM result c A.
  for (const auto& p : ThresholdPairs())
  {
    const hov::SegmentWeights w = hov::ExactSegmentWeights(p.first, p.second, true);
    const hov::SegmentWeights r = hov::ExactSegmentWeights(p.second, p.first, true);
    SCOPED_TRACE(Pair(p.first, p.second));
    EXPECT_LE(std::abs(w.WFront + w.WBack - w.Alpha), Tolerances.ClosedFormRel * w.Alpha);
    EXPECT_LE(std::abs(r.WFront + r.WBack - r.Alpha), Tolerances.ClosedFormRel * r.Alpha);
  }
}

TEST(SegmentIntegral, OpaqueMedium)
{
  const double cf[3] = { 0.25, 0.5, 0.75 };
  for (double tf : { Inf, 1.0, 0.0 })
  {
    for (double tb : { Inf, 2.0, 0.0 })
    {
      if (tf != Inf && tb != Inf)
      {
        continue;
      }
      for (double length : { 1e-300, 1.0, 1e300 })
      {
        SCOPED_TRACE("tauF=" + Str(tf) + " tauB=" + Str(tb) + " L=" + Str(length));
        const hov::SegmentEnd f = End(tf, cf[0], cf[1], cf[2]);
        const hov::SegmentEnd b = End(tb, 0.9, 0.9, 0.9);
        for (auto me : { hov::SegmentMethod::Exact, hov::SegmentMethod::Approximate })
        {
          const hov::RGBA m = hov::IntegrateSegment(length, f, b, hov::EmissionModel::WilliamsMax, me);
          const hov::RGBA v = hov::IntegrateSegment(length, f, b, hov::EmissionModel::WilhelmsVanGelder, me);
          EXPECT_EQ(m.A, 1.0);
          EXPECT_EQ(v.A, 1.0);
          if (me == hov::SegmentMethod::Exact)
          {
            EXPECT_EQ(m.R, cf[0]);
            EXPECT_EQ(m.G, cf[1]);
            EXPECT_EQ(m.B, cf[2]);
            EXPECT_EQ(v.R, 0.0);
            EXPECT_EQ(v.G, 0.0);
            EXPECT_EQ(v.B, 0.0);
          }
          EXPECT_TRUE(hovtest::AllFinite(m)) << hovtest::ToString(m);
          EXPECT_TRUE(hovtest::AllFinite(v)) << hovtest::ToString(v);
        }
      }
    }
  }
  // Very large but finite depth: the same limits, reached continuously.
  const hov::RGBA m = hov::IntegrateSegment(1.0, End(1e300, cf[0], cf[1], cf[2]), End(1e300, 0.9, 0.9, 0.9),
    hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
  EXPECT_EQ(m.A, 1.0);
  EXPECT_NEAR(m.R, cf[0], Tolerances.FewUlpAbs);
  const hov::RGBA v = hov::IntegrateSegment(1.0, End(1e300, 1, 1, 1), End(1e300, 1, 1, 1),
    hov::EmissionModel::WilhelmsVanGelder, hov::SegmentMethod::Exact);
  EXPECT_NEAR(v.R / 1e-300, 1.0, Tolerances.ClosedFormRel); // C = L g K0 = 1/tau
  // NaN extinction: documented "no Inf or NaN for finite colours".
  const hov::RGBA n = hov::IntegrateSegment(1.0, End(std::nan(""), 0.5, 0.5, 0.5), End(1.0, 0.5, 0.5, 0.5),
    hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
  EXPECT_TRUE(hovtest::AllFinite(n)) << hovtest::ToString(n);
  EXPECT_GE(n.A, 0.0);
  EXPECT_LE(n.A, 1.0);
}

// ---------------------------------------------------------------------------
// Continuity across the branch thresholds
// ---------------------------------------------------------------------------

namespace
{
/// Max relative difference over all weights between two nearby inputs.
double WeightJump(double a1, double c1, double a2, double c2)
{
  const hov::SegmentWeights p = hov::ExactSegmentWeights(a1, c1, true);
  const hov::SegmentWeights q = hov::ExactSegmentWeights(a2, c2, true);
  auto rel = [](double x, double y, double scale) { return std::abs(x - y) / scale; };
  const double k0 = std::max(p.VFront + p.VBack, 1e-300);
  double j = 0.0;
  j = std::max(j, rel(p.Alpha, q.Alpha, std::max(p.Alpha, 1e-300)));
  j = std::max(j, rel(p.WFront, q.WFront, std::max(p.WFront, 1e-300)));
  j = std::max(j, rel(p.WBack, q.WBack, std::max(p.WBack, 1e-300)));
  j = std::max(j, rel(p.VFront, q.VFront, k0));
  j = std::max(j, rel(p.VBack, q.VBack, k0));
  return j;
}
}

TEST(SegmentWeights, ContinuousAcrossThresholds)
{
  Worst thin, slope, moment, zero, sign;
  // ThinDepth: D(1) = 1/8 (thin series) vs the next double (closed form).
  for (double f : { 0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0 })
  {
    const double d = ThinDepth;
    const double dUp = std::nextafter(d, 1.0);
    const double a1 = 2 * d * f, c1 = 2 * d - a1;
    const double a2 = 2 * dUp * f, c2 = 2 * dUp - a2;
    ASSERT_LE(0.5 * (a1 + c1), ThinDepth);
    ASSERT_GT(0.5 * (a2 + c2), ThinDepth);
    const double j = WeightJump(a1, c1, a2, c2);
    thin.Add(j, Pair(a1, c1));
    EXPECT_LE(j, Tolerances.ContinuityRel) << Pair(a1, c1) << " vs " << Pair(a2, c2);
  }
  // SmallSlope: |b| = 1/16 - ulp (series in b) vs |b| = 1/16 (closed form K1).
  for (double a : { 0.0, 0.1, 0.2, 1.0, 5.0, 20.0, 39.9, 40.1, 64.0, 100.0 })
  {
    for (double sgn : { 1.0, -1.0 })
    {
      const double c1 = a + sgn * 2 * std::nextafter(SmallSlope, 0.0);
      const double c2 = a + sgn * 2 * SmallSlope;
      if (c2 < 0 || c1 < 0)
      {
        continue;
      }
      const double j = WeightJump(a, c1, a, c2);
      slope.Add(j, Pair(a, c1));
      EXPECT_LE(j, Tolerances.ContinuityRel) << Pair(a, c1) << " vs " << Pair(a, c2);
    }
  }
  // MomentUpwardFrom: a = 40 (downward recurrence) vs next double (upward).
  for (double db : { -0.06, -0.01, -1e-8, 0.0, 1e-8, 0.01, 0.06 })
  {
    const double a1 = MomentUpwardFrom, a2 = std::nextafter(MomentUpwardFrom, 100.0);
    const double j = WeightJump(a1, a1 + 2 * db, a2, a2 + 2 * db);
    moment.Add(j, Pair(a1, a1 + 2 * db));
    EXPECT_LE(j, Tolerances.ContinuityRel) << Pair(a1, a1 + 2 * db);
  }
  // ZeroSlopeRelative: |b| just below / above 1e-15 D(1), both signs.
  for (double a : { 0.2, 1.0, 7.0, 50.0, 1e4, 1e200 })
  {
    for (double sgn : { 1.0, -1.0 })
    {
      const double c1 = a * (1 + sgn * 2 * ZeroSlopeRelative * 0.9);
      const double c2 = a * (1 + sgn * 2 * ZeroSlopeRelative * 1.1);
      const double j = WeightJump(a, c1, a, c2);
      zero.Add(j, Pair(a, c1));
      EXPECT_LE(j, Tolerances.ContinuityRel) << Pair(a, c1) << " vs " << Pair(a, c2);
    }
    // Through b = 0 just outside the zero-slope band: Dawson (b < 0) vs erfcx (b > 0).
    const double j = WeightJump(a, a * (1 - 8 * ZeroSlopeRelative), a, a * (1 + 8 * ZeroSlopeRelative));
    sign.Add(j, Pair(a, a));
    EXPECT_LE(j, Tolerances.ContinuityRel + 16 * ZeroSlopeRelative) << "b sign change at a=" << a;
  }
  hovtest::ReportMeasured("jump at ThinDepth (relative)", thin);
  hovtest::ReportMeasured("jump at SmallSlope (relative)", slope);
  hovtest::ReportMeasured("jump at MomentUpwardFrom (relative)", moment);
  hovtest::ReportMeasured("jump at ZeroSlopeRelative (relative)", zero);
  hovtest::ReportMeasured("jump through b = 0 (relative)", sign);
}

// ---------------------------------------------------------------------------
// Composition: [0,L] = [0,f L] over [f L, L]
// ---------------------------------------------------------------------------

TEST(SegmentIntegral, SplitAndCompositeEqualsWhole)
{
  std::mt19937_64 rng(31337);
  Worst wm, wvg;
  for (int i = 0; i < 20000; ++i)
  {
    const double t0 = i % 9 == 0 ? 0.0 : hovtest::LogUniform(rng, 1e-4, 1e2);
    const double t1 = i % 13 == 0 ? 0.0 : hovtest::LogUniform(rng, 1e-4, 1e2);
    const double length = hovtest::LogUniform(rng, 1e-2, 10.0);
    const double f = hovtest::Uniform(rng, 0.01, 0.99);
    double c0[3], c1[3], cm[3];
    for (int ch = 0; ch < 3; ++ch)
    {
      c0[ch] = hovtest::Uniform(rng, 0, 1);
      c1[ch] = hovtest::Uniform(rng, 0, 1);
      cm[ch] = c0[ch] + (c1[ch] - c0[ch]) * f;
    }
    const double tm = t0 + (t1 - t0) * f;
    const std::string where = "tau0=" + Str(t0) + " tau1=" + Str(t1) + " L=" + Str(length) + " f=" + Str(f);
    SCOPED_TRACE(where);
    const hov::SegmentEnd e0 = End(t0, c0[0], c0[1], c0[2]);
    const hov::SegmentEnd em = End(tm, cm[0], cm[1], cm[2]);
    const hov::SegmentEnd e1 = End(t1, c1[0], c1[1], c1[2]);
    for (auto model : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      const hov::RGBA whole = hov::IntegrateSegment(length, e0, e1, model, hov::SegmentMethod::Exact);
      hov::RGBA acc = hov::IntegrateSegment(f * length, e0, em, model, hov::SegmentMethod::Exact);
      hov::CompositeBehind(acc, hov::IntegrateSegment((1 - f) * length, em, e1, model, hov::SegmentMethod::Exact));
      const bool isWM = model == hov::EmissionModel::WilliamsMax;
      const double scale = isWM ? 1.0 : std::max(1.0, length);
      const double e = hovtest::MaxAbsDiff(whole, acc) / scale;
      (isWM ? wm : wvg).Add(e, where);
      EXPECT_LE(e, Tolerances.CompositionAbs) << (isWM ? "WM " : "WVG ") << hovtest::ToString(whole)
                                              << " vs " << hovtest::ToString(acc);
    }
  }
  hovtest::ReportMeasured("split/composite WM (absolute)", wm);
  hovtest::ReportMeasured("split/composite WVG (absolute / max(1,L))", wvg);
}

// ---------------------------------------------------------------------------
// Log-uniform sweep over the whole double range
// ---------------------------------------------------------------------------

TEST(SegmentIntegral, LogUniformSweepIsFiniteAndBounded)
{
  std::mt19937_64 rng(424242);
  auto randomTau = [&]() {
    const double u = hovtest::Uniform(rng, 0, 1);
    if (u < 0.03)
    {
      return 0.0;
    }
    if (u < 0.05)
    {
      return Inf;
    }
    return hovtest::LogUniform(rng, 1e-300, 1e300);
  };
  Worst overM, overV;
  long failures = 0;
  for (int i = 0; i < 1000000; ++i)
  {
    const double t0 = randomTau(), t1 = randomTau();
    const double length = hovtest::Uniform(rng, 0, 1) < 0.02 ? 0.0 : hovtest::LogUniform(rng, 1e-300, 1e300);
    double c[6];
    for (double& v : c)
    {
      v = hovtest::Uniform(rng, 0, 1);
    }
    const hov::SegmentEnd f = End(t0, c[0], c[1], c[2]), b = End(t1, c[3], c[4], c[5]);
    const auto method = i % 4 == 3 ? hov::SegmentMethod::Approximate : hov::SegmentMethod::Exact;
    const hov::RGBA m = hov::IntegrateSegment(length, f, b, hov::EmissionModel::WilliamsMax, method);
    const hov::RGBA v = hov::IntegrateSegment(length, f, b, hov::EmissionModel::WilhelmsVanGelder, method);
    const double mm[3] = { m.R, m.G, m.B }, vv[3] = { v.R, v.G, v.B };
    bool ok = hovtest::AllFinite(m) && hovtest::AllFinite(v) && m.A >= 0 && m.A <= 1 && v.A >= 0 && v.A <= 1;
    for (int ch = 0; ch < 3; ++ch)
    {
      const double cmax = std::max(c[ch], c[3 + ch]);
      // WM: 0 <= C <= A max c (WFront + WBack = A), and so C <= max c; the
      // first bound up to rounding in subnormal numbers (4 denorm_min).
      const double limM = std::min(m.A * cmax + 4 * Denorm, cmax) * (1 + Tolerances.SweepSlackRel);
      // WVG: 0 <= C <= L max g (K0 <= 1).
      const double limV = length * cmax * (1 + Tolerances.SweepSlackRel);
      ok = ok && mm[ch] >= 0 && mm[ch] <= limM && vv[ch] >= 0 && vv[ch] <= limV;
      if (m.A > 1e-300 && cmax > 0)
      {
        overM.Add(mm[ch] / (m.A * cmax) - 1, "");
      }
      if (limV > 0)
      {
        overV.Add(vv[ch] / (length * cmax) - 1, "");
      }
    }
    if (!ok && ++failures <= 10)
    {
      ADD_FAILURE() << "tau0=" << Str(t0) << " tau1=" << Str(t1) << " L=" << Str(length)
                    << " method=" << static_cast<int>(method) << " WM=" << hovtest::ToString(m)
                    << " WVG=" << hovtest::ToString(v);
    }
  }
  EXPECT_EQ(failures, 0);
  hovtest::ReportMeasured("sweep: max WM C/(A max c) - 1", overM);
  hovtest::ReportMeasured("sweep: max WVG C/(L max g) - 1", overV);
}

// ---------------------------------------------------------------------------
// Approximate method (HIAC section 4)
// ---------------------------------------------------------------------------

TEST(SegmentIntegral, ApproximateMethod)
{
  std::mt19937_64 rng(5150);
  Worst ratioM, ratioV, errM, kRatio;
  for (int i = 0; i < 50000; ++i)
  {
    const double t0 = i % 10 == 0 ? 0.0 : hovtest::LogUniform(rng, 1e-6, 1e3);
    const double t1 = i % 7 == 0 ? t0 : (i % 10 == 1 ? 0.0 : hovtest::LogUniform(rng, 1e-6, 1e3));
    const double length = hovtest::LogUniform(rng, 1e-3, 10.0);
    double c0[3], c1[3];
    for (int ch = 0; ch < 3; ++ch)
    {
      c0[ch] = hovtest::Uniform(rng, 0, 1);
      c1[ch] = hovtest::Uniform(rng, 0, 1);
    }
    const std::string where = "tau0=" + Str(t0) + " tau1=" + Str(t1) + " L=" + Str(length);
    SCOPED_TRACE(where);
    const hov::SegmentEnd f = End(t0, c0[0], c0[1], c0[2]), b = End(t1, c1[0], c1[1], c1[2]);
    const hov::RGBA ex = hov::IntegrateSegment(length, f, b, hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
    const hov::RGBA ap = hov::IntegrateSegment(length, f, b, hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Approximate);
    // Opacity: the exact opacity of the linear extinction.
    EXPECT_LE(std::abs(ap.A - ex.A), Tolerances.ApproxOpacityRel * ex.A);
    // Colour, WM: exact = WFront cF + WBack cB with WFront + WBack = A and both
    // in [0, A]; approximate = A (cF + cB)/2. So the error is
    // (WFront - A/2)(cF - cB) and |error| <= (A/2)|cF - cB| per channel.
    const double e[3] = { ap.R - ex.R, ap.G - ex.G, ap.B - ex.B };
    for (int ch = 0; ch < 3; ++ch)
    {
      const double bound = 0.5 * ex.A * std::abs(c0[ch] - c1[ch]);
      EXPECT_LE(std::abs(e[ch]), bound * (1 + Tolerances.BoundSlackRel) + Tolerances.FewUlpAbs * ex.A) << "channel " << ch;
      if (bound > 1e-12)
      {
        ratioM.Add(std::abs(e[ch]) / bound, where);
      }
      errM.Add(std::abs(e[ch]), where);
    }
    // WVG: exact for constant extinction and colour; with constant extinction
    // and linear colour |error| <= L K0/2 |gF - gB| (same argument with V).
    const hov::RGBA vx = hov::IntegrateSegment(length, f, b, hov::EmissionModel::WilhelmsVanGelder, hov::SegmentMethod::Exact);
    const hov::RGBA va = hov::IntegrateSegment(length, f, b, hov::EmissionModel::WilhelmsVanGelder, hov::SegmentMethod::Approximate);
    EXPECT_LE(std::abs(va.A - vx.A), Tolerances.ApproxOpacityRel * vx.A);
    const hov::SegmentWeights w = hov::ExactSegmentWeights(t0 * length, t1 * length, true);
    const double k0 = w.VFront + w.VBack;
    if (t0 == t1)
    {
      const double ev[3] = { va.R - vx.R, va.G - vx.G, va.B - vx.B };
      for (int ch = 0; ch < 3; ++ch)
      {
        const double bound = 0.5 * length * k0 * std::abs(c0[ch] - c1[ch]);
        EXPECT_LE(std::abs(ev[ch]), bound * (1 + Tolerances.BoundSlackRel) + Tolerances.FewUlpAbs * length * k0) << "WVG channel " << ch;
        if (bound > 1e-12)
        {
          ratioV.Add(std::abs(ev[ch]) / bound, where);
        }
      }
    }
    else
    {
      // Non-constant extinction: the approximate WVG uses K0 ~ A / D(1),
      // which is exact only for constant extinction. Measured, not bounded.
      const double d1 = 0.5 * (t0 + t1) * length;
      if (d1 > 0)
      {
        kRatio.Add(std::abs(ex.A / d1 / k0 - 1), where);
      }
    }
  }
  hovtest::ReportMeasured("approx WM colour |error| / ((A/2)|cF-cB|)", ratioM);
  hovtest::ReportMeasured("approx WM colour absolute error", errM);
  hovtest::ReportMeasured("approx WVG (constant tau) |error| / ((L K0/2)|gF-gB|)", ratioV);
  hovtest::ReportMeasured("approx WVG, non-constant tau: |A/D1/K0 - 1| (not bounded)", kRatio);

  // Constant colour, WM: the approximate method is exact.
  const hov::RGBA ex = hov::IntegrateSegment(2.0, End(0.5, 0.3, 0.3, 0.3), End(7.0, 0.3, 0.3, 0.3),
    hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
  const hov::RGBA ap = hov::IntegrateSegment(2.0, End(0.5, 0.3, 0.3, 0.3), End(7.0, 0.3, 0.3, 0.3),
    hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Approximate);
  EXPECT_NEAR(ap.R, ex.R, Tolerances.FewUlpAbs);
  EXPECT_LE(std::abs(ap.A - ex.A), Tolerances.ApproxOpacityRel * ex.A);
}
