// Tests of hovSegmentIntegral against an independent 50-digit quadrature of
// the defining integrals (hovKernelTestReference.h): the reference itself,
// ExactSegmentWeights for both emission models over the grid of depth rates
// (hovSegmentTestCases.h), and the RGBA of IntegrateSegment. Tolerances:
// hovKernelTestTolerances.h.

#include "hovSegmentTestCases.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace hovtest::segment;

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
