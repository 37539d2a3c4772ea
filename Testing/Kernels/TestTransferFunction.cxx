// Tests of hovTransferFunction: the piecewise-linear table (breakpoints,
// clamping, jumps, the three opacity semantics, GPU-compatible refinement and
// its error bound, opaque media, absurd inputs).

#include "hovTransferFunction.h"

#include "hovRayIntegrator.h"
#include "hovSegmentIntegral.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using hovtest::Str;
using hovtest::Tolerances;
using hovtest::Worst;

namespace
{
constexpr double Inf = std::numeric_limits<double>::infinity();
constexpr double Eps = std::numeric_limits<double>::epsilon();
const double NaN = std::nan("");

hov::TransferFunctionSpec Spec(std::vector<hov::ColorNode> color, std::vector<hov::OpacityNode> opacity,
  hov::OpacitySemantics semantics, double unit = 1.0)
{
  hov::TransferFunctionSpec s;
  s.Color = std::move(color);
  s.Opacity = std::move(opacity);
  s.Semantics = semantics;
  s.UnitDistance = unit;
  return s;
}

/// Table values at s, walking up (right limit at a node) or down (left limit).
hov::SegmentEnd At(const hov::TransferFunction& tf, double s, bool up = true, bool emission = false)
{
  hov::SegmentEnd e;
  tf.Evaluate(up ? tf.FindIntervalUpward(s) : tf.FindIntervalDownward(s), s, emission, e);
  return e;
}

/// Direct linear interpolation of opacity nodes (no jumps), clamped outside.
double OpacityAt(const std::vector<hov::OpacityNode>& n, double s)
{
  if (s <= n.front().X)
  {
    return n.front().Opacity;
  }
  if (s >= n.back().X)
  {
    return n.back().Opacity;
  }
  size_t i = 0;
  while (n[i + 1].X < s)
  {
    ++i;
  }
  const double w = (s - n[i].X) / (n[i + 1].X - n[i].X);
  return n[i].Opacity + (n[i + 1].Opacity - n[i].Opacity) * w;
}

hov::IntegrationSettings Settings(hov::EmissionModel m)
{
  hov::IntegrationSettings s;
  s.Emission = m;
  s.Method = hov::SegmentMethod::Exact;
  return s;
}

bool Contains(const std::vector<std::string>& messages, const std::string& word)
{
  return std::any_of(messages.begin(), messages.end(),
    [&](const std::string& m) { return m.find(word) != std::string::npos; });
}

std::string Join(const std::vector<std::string>& messages)
{
  std::string out;
  for (const auto& m : messages)
  {
    out += "[" + m + "] ";
  }
  return out;
}
}

// ---------------------------------------------------------------------------
// Breakpoints
// ---------------------------------------------------------------------------

TEST(TransferFunction, BreakpointsAreUnionOfColorAndOpacityNodes)
{
  for (auto sem : { hov::OpacitySemantics::VTKUnstructured, hov::OpacitySemantics::RawExtinction })
  {
    SCOPED_TRACE("semantics " + std::to_string(static_cast<int>(sem)));
    hov::TransferFunction tf;
    std::vector<std::string> messages;
    ASSERT_TRUE(tf.Build(Spec({ { 0.0, 1, 0, 0 }, { 0.3, 0, 1, 0 }, { 1.0, 0, 0, 1 } },
                           { { 0.0, 0.1 }, { 0.5, 0.9 }, { 0.7, 0.2 }, { 1.0, 0.4 } }, sem),
      &messages));
    EXPECT_TRUE(messages.empty()) << Join(messages);
    EXPECT_EQ(tf.GetNodes(), (std::vector<double>{ 0.0, 0.3, 0.5, 0.7, 1.0 }));
    EXPECT_EQ(tf.GetNumberOfRefinementNodes(), 0);
    EXPECT_TRUE(tf.HasExtinction());
    // Values at the nodes: colour interpolated at opacity nodes and vice versa
    // (u = 1, so tau = a in both semantics).
    EXPECT_NEAR(At(tf, 0.5).Tau, 0.9, Tolerances.FewUlpAbs);
    EXPECT_NEAR(At(tf, 0.3).Tau, 0.1 + (0.9 - 0.1) * 0.6, Tolerances.FewUlpAbs);
    EXPECT_NEAR(At(tf, 0.5).Color[2], 0.2 / 0.7, Tolerances.FewUlpAbs);
    EXPECT_NEAR(At(tf, 0.7).Color[1], 0.3 / 0.7, Tolerances.FewUlpAbs);
  }
}

