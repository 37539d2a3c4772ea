// Blend-mode kernel tests, second part (see TestBlendModes.cxx): polynomial
// extrema against Brent, order independence and composition, continuity
// across branches, VTK's semantics, degenerate input.
#include "hovBlendModes.h"

#include "hovCellRestriction.h"
#include "hovTransferFunction.h"

#include "hovFeatureTestReference.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"
#include "hovBlendTestTables.h"

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/tools/minima.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using hovtest::LD;
using hovtest::Str;
using hovtest::Tolerances;
using hovtest::Worst;

using hovtest::RandomSpec;
using hovtest::RawTable;

TEST(BlendModes, PolynomialExtremumAgainstBrent)
{
  std::mt19937_64 rng(1903);
  Worst relErr, violations;
  int count = 0;
  for (int degree = 2; degree <= 8; ++degree)
  {
    for (int trial = 0; trial < 150; ++trial)
    {
      hov::Polynomial s;
      s.Degree = degree;
      const double h = hovtest::LogUniform(rng, 0.05, 5.0);
      for (int k = 0; k <= degree; ++k)
      {
        s.C[k] = hovtest::Uniform(rng, -1, 1) / std::pow(h, k); // O(1) on [0, h]
      }
      LD scale = 0;
      for (int k = 0; k <= degree; ++k)
      {
        scale += std::fabs(s.C[k]) * std::pow(static_cast<LD>(h), k);
      }
      auto p = [&](LD t) {
        LD r = s.C[degree];
        for (int k = degree - 1; k >= 0; --k)
        {
          r = r * t + s.C[k];
        }
        return r;
      };
      for (int sign : { 1, -1 })
      {
        // Reference: dense samples, then Brent (64 bits) around the best.
        const int m = 4000;
        int best = 0;
        for (int i = 1; i <= m; ++i)
        {
          if (sign * p(h * static_cast<LD>(i) / m) > sign * p(h * static_cast<LD>(best) / m))
          {
            best = i;
          }
        }
        LD ref = p(h * static_cast<LD>(best) / m);
        if (best > 0 && best < m)
        {
          const auto r = boost::math::tools::brent_find_minima(
            [&](LD t) { return -sign * p(t); }, h * static_cast<LD>(best - 1) / m,
            h * static_cast<LD>(best + 1) / m, 64);
          ref = sign > 0 ? std::max(ref, -r.second) : std::min(ref, r.second);
        }
        double value, where, bound;
        ASSERT_TRUE(hov::PolynomialExtremum(s, h, sign, value, where, bound));
        const std::string at = "degree " + std::to_string(degree) + " trial " + std::to_string(trial) +
          " sign " + std::to_string(sign) + " h=" + Str(h);
        const double err = static_cast<double>(std::fabs(value - ref));
        relErr.Add(err / static_cast<double>(scale), at);
        // The bound must hold (the long double reference itself: ~1e-18 scale).
        violations.Add(err - bound - 1e-17 * static_cast<double>(scale), at);
        EXPECT_GE(where, 0.0);
        EXPECT_LE(where, h);
        EXPECT_NEAR(value, static_cast<double>(p(where)), bound + 1e-15 * static_cast<double>(scale)) << at;
        ++count;
      }
    }
  }
  hovtest::ReportMeasured("BlendModes.ExtremumVsBrentRel", relErr);
  hovtest::ReportMeasured("BlendModes.ExtremumBoundViolation", violations);
  EXPECT_LE(relErr.Value, Tolerances.BlendPolynomialRel) << relErr.Where;
  EXPECT_LE(violations.Value, 0.0) << violations.Where;
  EXPECT_EQ(count, 7 * 150 * 2);
}

