// Properties of hovSegmentIntegral that hold for any input: continuity across
// the kernel's branch thresholds, splitting a segment and compositing the
// halves, finite and bounded results over the whole double range, and the
// error bounds of the approximate method. Tolerances: hovKernelTestTolerances.h.

#include "hovSegmentTestCases.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace hovtest::segment;

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
