// Tests of hovSegmentIntegral (IntegrateSegment, ExactSegmentWeights)
// against closed forms and limits: constant and vanishing extinction, zero
// length, reversal symmetry, opaque media. Tolerances: hovKernelTestTolerances.h.

#include "hovSegmentTestCases.h"

#include <gtest/gtest.h>

#include <random>

using namespace hovtest::segment;

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