TEST(BlendModes, OrderIndependenceAndComposition)
{
  std::mt19937_64 rng(1904);
  const hov::TransferFunctionSpec spec = RandomSpec(rng, 4, 6);
  const hov::TransferFunction table = RawTable(spec);
  Worst sumErr, splitErr;
  for (int trial = 0; trial < 100; ++trial)
  {
    struct Seg
    {
      double T, L, SF, SB;
      hov::Polynomial P;
      bool Poly;
    };
    std::vector<Seg> segs;
    double t = 0;
    for (int i = 0; i < 8; ++i)
    {
      Seg g;
      g.T = t;
      g.L = hovtest::Uniform(rng, 0.01, 0.5);
      g.SF = hovtest::Uniform(rng, -0.2, 1.2);
      g.SB = hovtest::Uniform(rng, -0.2, 1.2);
      g.Poly = i % 2 == 1;
      g.P = hov::Polynomial::FromCoefficients({ g.SF, hovtest::Uniform(rng, -2, 2), hovtest::Uniform(rng, -4, 4) });
      segs.push_back(g);
      t += g.L;
    }
    for (hov::BlendMode mode : { hov::BlendMode::MaximumIntensity, hov::BlendMode::MinimumIntensity,
           hov::BlendMode::AverageIntensity })
    {
      hov::BlendSettings bs;
      bs.Mode = mode;
      bs.AverageRange[0] = 0.1;
      bs.AverageRange[1] = 0.9;
      auto run = [&](const std::vector<Seg>& order) {
        hov::RayBlendState st;
        for (const Seg& g : order)
        {
          if (g.Poly)
          {
            hov::AccumulatePolynomialSegment(st, bs, table, g.T, g.L, g.P);
          }
          else
          {
            hov::AccumulateLinearSegment(st, bs, table, g.T, g.L, g.SF, g.SB);
          }
        }
        return st;
      };
      const hov::RayBlendState a = run(segs);
      std::vector<Seg> shuffled = segs;
      std::shuffle(shuffled.begin(), shuffled.end(), rng);
      const hov::RayBlendState b = run(shuffled);
      // Two partial states merged (e.g. two tiles or threads).
      const std::vector<Seg> first(segs.begin(), segs.begin() + 3), second(segs.begin() + 3, segs.end());
      hov::RayBlendState merged = run(second);
      hov::MergeBlendStates(merged, run(first), bs);
      const std::string where = "trial " + std::to_string(trial) + " mode " + std::to_string(static_cast<int>(mode));
      EXPECT_EQ(a.Value, b.Value) << where;
      EXPECT_EQ(a.T, b.T) << where;
      EXPECT_EQ(a.Value, merged.Value) << where;
      EXPECT_EQ(a.T, merged.T) << where;
      sumErr.Add(std::max({ std::fabs(a.WeightedIntegral - b.WeightedIntegral),
                   std::fabs(a.InRangeLength - merged.InRangeLength),
                   std::fabs(a.ScalarIntegral - merged.ScalarIntegral) }),
        where);
      // Splitting a linear segment in two gives the same sums.
      const Seg& g = segs[0];
      const double x = hovtest::Uniform(rng, 0.05, 0.95);
      const double sx = g.SF + (g.SB - g.SF) * x;
      hov::RayBlendState whole, halves;
      hov::AccumulateLinearSegment(whole, bs, table, g.T, g.L, g.SF, g.SB);
      hov::AccumulateLinearSegment(halves, bs, table, g.T, g.L * x, g.SF, sx);
      hov::AccumulateLinearSegment(halves, bs, table, g.T + g.L * x, g.L * (1 - x), sx, g.SB);
      splitErr.Add(std::max({ std::fabs(whole.WeightedIntegral - halves.WeightedIntegral),
                     std::fabs(whole.InRangeLength - halves.InRangeLength),
                     std::fabs(whole.ScalarIntegral - halves.ScalarIntegral) }),
        where);
    }
  }
  hovtest::ReportMeasured("BlendModes.ReorderedSums", sumErr);
  hovtest::ReportMeasured("BlendModes.SplitSums", splitErr);
  EXPECT_LE(sumErr.Value, Tolerances.BlendCompositionAbs) << sumErr.Where;
  EXPECT_LE(splitErr.Value, Tolerances.BlendCompositionAbs) << splitErr.Where;
}