// The opacity peak at s = 0.5 is not a colour node; VTK's unstructured
// integrators keep only the first opacity node of each colour interval and
// see a(s) = 0 on [0,1] (opacity 0): this table keeps the peak. With
// VTK-unstructured semantics tau = a/u, L = 2u and s from 0 to 1, the optical
// depth is (2u)(1/2)/u = 1 and the exact opacity is 1 - e^-1.
TEST(TransferFunction, OpacityPeakBetweenColorNodesIsKept)
{
  const double u = 1.7;
  const double c = 0.6;
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(Spec({ { 0.0, c, c, c }, { 1.0, c, c, c } }, { { 0.0, 0.0 }, { 0.5, 1.0 }, { 1.0, 0.0 } },
    hov::OpacitySemantics::VTKUnstructured, u)));
  EXPECT_EQ(tf.GetNodes(), (std::vector<double>{ 0.0, 0.5, 1.0 }));
  const double expected = -std::expm1(-1.0); // 0.63212055882855767
  for (bool up : { true, false })
  {
    SCOPED_TRACE(up ? "s 0 -> 1" : "s 1 -> 0");
    int pieces = 0;
    const hov::RGBA out = hov::IntegrateLinearScalar(tf, up ? 0.0 : 1.0, up ? 1.0 : 0.0, 2 * u,
      Settings(hov::EmissionModel::WilliamsMax), &pieces);
    EXPECT_EQ(pieces, 2);
    EXPECT_NEAR(out.A, expected, Tolerances.FewUlpAbs);
    EXPECT_NEAR(out.R, c * expected, Tolerances.FewUlpAbs);
    EXPECT_GT(out.A, 0.6); // VTK's own integrator gives 0 here
  }
}

TEST(TransferFunction, ClampedOutsideNodeRange)
{
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(Spec({ { 0.2, 0.1, 0.2, 0.3 }, { 0.8, 0.7, 0.8, 0.9 } }, { { 0.3, 0.25 }, { 0.6, 0.75 } },
    hov::OpacitySemantics::RawExtinction)));
  for (double s : { -1e300, -5.0, 0.0, 0.2 - 1e-12 })
  {
    const hov::SegmentEnd e = At(tf, s);
    EXPECT_EQ(e.Tau, 0.25) << s;
    EXPECT_EQ(e.Color[0], 0.1) << s;
    EXPECT_EQ(e.Color[2], 0.3) << s;
  }
  for (double s : { 0.8 + 1e-12, 1.0, 7.0, 1e300 })
  {
    const hov::SegmentEnd e = At(tf, s, false);
    EXPECT_EQ(e.Tau, 0.75) << s;
    EXPECT_EQ(e.Color[1], 0.8) << s;
  }
  // A ray entirely below the range sees constant values.
  const double length = 3.0;
  int pieces = 0;
  const hov::RGBA out = hov::IntegrateLinearScalar(tf, -3.0, -1.0, length, Settings(hov::EmissionModel::WilliamsMax), &pieces);
  EXPECT_EQ(pieces, 1);
  EXPECT_NEAR(out.A, -std::expm1(-0.25 * length), Tolerances.FewUlpAbs);
  EXPECT_NEAR(out.G, 0.2 * out.A, Tolerances.FewUlpAbs);
  // Entirely above, walking down.
  const hov::RGBA hi = hov::IntegrateLinearScalar(tf, 5.0, 2.0, length, Settings(hov::EmissionModel::WilliamsMax), &pieces);
  EXPECT_EQ(pieces, 1);
  EXPECT_NEAR(hi.A, -std::expm1(-0.75 * length), Tolerances.FewUlpAbs);
  EXPECT_NEAR(hi.B, 0.9 * hi.A, Tolerances.FewUlpAbs);
}