TEST(BlendModes, ContinuityAcrossBranches)
{
  std::mt19937_64 rng(1905);
  const hov::TransferFunctionSpec spec = RandomSpec(rng, 5, 5);
  const hov::TransferFunction table = RawTable(spec);
  Worst quadToLinear, flatToSloped, limitCrossing;
  for (int trial = 0; trial < 200; ++trial)
  {
    const double sF = hovtest::Uniform(rng, 0, 1), sB = hovtest::Uniform(rng, 0, 1), L = 0.7;
    const std::string where = "trial " + std::to_string(trial);
    // (1) degree 2 with a vanishing quadratic term -> the linear path.
    for (hov::BlendMode mode : { hov::BlendMode::MaximumIntensity, hov::BlendMode::AverageIntensity })
    {
      hov::BlendSettings bs;
      bs.Mode = mode;
      hov::RayBlendState lin, quad;
      hov::AccumulateLinearSegment(lin, bs, table, 0.0, L, sF, sB);
      const double eps2 = 1e-13;
      hov::Polynomial p = hov::Polynomial::FromCoefficients({ sF, (sB - sF) / L - eps2 * L, eps2 });
      hov::AccumulatePolynomialSegment(quad, bs, table, 0.0, L, p);
      quadToLinear.Add(std::max({ std::fabs(lin.Value - quad.Value),
                         std::fabs(lin.WeightedIntegral - quad.WeightedIntegral),
                         std::fabs(lin.InRangeLength - quad.InRangeLength) }),
        where);
    }
    // (2) sB -> sF: the constant branch (ds == 0) vs a tiny slope.
    hov::BlendSettings avg;
    avg.Mode = hov::BlendMode::AverageIntensity;
    hov::RayBlendState flat, sloped;
    hov::AccumulateLinearSegment(flat, avg, table, 0.0, L, sF, sF);
    hov::AccumulateLinearSegment(sloped, avg, table, 0.0, L, sF, sF + 1e-12);
    flatToSloped.Add(std::fabs(flat.WeightedIntegral - sloped.WeightedIntegral), where);
    // (3) the average range's limit moving across the segment's end value.
    hov::BlendSettings below = avg, above = avg;
    below.AverageRange[0] = sF - 1e-12;
    above.AverageRange[0] = sF + 1e-12;
    hov::RayBlendState b, a;
    hov::AccumulateLinearSegment(b, below, table, 0.0, L, sF, sB);
    hov::AccumulateLinearSegment(a, above, table, 0.0, L, sF, sB);
    // Lipschitz in the limit with constant L / |sB - sF|: compare on that scale.
    limitCrossing.Add(std::max(std::fabs(b.WeightedIntegral - a.WeightedIntegral),
                        std::fabs(b.InRangeLength - a.InRangeLength)) * std::fabs(sB - sF) / L,
      where);
  }
  hovtest::ReportMeasured("BlendModes.ContinuityQuadraticToLinear", quadToLinear);
  hovtest::ReportMeasured("BlendModes.ContinuityFlatToSloped", flatToSloped);
  hovtest::ReportMeasured("BlendModes.ContinuityRangeLimit", limitCrossing);
  EXPECT_LE(quadToLinear.Value, Tolerances.BlendContinuityAbs) << quadToLinear.Where;
  EXPECT_LE(flatToSloped.Value, Tolerances.BlendContinuityAbs) << flatToSloped.Where;
  EXPECT_LE(limitCrossing.Value, Tolerances.BlendContinuityAbs) << limitCrossing.Where;
}

TEST(BlendModes, ResolveFollowsVTKSemantics)
{
  // Colour ramp black -> (2, 1, 0.5) (clamped by the GPU: channels > 1 -> 1),
  // opacity 0.2 -> 0.8 over [0, 1]; GPU semantics and a unit distance that the
  // blend modes must ignore (VTK corrects the opacity table only for COMPOSITE).
  hov::TransferFunctionSpec spec;
  spec.Color = { { 0.0, 0.0, 0.0, 0.0 }, { 1.0, 2.0, 1.0, 0.5 } };
  spec.Opacity = { { 0.0, 0.2 }, { 1.0, 0.8 } };
  spec.UnitDistance = 0.01;
  const hov::TransferFunction table = RawTable(spec);
  hov::BlendSettings bs;
  hov::RayBlendState st;
  hov::AccumulateLinearSegment(st, bs, table, 2.0, 1.0, 0.25, 0.75);
  hov::RGBA px = hov::ResolveBlend(st, bs, table);
  // s = 0.75: colour (1.5 -> 1, 0.75, 0.375), a = 0.65; premultiplied.
  EXPECT_NEAR(px.A, 0.65, Tolerances.FewUlpAbs);
  EXPECT_NEAR(px.R, 1.0 * 0.65, Tolerances.FewUlpAbs);
  EXPECT_NEAR(px.G, 0.75 * 0.65, Tolerances.FewUlpAbs);
  EXPECT_NEAR(px.B, 0.375 * 0.65, Tolerances.FewUlpAbs);
  EXPECT_EQ(st.T, 3.0);
  bs.Mode = hov::BlendMode::MinimumIntensity;
  hov::RayBlendState mn;
  hov::AccumulateLinearSegment(mn, bs, table, 2.0, 1.0, 0.25, 0.75);
  px = hov::ResolveBlend(mn, bs, table);
  EXPECT_NEAR(px.A, 0.35, Tolerances.FewUlpAbs);
  EXPECT_NEAR(px.R, 0.5 * 0.35, Tolerances.FewUlpAbs);
  EXPECT_EQ(mn.T, 2.0);
  // Average: a(s) sn(s) with sn = s on [0, 1]: int_0.25^0.75 (0.2 + 0.6 s) s ds / 0.5.
  bs.Mode = hov::BlendMode::AverageIntensity;
  hov::RayBlendState av;
  hov::AccumulateLinearSegment(av, bs, table, 2.0, 1.0, 0.25, 0.75);
  px = hov::ResolveBlend(av, bs, table);
  const double expected = ((0.1 * 0.5625 + 0.2 * 0.421875) - (0.1 * 0.0625 + 0.2 * 0.015625)) / 0.5;
  EXPECT_NEAR(px.R, expected, Tolerances.FewUlpAbs);
  EXPECT_EQ(px.G, px.R);
  EXPECT_EQ(px.A, 1.0); // opaque grey, as the GPU mapper
  // No sample in range: transparent (the GPU discards the fragment).
  bs.AverageRange[0] = 2.0;
  bs.AverageRange[1] = 3.0;
  hov::RayBlendState none;
  hov::AccumulateLinearSegment(none, bs, table, 2.0, 1.0, 0.25, 0.75);
  px = hov::ResolveBlend(none, bs, table);
  EXPECT_EQ(px.A, 0.0);
  EXPECT_EQ(px.R, 0.0);
  // Nothing seen: transparent in every mode.
  EXPECT_EQ(hov::ResolveBlend(hov::RayBlendState(), bs, table).A, 0.0);
}