TEST(TransferFunction, JumpsKeepLeftAndRightValues)
{
  const double red[3] = { 1, 0, 0 }, blue[3] = { 0, 0, 1 };
  hov::TransferFunction tf;
  std::vector<std::string> messages;
  ASSERT_TRUE(tf.Build(Spec({ { 0.0, 1, 0, 0 }, { 0.5, 1, 0, 0 }, { 0.5, 0, 0, 1 }, { 1.0, 0, 0, 1 } },
                         { { 0.0, 0.1 }, { 0.5, 0.1 }, { 0.5, 0.9 }, { 1.0, 0.9 } },
                         hov::OpacitySemantics::RawExtinction),
    &messages));
  EXPECT_TRUE(messages.empty()) << Join(messages);
  EXPECT_EQ(tf.GetNodes(), (std::vector<double>{ 0.0, 0.5, 0.5, 1.0 }));
  const hov::SegmentEnd right = At(tf, 0.5, true), left = At(tf, 0.5, false);
  EXPECT_EQ(right.Tau, 0.9);
  EXPECT_EQ(right.Color[2], 1.0);
  EXPECT_EQ(left.Tau, 0.1);
  EXPECT_EQ(left.Color[0], 1.0);
  // Ray across the jump = composite of the two constant halves, both directions.
  const double length = 2.0;
  hov::SegmentEnd r{}, b{};
  r.Tau = 0.1;
  b.Tau = 0.9;
  for (int i = 0; i < 3; ++i)
  {
    r.Color[i] = red[i];
    b.Color[i] = blue[i];
  }
  for (auto model : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
  {
    const hov::RGBA segR = hov::IntegrateSegment(length / 2, r, r, model, hov::SegmentMethod::Exact);
    const hov::RGBA segB = hov::IntegrateSegment(length / 2, b, b, model, hov::SegmentMethod::Exact);
    int pieces = 0;
    const hov::RGBA up = hov::IntegrateLinearScalar(tf, 0.0, 1.0, length, Settings(model), &pieces);
    EXPECT_EQ(pieces, 2);
    EXPECT_LE(hovtest::MaxAbsDiff(up, hov::Over(segR, segB)), Tolerances.FewUlpAbs) << hovtest::ToString(up);
    const hov::RGBA down = hov::IntegrateLinearScalar(tf, 1.0, 0.0, length, Settings(model), &pieces);
    EXPECT_EQ(pieces, 2);
    EXPECT_LE(hovtest::MaxAbsDiff(down, hov::Over(segB, segR)), Tolerances.FewUlpAbs) << hovtest::ToString(down);
  }
  // Three nodes at one X: the first is the left value, the last the right one.
  ASSERT_TRUE(tf.Build(Spec({ { 0.0, 1, 0, 0 }, { 0.5, 1, 0, 0 }, { 0.5, 0, 1, 0 }, { 0.5, 0, 0, 1 }, { 1.0, 0, 0, 1 } },
    { { 0.0, 0.5 } }, hov::OpacitySemantics::RawExtinction)));
  EXPECT_EQ(At(tf, 0.5, false).Color[0], 1.0);
  EXPECT_EQ(At(tf, 0.5, true).Color[2], 1.0);
  EXPECT_EQ(At(tf, 0.5, true).Color[1], 0.0);
}

// ---------------------------------------------------------------------------
// Semantics
// ---------------------------------------------------------------------------

TEST(TransferFunction, LinearSemanticsValues)
{
  std::mt19937_64 rng(77);
  Worst worst;
  for (int trial = 0; trial < 50; ++trial)
  {
    std::vector<hov::OpacityNode> op;
    double x = hovtest::Uniform(rng, -1, 0);
    for (int i = 0; i < 6; ++i)
    {
      op.push_back({ x, hovtest::Uniform(rng, 0, 1) });
      x += hovtest::Uniform(rng, 0.05, 0.5);
    }
    const double u = hovtest::LogUniform(rng, 1e-3, 1e3);
    const double scale = hovtest::LogUniform(rng, 0.1, 10);
    for (auto sem : { hov::OpacitySemantics::VTKUnstructured, hov::OpacitySemantics::RawExtinction })
    {
      hov::TransferFunctionSpec spec = Spec({ { 0.0, 0.2, 0.4, 0.6 }, { 0.5, 0.8, 0.6, 0.4 } }, op, sem, u);
      spec.EmissionScale = scale;
      SCOPED_TRACE(hovtest::ToString(spec));
      hov::TransferFunction tf;
      ASSERT_TRUE(tf.Build(spec));
      EXPECT_EQ(tf.GetSemantics(), sem);
      EXPECT_NEAR(tf.GetEmissionFactor(), scale / u, Tolerances.FewUlpAbs * scale / u);
      for (int j = 0; j < 200; ++j)
      {
        const double s = hovtest::Uniform(rng, -1.5, 3.5);
        const double a = OpacityAt(op, s);
        const double expected = sem == hov::OpacitySemantics::VTKUnstructured ? a / u : a;
        const hov::SegmentEnd e = At(tf, s);
        // Relative to the function's scale max(a)/u (see TableValueRel).
        double amax = 0.0;
        for (const auto& n : op)
        {
          amax = std::max(amax, n.Opacity);
        }
        const double scaleTau = sem == hov::OpacitySemantics::VTKUnstructured ? amax / u : amax;
        const double err = std::abs(e.Tau - expected) / scaleTau;
        worst.Add(err, "s=" + Str(s));
        EXPECT_LE(err, Tolerances.TableValueRel) << "s=" << Str(s) << " tau=" << Str(e.Tau) << " expected " << Str(expected);
        // Wilhelms-Van Gelder emission g = EmissionScale c / u.
        const hov::SegmentEnd g = At(tf, s, true, true);
        const hov::SegmentEnd c = At(tf, s, true, false);
        EXPECT_NEAR(g.Color[1], scale / u * c.Color[1], Tolerances.TableValueRel * scale / u);
        EXPECT_EQ(g.Tau, c.Tau);
      }
    }
  }
  hovtest::ReportMeasured("table tau, linear semantics (relative)", worst);
}

// ---------------------------------------------------------------------------
// GPU-compatible semantics
// ---------------------------------------------------------------------------

namespace
{
/// The opacity functions used for the GPU-compatible checks (max opacity < 1
/// unless stated; the last one reaches 1 at a single node).
std::vector<std::vector<hov::OpacityNode>> GPUOpacities()
{
  return { { { 0.0, 0.0 }, { 1.0, 0.9 } }, { { 0.0, 0.05 }, { 0.3, 0.5 }, { 0.6, 0.99 }, { 1.0, 0.2 } },
    { { 0.0, 0.0 }, { 0.2, 0.0 }, { 0.4, 0.7 }, { 0.41, 0.1 }, { 1.0, 0.95 } },
    { { 0.0, 0.3 }, { 0.5, 0.3 }, { 0.5, 0.8 }, { 1.0, 0.999 } }, { { 0.0, 0.0 }, { 0.5, 1.0 }, { 1.0, 0.0 } } };
}

/// The extinction the refinement approximates: -ln(1 - a)/u with 1 - a
/// clamped at OpaqueClamp (documented).
double ClampedGPUTau(double a, double u)
{
  const double p = 1.0 - a;
  if (p <= hov::TransferFunction::OpaqueClamp)
  {
    return -std::log(hov::TransferFunction::OpaqueClamp) / u;
  }
  return -std::log1p(-a) / u;
}
}

TEST(TransferFunction, GPURefinementMeetsTolerance)
{
  Worst worst;
  for (double u : { 0.01, 1.0, 37.0 })
  {
    for (const auto& op : GPUOpacities())
    {
      int previousNodes = -1;
      // 1e-8 only where the opacity stays below 0.999: see
      // GPURefinementNearOpacityOne for what happens at a = 1.
      double maxOpacity = 0.0;
      for (const auto& n : op)
      {
        maxOpacity = std::max(maxOpacity, n.Opacity);
      }
      std::vector<double> tolerances = { 1e-2, 1e-3, 1e-4, 1e-6 };
      if (maxOpacity < 0.999)
      {
        tolerances.push_back(1e-8);
      }
      for (double tol : tolerances)
      {
        hov::TransferFunctionSpec spec = Spec({ { 0.0, 1, 1, 1 } }, op, hov::OpacitySemantics::GPUCompatible, u);
        spec.GPUTolerance = tol;
        SCOPED_TRACE(hovtest::ToString(spec));
        hov::TransferFunction tf;
        std::vector<std::string> messages;
        ASSERT_TRUE(tf.Build(spec, &messages));
        EXPECT_TRUE(messages.empty()) << Join(messages);
        EXPECT_GT(tf.GetNumberOfRefinementNodes(), previousNodes) << "more nodes for a smaller tolerance";
        previousNodes = tf.GetNumberOfRefinementNodes();
        // Dense sampling, including both sides of every node of the spec.
        std::vector<double> ss;
        for (int j = 0; j <= 20000; ++j)
        {
          ss.push_back(-0.1 + 1.2 * j / 20000.0);
        }
        for (const auto& n : op)
        {
          ss.push_back(std::nextafter(n.X, -1.0));
          ss.push_back(std::nextafter(n.X, 2.0));
        }
        double worstHere = 0.0;
        std::string where;
        for (double s : ss)
        {
          // Left/right limits differ at a jump of the spec: compare each side
          // with the spec's value on that side.
          for (bool up : { true, false })
          {
            double a = OpacityAt(op, s);
            if (op.size() == 4 && op[1].X == op[2].X && s == 0.5)
            {
              a = up ? 0.8 : 0.3;
            }
            const double exact = ClampedGPUTau(a, u);
            const double got = At(tf, s, up).Tau;
            // a(s) itself is only known to ~2 eps absolute (interpolation, in
            // the table and here): allow that much, propagated through
            // dtau/da = 1/((1-a)u), on top of the tolerance.
            const double noise = 8 * Eps / (std::max(1.0 - a, hov::TransferFunction::OpaqueClamp) * u);
            const double err = std::max(0.0, std::abs(got - exact) - noise) / std::max(exact, 1e-300);
            if (err > worstHere)
            {
              worstHere = err;
              where = "s=" + Str(s) + " a=" + Str(a) + " got=" + Str(got) + " exact=" + Str(exact);
            }
          }
        }
        worst.Add(worstHere / tol, where + " tol=" + Str(tol) + " u=" + Str(u));
        EXPECT_LE(worstHere, tol * Tolerances.RefinementSlack) << where;
      }
    }
  }
  hovtest::ReportMeasured("GPU refinement: max relative tau error / GPUTolerance", worst);
}

// Regression test. Opacity 1 at a node and a tolerance of 1e-7. Before commit
// a5a5c71 the refinement sampled p = 1 - a near a = 1 by cancellation (p ~ 1e-11
// carries a relative rounding noise ~1e-5, i.e. ~4e-7 relative in tau = -ln p),
// so the chord test never passed there and bisection ran down to ulp spacing:
// ~185000 of the 200000-node budget landed where 1e-12 < 1 - a < 1e-10, the
// budget ran out, and the intervals refined afterwards (here the whole right
// half of the tent) were not refined at all (relative tau error 27 at
// s = 0.99998). The tolerance must be met with a sane node count.
TEST(TransferFunction, GPURefinementNearOpacityOne)
{
  const double u = 1.0;
  const std::vector<hov::OpacityNode> op = { { 0.0, 0.0 }, { 0.5, 1.0 }, { 1.0, 0.0 } };
  for (double tol : { 1e-6, 1e-7 })
  {
    hov::TransferFunctionSpec spec = Spec({ { 0.0, 1, 1, 1 } }, op, hov::OpacitySemantics::GPUCompatible, u);
    spec.GPUTolerance = tol;
    SCOPED_TRACE(hovtest::ToString(spec));
    hov::TransferFunction tf;
    std::vector<std::string> messages;
    ASSERT_TRUE(tf.Build(spec, &messages));
    EXPECT_TRUE(messages.empty()) << Join(messages);
    // ~ln(1e12)/sqrt(8 tol ln(1e12)) pieces per side would do; allow 10x that.
    const double needed = 2 * std::log(1e12) / std::sqrt(8 * tol * std::log(1e12));
    EXPECT_LT(tf.GetNumberOfRefinementNodes(), 10 * needed);
    hovtest::ReportMeasured("refinement nodes, tent to a = 1, tol " + Str(tol), tf.GetNumberOfRefinementNodes());
    double worst = 0.0;
    std::string where;
    for (int j = 1; j < 2000; ++j)
    {
      const double s = 0.55 + 0.45 * j / 2000.0; // right half, a <= 0.9
      const double a = OpacityAt(op, s);
      const double exact = ClampedGPUTau(a, u);
      const double err = std::abs(At(tf, s).Tau - exact) / exact;
      if (err > worst)
      {
        worst = err;
        where = "s=" + Str(s) + " got " + Str(At(tf, s).Tau) + " exact " + Str(exact);
      }
    }
    EXPECT_LE(worst, tol * Tolerances.RefinementSlack) << where;
  }
}

TEST(TransferFunction, GPUWholeRayWithinStatedBound)
{
  // IntegrateLinearScalar with the refined table against a long double
  // quadrature of the true tau(s) = -ln(1 - a(s))/u (Williams-Max). The
  // stated bound: opacity error <= GPUTolerance/e, colour error <=
  // 2 GPUTolerance max|c|; and the error must shrink with the tolerance.
  const double u = 0.8;
  const std::vector<hov::ColorNode> color = { { 0.0, 0.9, 0.2, 0.1 }, { 0.45, 0.1, 0.8, 0.3 }, { 1.0, 0.3, 0.3, 1.0 } };
  struct Ray
  {
    double S0, S1, L;
  };
  const std::vector<Ray> rays = { { 0.0, 1.0, 1.5 }, { 1.0, 0.0, 1.5 }, { -0.2, 1.2, 3.0 }, { 0.1, 0.35, 0.5 },
    { 0.9, 0.3, 4.0 }, { 0.5, 0.5, 2.0 } };
  Worst ratio;
  const auto opacities = GPUOpacities();
  for (size_t o = 0; o < opacities.size(); ++o)
  {
    double previous = Inf;
    for (double tol : { 1e-2, 1e-3, 1e-4, 1e-5, 1e-6 })
    {
      hov::TransferFunctionSpec spec = Spec(color, opacities[o], hov::OpacitySemantics::GPUCompatible, u);
      spec.GPUTolerance = tol;
      SCOPED_TRACE(hovtest::ToString(spec));
      hov::TransferFunction tf;
      ASSERT_TRUE(tf.Build(spec));
      const hovtest::RefTransferFunction ref = hovtest::ToReference(spec);
      double worstHere = 0.0;
      for (const Ray& r : rays)
      {
        SCOPED_TRACE("ray s " + Str(r.S0) + " -> " + Str(r.S1) + " L=" + Str(r.L));
        const hov::RGBA got = hov::IntegrateLinearScalar(tf, r.S0, r.S1, r.L, Settings(hov::EmissionModel::WilliamsMax));
        const hovtest::RefRGBA want = hovtest::ReferenceRay(ref, r.S0, r.S1, r.L, hovtest::RefEmission::WilliamsMax);
        const double eA = std::fabs(static_cast<double>(got.A - want.A));
        const double eC = std::max({ std::fabs(static_cast<double>(got.R - want.R)),
          std::fabs(static_cast<double>(got.G - want.G)), std::fabs(static_cast<double>(got.B - want.B)) });
        const double maxC = 1.0;
        EXPECT_LE(eA, tol / std::exp(1.0) + Tolerances.GPURayExtraAbs)
          << "A got " << Str(got.A) << " ref " << Str(static_cast<double>(want.A));
        EXPECT_LE(eC, 2 * tol * maxC + Tolerances.GPURayExtraAbs)
          << "C got " << hovtest::ToString(got) << " ref " << hovtest::ToString(want);
        ratio.Add(std::max(eA * std::exp(1.0), eC / 2) / tol,
          "opacity set " + std::to_string(o) + " tol=" + Str(tol) + " s " + Str(r.S0) + "->" + Str(r.S1));
        worstHere = std::max(worstHere, std::max(eA, eC));
      }
      EXPECT_LT(worstHere, previous) << "error did not decrease with the tolerance (tol=" << tol << ")";
      previous = worstHere;
      std::cout << "[measured] GPU whole-ray opacity set " << o << " tol=" << tol << ": max |error| = " << worstHere
                << std::endl;
    }
  }
  hovtest::ReportMeasured("GPU whole ray: max(e A err, C err / 2) / GPUTolerance (bound 1)", ratio);
}

TEST(TransferFunction, GPUOpaqueIntervalIsOpaque)
{
  // Opacity exactly 1 on [0.4, 0.6]: an opaque medium.
  const double u = 0.5;
  const std::vector<hov::OpacityNode> op = { { 0.0, 0.0 }, { 0.4, 1.0 }, { 0.6, 1.0 }, { 1.0, 0.0 } };
  const std::vector<hov::ColorNode> color = { { 0.0, 0.2, 0.4, 0.6 }, { 1.0, 0.9, 0.7, 0.5 } };
  hov::TransferFunctionSpec spec = Spec(color, op, hov::OpacitySemantics::GPUCompatible, u);
  spec.GPUTolerance = 1e-6;
  hov::TransferFunction tf;
  std::vector<std::string> messages;
  ASSERT_TRUE(tf.Build(spec, &messages));
  EXPECT_TRUE(messages.empty()) << Join(messages);
  EXPECT_EQ(At(tf, 0.5).Tau, Inf);
  EXPECT_EQ(At(tf, 0.4, true).Tau, Inf);
  EXPECT_TRUE(std::isfinite(At(tf, 0.4, false).Tau)); // left limit: clamped log
  const hovtest::RefTransferFunction ref = hovtest::ToReference(spec);
  for (auto model : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
  {
    for (const auto& r : std::vector<std::pair<double, double>>{ { 0.0, 1.0 }, { 1.0, 0.0 }, { 0.5, 0.9 }, { 0.45, 0.55 } })
    {
      SCOPED_TRACE("model " + std::to_string(static_cast<int>(model)) + " s " + Str(r.first) + " -> " + Str(r.second));
      int pieces = 0;
      const hov::RGBA out = hov::IntegrateLinearScalar(tf, r.first, r.second, 2.0, Settings(model), &pieces);
      EXPECT_TRUE(hovtest::AllFinite(out)) << hovtest::ToString(out);
      EXPECT_EQ(out.A, 1.0);
      const hovtest::RefRGBA want = hovtest::ReferenceRay(ref, r.first, r.second, 2.0, hovtest::ToReference(model));
      const double scale = model == hov::EmissionModel::WilliamsMax ? 1.0 : 2.0 / u;
      EXPECT_LE(hovtest::MaxAbsDiff(out, want, scale), 2 * spec.GPUTolerance + Tolerances.GPURayExtraAbs)
        << hovtest::ToString(out) << " ref " << hovtest::ToString(want);
      if (r.first >= 0.4 && r.first <= 0.6 && model == hov::EmissionModel::WilliamsMax)
      {
        // Starting inside the opaque medium: one piece, the front colour.
        EXPECT_EQ(pieces, 1);
        EXPECT_NEAR(out.R, 0.2 + 0.7 * r.first, Tolerances.FewUlpAbs);
      }
    }
  }
}

TEST(TransferFunction, GPUOpacityOneAtSingleNodeIsFinite)
{
  const double u = 1.0;
  const std::vector<hov::OpacityNode> op = { { 0.0, 0.0 }, { 0.5, 1.0 }, { 1.0, 0.0 } };
  hov::TransferFunctionSpec spec = Spec({ { 0.0, 1, 0.5, 0.25 } }, op, hov::OpacitySemantics::GPUCompatible, u);
  spec.GPUTolerance = 1e-5;
  hov::TransferFunction tf;
  std::vector<std::string> messages;
  ASSERT_TRUE(tf.Build(spec, &messages));
  EXPECT_TRUE(messages.empty()) << Join(messages);
  const double tauPeak = At(tf, 0.5).Tau;
  EXPECT_TRUE(std::isfinite(tauPeak));
  EXPECT_NEAR(tauPeak, -std::log(hov::TransferFunction::OpaqueClamp) / u, Tolerances.TableValueRel * tauPeak);
  for (const auto& nodeValue : tf.GetNodes())
  {
    EXPECT_TRUE(std::isfinite(nodeValue));
  }
  const hovtest::RefTransferFunction ref = hovtest::ToReference(spec);
  for (double length : { 0.1, 1.0, 10.0 })
  {
    SCOPED_TRACE("L=" + Str(length));
    const hov::RGBA out = hov::IntegrateLinearScalar(tf, 0.0, 1.0, length, Settings(hov::EmissionModel::WilliamsMax));
    EXPECT_TRUE(hovtest::AllFinite(out)) << hovtest::ToString(out);
    EXPECT_LT(out.A, 1.0);
    // int_0^1 -ln(1 - a(s)) ds = 1 for the tent: A = 1 - e^{-L/u}.
    EXPECT_NEAR(out.A, -std::expm1(-length / u), spec.GPUTolerance / std::exp(1.0) + Tolerances.GPURayExtraAbs);
    const hovtest::RefRGBA want = hovtest::ReferenceRay(ref, 0.0, 1.0, length, hovtest::RefEmission::WilliamsMax);
    EXPECT_LE(hovtest::MaxAbsDiff(out, want, 1.0), 2 * spec.GPUTolerance + Tolerances.GPURayExtraAbs)
      << hovtest::ToString(out) << " ref " << hovtest::ToString(want);
  }
}

// ---------------------------------------------------------------------------
// Absurd inputs: messages and finite results
// ---------------------------------------------------------------------------

namespace
{
/// Rays through @p tf must give finite, valid results.
void ExpectFiniteRays(const hov::TransferFunction& tf)
{
  for (auto model : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
  {
    for (const auto& r : std::vector<std::array<double, 3>>{ { 0.0, 1.0, 1.0 }, { 1.0, -1.0, 3.0 }, { 0.5, 0.5, 1.0 },
           { -1e300, 1e300, 1.0 } })
    {
      const hov::RGBA out = hov::IntegrateLinearScalar(tf, r[0], r[1], r[2], Settings(model));
      EXPECT_TRUE(hovtest::AllFinite(out)) << "ray " << r[0] << " -> " << r[1] << ": " << hovtest::ToString(out);
      EXPECT_GE(out.A, 0.0);
      EXPECT_LE(out.A, 1.0);
    }
  }
}
}

TEST(TransferFunction, AbsurdInputsGiveMessagesAndFiniteResults)
{
  const std::vector<hov::ColorNode> goodColor = { { 0.0, 0.5, 0.5, 0.5 }, { 1.0, 1.0, 0.0, 0.0 } };
  const std::vector<hov::OpacityNode> goodOpacity = { { 0.0, 0.2 }, { 1.0, 0.6 } };
  struct Case
  {
    std::string Name;
    hov::TransferFunctionSpec Spec;
    std::string Expected; // a word of the expected message
  };
  std::vector<Case> cases;
  for (auto sem : { hov::OpacitySemantics::GPUCompatible, hov::OpacitySemantics::VTKUnstructured,
         hov::OpacitySemantics::RawExtinction })
  {
    const std::string tag = " semantics " + std::to_string(static_cast<int>(sem));
    cases.push_back({ "NaN colour X" + tag, Spec({ { NaN, 1, 1, 1 }, { 0.5, 1, 0, 0 } }, goodOpacity, sem), "colour" });
    cases.push_back({ "Inf colour value" + tag, Spec({ { 0.0, Inf, 1, 1 }, { 0.5, 1, 0, 0 } }, goodOpacity, sem), "colour" });
    cases.push_back({ "negative colour" + tag, Spec({ { 0.0, -1, 1, 1 } }, goodOpacity, sem), "negative" });
    cases.push_back({ "NaN opacity X" + tag, Spec(goodColor, { { NaN, 0.5 }, { 1.0, 0.5 } }, sem), "opacity" });
    cases.push_back({ "NaN opacity value" + tag, Spec(goodColor, { { 0.0, NaN }, { 1.0, 0.5 } }, sem), "opacity" });
    cases.push_back({ "opacity > 1" + tag, Spec(goodColor, { { 0.0, 1.5 }, { 1.0, 0.5 } }, sem), "clamped" });
    cases.push_back({ "opacity < 0" + tag, Spec(goodColor, { { 0.0, -0.5 }, { 1.0, 0.5 } }, sem), "clamped" });
    cases.push_back({ "no colour nodes" + tag, Spec({}, goodOpacity, sem), "colour" });
    cases.push_back({ "no opacity nodes" + tag, Spec(goodColor, {}, sem), "opacity" });
    cases.push_back({ "all NaN" + tag, Spec({ { NaN, NaN, NaN, NaN } }, { { NaN, NaN } }, sem), "dropped" });
    for (double u : { 0.0, -1.0, NaN, Inf, -Inf })
    {
      cases.push_back({ "unit distance " + Str(u) + tag, Spec(goodColor, goodOpacity, sem, u), "unit distance" });
    }
    if (sem == hov::OpacitySemantics::GPUCompatible)
    {
      for (double tol : { 0.0, -1.0, NaN, 1.0, 1e-300 })
      {
        // Constant opacity: nothing to refine, so a tolerance clamped to
        // 1e-14 does not spend the whole node budget (GPURefinementBudget).
        hov::TransferFunctionSpec s = Spec(goodColor, { { 0.0, 0.3 }, { 1.0, 0.3 } }, sem);
        s.GPUTolerance = tol;
        cases.push_back({ "GPU tolerance " + Str(tol), s, "tolerance" });
      }
    }
  }
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.Name);
    hov::TransferFunction tf;
    std::vector<std::string> messages;
    tf.Build(c.Spec, &messages);
    EXPECT_TRUE(Contains(messages, c.Expected)) << "messages: " << Join(messages);
    EXPECT_GT(tf.GetNumberOfNodes(), 0);
    for (double x : tf.GetNodes())
    {
      EXPECT_TRUE(std::isfinite(x));
    }
    EXPECT_TRUE(std::isfinite(tf.GetEmissionFactor()));
    ExpectFiniteRays(tf);
    // Building without a message list must not crash either.
    hov::TransferFunction quiet;
    quiet.Build(c.Spec);
    ExpectFiniteRays(quiet);
  }
  // Empty opacity: transparent.
  {
    hov::TransferFunction tf;
    tf.Build(Spec(goodColor, {}, hov::OpacitySemantics::VTKUnstructured));
    EXPECT_FALSE(tf.HasExtinction());
    const hov::RGBA out = hov::IntegrateLinearScalar(tf, 0.0, 1.0, 5.0, Settings(hov::EmissionModel::WilliamsMax));
    EXPECT_EQ(out.A, 0.0);
    EXPECT_EQ(out.R, 0.0);
  }
  // Extreme but valid unit distances: finite results, and the expected depth.
  for (double u : { 1e-300, 1e300 })
  {
    for (auto sem : { hov::OpacitySemantics::GPUCompatible, hov::OpacitySemantics::VTKUnstructured })
    {
      SCOPED_TRACE("u=" + Str(u) + " semantics " + std::to_string(static_cast<int>(sem)));
      hov::TransferFunction tf;
      std::vector<std::string> messages;
      tf.Build(Spec(goodColor, goodOpacity, sem, u), &messages);
      ExpectFiniteRays(tf);
      const hov::RGBA out = hov::IntegrateLinearScalar(tf, 0.5, 0.5, 1.0, Settings(hov::EmissionModel::WilliamsMax));
      const double tau = sem == hov::OpacitySemantics::GPUCompatible ? -std::log1p(-0.4) / u : 0.4 / u;
      EXPECT_NEAR(out.A, -std::expm1(-tau), Tolerances.FewUlpAbs);
    }
  }
  // Unsorted input is sorted; repeated identical nodes are merged.
  {
    hov::TransferFunction tf;
    std::vector<std::string> messages;
    tf.Build(Spec({ { 1.0, 0, 0, 1 }, { 0.0, 1, 0, 0 }, { 0.0, 1, 0, 0 } }, { { 1.0, 0.5 }, { 0.0, 0.1 } },
               hov::OpacitySemantics::RawExtinction),
      &messages);
    EXPECT_EQ(tf.GetNodes(), (std::vector<double>{ 0.0, 1.0 }));
    EXPECT_NEAR(At(tf, 0.25).Tau, 0.2, Tolerances.FewUlpAbs);
    EXPECT_NEAR(At(tf, 0.25).Color[0], 0.75, Tolerances.FewUlpAbs);
  }
}

TEST(TransferFunction, GPURefinementBudget)
{
  // A tolerance at the clamp (1e-14) on a function reaching a = 1 needs more
  // than MaxRefinementNodes: Build() stops at the budget and says so.
  hov::TransferFunctionSpec spec = Spec({ { 0.0, 1, 1, 1 } }, { { 0.0, 0.0 }, { 1.0, 1.0 }, { 2.0, 1.0 } },
    hov::OpacitySemantics::GPUCompatible);
  spec.GPUTolerance = 1e-14;
  hov::TransferFunction tf;
  std::vector<std::string> messages;
  ASSERT_TRUE(tf.Build(spec, &messages));
  // A depth-first bisection adds the midpoint of every piece it is inside when
  // the budget runs out, so the count may pass the budget by up to its
  // recursion depth (64): the kernels before commit a5a5c71 stopped at 200022 for
  // a budget of 200000.
  EXPECT_LE(tf.GetNumberOfRefinementNodes(), hov::TransferFunction::MaxRefinementNodes + 64);
  hovtest::ReportMeasured("refinement nodes at budget exhaustion (budget " +
      std::to_string(hov::TransferFunction::MaxRefinementNodes) + ")",
    tf.GetNumberOfRefinementNodes());
  if (tf.GetNumberOfRefinementNodes() >= hov::TransferFunction::MaxRefinementNodes)
  {
    EXPECT_TRUE(Contains(messages, "budget")) << Join(messages);
  }
  EXPECT_TRUE(Contains(messages, "budget") || Contains(messages, "tolerance")) << Join(messages);
  ExpectFiniteRays(tf);
}