TEST(BlendModes, DegenerateInputHasNoNaN)
{
  hov::TransferFunctionSpec spec;
  spec.Color = { { 0.0, 1.0, 1.0, 1.0 } };
  spec.Opacity = { { 0.0, 0.5 } };
  const hov::TransferFunction table = RawTable(spec);
  hov::TransferFunction empty; // never built: no nodes
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (hov::BlendMode mode : { hov::BlendMode::MaximumIntensity, hov::BlendMode::MinimumIntensity,
         hov::BlendMode::AverageIntensity })
  {
    hov::BlendSettings bs;
    bs.Mode = mode;
    bs.ScalarRange[0] = bs.ScalarRange[1] = 3.0; // empty range: sn = 0
    bs.AverageRange[0] = nan;
    for (const hov::TransferFunction* tf : std::vector<const hov::TransferFunction*>{ &table, &empty })
    {
      hov::RayBlendState st;
      hov::AccumulateLinearSegment(st, bs, *tf, 0.0, 0.0, 1.0, 2.0);   // zero length
      hov::AccumulateLinearSegment(st, bs, *tf, 0.0, -1.0, 1.0, 2.0);  // negative length
      hov::AccumulateLinearSegment(st, bs, *tf, 0.0, 1.0, nan, 2.0);   // NaN scalar
      hov::AccumulateLinearSegment(st, bs, *tf, 0.0, inf, 1.0, 2.0);   // infinite length
      hov::Polynomial bad = hov::Polynomial::FromCoefficients({ 1.0, nan, 2.0 });
      hov::AccumulatePolynomialSegment(st, bs, *tf, 0.0, 1.0, bad);
      hov::AccumulatePolynomialSegment(st, bs, *tf, 0.0, 1.0, hov::Polynomial::FromCoefficients({ 1.0, 2.0, 3.0 }), nan);
      EXPECT_EQ(st.SkippedSegments, 6);
      EXPECT_FALSE(st.Found);
      hov::RGBA px = hov::ResolveBlend(st, bs, *tf);
      EXPECT_EQ(px.A, 0.0);
      // Valid but extreme input: values near the double range, a huge polynomial.
      hov::AccumulateLinearSegment(st, bs, *tf, 0.0, 1e-300, 1e300, -1e300);
      hov::AccumulateLinearSegment(st, bs, *tf, 1.0, 1e300, 0.5, 0.5);
      hov::AccumulatePolynomialSegment(st, bs, *tf, 2.0, 1e-3, hov::Polynomial::FromCoefficients({ 1e200, -1e250, 1e300 }));
      px = hov::ResolveBlend(st, bs, *tf);
      EXPECT_TRUE(hovtest::AllFinite(px));
      EXPECT_TRUE(std::isfinite(st.Value) && std::isfinite(st.WeightedIntegral) && std::isfinite(st.InRangeLength));
      EXPECT_TRUE(std::isfinite(st.ErrorBound));
    }
  }
}
