// Tests of hovRayIntegrator: IntegrateLinearScalar against an independent
// long double integration of the piecewise-linear transfer function along the
// ray (hovKernelTestReference.h: tanh-sinh quadrature over every interval
// between breakpoints, from the raw nodes, not from hov::TransferFunction).

#include "hovRayIntegrator.h"

#include "hovSegmentIntegral.h"
#include "hovTransferFunction.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

using hovtest::Str;
using hovtest::Tolerances;
using hovtest::Worst;

namespace
{
hov::IntegrationSettings Settings(hov::EmissionModel m, hov::SegmentMethod method = hov::SegmentMethod::Exact)
{
  hov::IntegrationSettings s;
  s.Emission = m;
  s.Method = method;
  return s;
}

/// Sorted node positions in [0,1], sometimes with a jump (a repeated X).
std::vector<double> RandomPositions(std::mt19937_64& rng, int n)
{
  std::vector<double> x;
  for (int i = 0; i < n; ++i)
  {
    x.push_back(hovtest::Uniform(rng, 0, 1));
  }
  std::sort(x.begin(), x.end());
  for (size_t i = 1; i < x.size(); ++i)
  {
    if (hovtest::Uniform(rng, 0, 1) < 0.15)
    {
      x[i] = x[i - 1]; // jump
      if (i + 1 < x.size())
      {
        ++i; // at most two nodes at one X
      }
    }
  }
  return x;
}

hov::TransferFunctionSpec RandomSpec(std::mt19937_64& rng, hov::OpacitySemantics semantics)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = semantics;
  spec.UnitDistance = hovtest::LogUniform(rng, 0.2, 5.0);
  spec.EmissionScale = hovtest::LogUniform(rng, 0.5, 2.0);
  for (double x : RandomPositions(rng, 2 + static_cast<int>(rng() % 6)))
  {
    spec.Color.push_back(
      { x, hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1) });
  }
  for (double x : RandomPositions(rng, 2 + static_cast<int>(rng() % 6)))
  {
    const double a = hovtest::Uniform(rng, 0, 1) < 0.15 ? 0.0 : hovtest::Uniform(rng, 0, 1);
    spec.Opacity.push_back({ x, a });
  }
  return spec;
}

/// Distinct node positions of the spec strictly between lo and hi.
int NodesStrictlyInside(const hov::TransferFunctionSpec& spec, double lo, double hi)
{
  std::set<double> xs;
  for (const auto& n : spec.Color)
  {
    xs.insert(n.X);
  }
  for (const auto& n : spec.Opacity)
  {
    xs.insert(n.X);
  }
  return static_cast<int>(std::count_if(xs.begin(), xs.end(), [&](double x) { return x > lo && x < hi; }));
}

/// Colour scale for comparisons: WM colours are <= 1; WVG colour <= L g_max.
double ColorScale(const hov::TransferFunctionSpec& spec, double length, hov::EmissionModel m)
{
  return m == hov::EmissionModel::WilliamsMax ? 1.0 : std::max(1.0, length * spec.EmissionScale / spec.UnitDistance);
}

/// Segment end values straight from the spec (the piece containing @p hint).
hov::SegmentEnd EndFromSpec(const hov::TransferFunctionSpec& spec, double s, double hint, bool emission)
{
  const hovtest::RefTransferFunction r = hovtest::ToReference(spec);
  std::vector<long double> a(r.Opacity.begin(), r.Opacity.end());
  hov::SegmentEnd e;
  const double op = static_cast<double>(hovtest::PwlAt(r.OpacityX, a, s, hint));
  e.Tau = spec.Semantics == hov::OpacitySemantics::VTKUnstructured ? op / spec.UnitDistance : op;
  for (int ch = 0; ch < 3; ++ch)
  {
    std::vector<long double> c;
    for (const auto& n : spec.Color)
    {
      c.push_back(ch == 0 ? n.R : (ch == 1 ? n.G : n.B));
    }
    e.Color[ch] = static_cast<double>(hovtest::PwlAt(r.ColorX, c, s, hint)) *
      (emission ? spec.EmissionScale / spec.UnitDistance : 1.0);
  }
  return e;
}
}

TEST(RayReference, ReproducesClosedForms)
{
  // Constant colour and extinction: A = 1 - e^{-tau L}, C = c A (WM),
  // C = (g/tau)(1 - e^{-tau L}) (WVG).
  hovtest::RefTransferFunction tf;
  tf.ColorX = { 0.0 };
  tf.Color = { { 0.5, 0.25, 1.0 } };
  tf.OpacityX = { 0.0 };
  tf.Opacity = { 0.3 };
  tf.Semantics = hovtest::RefSemantics::Raw;
  const hovtest::RefRGBA m = hovtest::ReferenceRay(tf, 0.2, 0.7, 4.0, hovtest::RefEmission::WilliamsMax);
  const long double tau = 0.3; // the double nearest 0.3, as stored in tf
  const long double A = -std::expm1(-4.0L * tau);
  EXPECT_NEAR(static_cast<double>((m.A - A) / A), 0.0, Tolerances.LongDoubleReferenceRel);
  EXPECT_NEAR(static_cast<double>((m.R - 0.5L * A) / A), 0.0, Tolerances.LongDoubleReferenceRel);
  const hovtest::RefRGBA v = hovtest::ReferenceRay(tf, 0.2, 0.7, 4.0, hovtest::RefEmission::WilhelmsVanGelder);
  EXPECT_NEAR(static_cast<double>((v.B - A / tau) / (A / tau)), 0.0, Tolerances.LongDoubleReferenceRel);
  // GPU semantics, a = 1 - e^{-1} constant, u = 2: tau = 1/2.
  tf.Semantics = hovtest::RefSemantics::GPU;
  tf.Unit = 2.0;
  tf.Opacity = { static_cast<double>(-std::expm1(-1.0L)) };
  const hovtest::RefRGBA g = hovtest::ReferenceRay(tf, 0.0, 1.0, 2.0, hovtest::RefEmission::WilliamsMax);
  EXPECT_NEAR(static_cast<double>(g.A), -std::expm1(-1.0), Tolerances.FewUlpAbs);
}

TEST(RayIntegrator, MatchesReferenceForRandomTransferFunctions)
{
  std::mt19937_64 rng(8675309);
  Worst worstM, worstV;
  int cases = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    const auto semantics = trial % 2 == 0 ? hov::OpacitySemantics::VTKUnstructured : hov::OpacitySemantics::RawExtinction;
    const hov::TransferFunctionSpec spec = RandomSpec(rng, semantics);
    hov::TransferFunction tf;
    std::vector<std::string> messages;
    ASSERT_TRUE(tf.Build(spec, &messages));
    ASSERT_TRUE(messages.empty()) << hovtest::ToString(spec);
    const hovtest::RefTransferFunction ref = hovtest::ToReference(spec);
    for (int r = 0; r < 4; ++r)
    {
      const double s0 = hovtest::Uniform(rng, -0.3, 1.3);
      const double s1 = r == 3 ? s0 : hovtest::Uniform(rng, -0.3, 1.3);
      const double length = hovtest::LogUniform(rng, 0.05, 5.0);
      const std::string where = hovtest::ToString(spec) + " ray s " + Str(s0) + " -> " + Str(s1) + " L=" + Str(length);
      SCOPED_TRACE(where);
      for (auto model : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
      {
        int pieces = -1;
        const hov::RGBA got = hov::IntegrateLinearScalar(tf, s0, s1, length, Settings(model), &pieces);
        const hovtest::RefRGBA want = hovtest::ReferenceRay(ref, s0, s1, length, hovtest::ToReference(model),
          static_cast<long double>(Tolerances.ReferenceQuadratureTol));
        const double e = hovtest::MaxAbsDiff(got, want, ColorScale(spec, length, model));
        (model == hov::EmissionModel::WilliamsMax ? worstM : worstV).Add(e, where);
        EXPECT_LE(e, Tolerances.RayAbs) << "model " << static_cast<int>(model) << " got " << hovtest::ToString(got)
                                        << " ref " << hovtest::ToString(want);
        // One piece per breakpoint interval crossed (jumps add no piece).
        const int expectedPieces = s0 == s1 ? 1 : 1 + NodesStrictlyInside(spec, std::min(s0, s1), std::max(s0, s1));
        EXPECT_EQ(pieces, expectedPieces);
        ++cases;
      }
    }
  }
  hovtest::ReportMeasured("ray vs reference, WM (absolute)", worstM);
  hovtest::ReportMeasured("ray vs reference, WVG (absolute / max(1, L g_max))", worstV);
  hovtest::ReportMeasured("ray cases", cases);
}

TEST(RayIntegrator, SingleIntervalEqualsOneSegment)
{
  std::mt19937_64 rng(4242);
  Worst worst;
  for (int trial = 0; trial < 500; ++trial)
  {
    const auto semantics = trial % 2 == 0 ? hov::OpacitySemantics::VTKUnstructured : hov::OpacitySemantics::RawExtinction;
    const hov::TransferFunctionSpec spec = RandomSpec(rng, semantics);
    hov::TransferFunction tf;
    ASSERT_TRUE(tf.Build(spec));
    // Pick an interval between consecutive distinct nodes, or a clamped region.
    std::vector<double> xs = tf.GetNodes();
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    const int k = static_cast<int>(rng() % (xs.size() + 1)) - 1;
    const double lo = k < 0 ? xs.front() - 1.0 : xs[k];
    const double hi = k + 1 >= static_cast<int>(xs.size()) ? xs.back() + 1.0 : xs[k + 1];
    const double s0 = lo + (hi - lo) * hovtest::Uniform(rng, 0.0, 1.0);
    const double s1 = lo + (hi - lo) * hovtest::Uniform(rng, 0.0, 1.0);
    const double hint = 0.5 * (lo + hi);
    const double length = hovtest::LogUniform(rng, 0.05, 5.0);
    SCOPED_TRACE(hovtest::ToString(spec) + " s " + Str(s0) + " -> " + Str(s1) + " L=" + Str(length));
    for (auto model : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      const bool em = model == hov::EmissionModel::WilhelmsVanGelder;
      int pieces = -1;
      const hov::RGBA got = hov::IntegrateLinearScalar(tf, s0, s1, length, Settings(model), &pieces);
      const hov::RGBA want = hov::IntegrateSegment(length, EndFromSpec(spec, s0, hint, em),
        EndFromSpec(spec, s1, hint, em), model, hov::SegmentMethod::Exact);
      EXPECT_EQ(pieces, 1);
      const double e = hovtest::MaxAbsDiff(got, want) / ColorScale(spec, length, model);
      worst.Add(e, "");
      EXPECT_LE(e, Tolerances.SingleIntervalAbs) << hovtest::ToString(got) << " vs " << hovtest::ToString(want);
    }
  }
  hovtest::ReportMeasured("single interval vs IntegrateSegment (absolute)", worst);
}

TEST(RayIntegrator, ConstantScalar)
{
  // ds = 0: one segment with the table's values at s (right limit at a jump).
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::VTKUnstructured;
  spec.UnitDistance = 0.5;
  spec.Color = { { 0.0, 1, 0, 0 }, { 1.0, 0, 1, 0 } };
  spec.Opacity = { { 0.0, 0.2 }, { 0.5, 0.2 }, { 0.5, 0.6 }, { 1.0, 0.4 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  for (double s : { -1.0, 0.25, 0.5, 0.75, 2.0 })
  {
    SCOPED_TRACE("s=" + Str(s));
    int pieces = -1;
    const hov::RGBA got = hov::IntegrateLinearScalar(tf, s, s, 1.5, Settings(hov::EmissionModel::WilliamsMax), &pieces);
    EXPECT_EQ(pieces, 1);
    const double a = s < 0.5 ? 0.2 : (s > 1.0 ? 0.4 : 0.6 + (0.4 - 0.6) * (s - 0.5) / 0.5);
    const double cg = std::min(std::max(s, 0.0), 1.0);
    EXPECT_NEAR(got.A, -std::expm1(-a / 0.5 * 1.5), Tolerances.FewUlpAbs);
    EXPECT_NEAR(got.G, cg * got.A, Tolerances.FewUlpAbs);
  }
}

TEST(RayIntegrator, ReversedRayHasSameOpacity)
{
  std::mt19937_64 rng(2718);
  Worst worst;
  for (int trial = 0; trial < 500; ++trial)
  {
    hov::TransferFunctionSpec spec = RandomSpec(rng, hov::OpacitySemantics::RawExtinction);
    for (auto& c : spec.Color)
    {
      c.R = c.G = c.B = 0.7; // constant colour: WM colour = 0.7 A both ways
    }
    hov::TransferFunction tf;
    ASSERT_TRUE(tf.Build(spec));
    const double s0 = hovtest::Uniform(rng, -0.3, 1.3), s1 = hovtest::Uniform(rng, -0.3, 1.3);
    const double length = hovtest::LogUniform(rng, 0.05, 5.0);
    SCOPED_TRACE(hovtest::ToString(spec) + " s " + Str(s0) + " <-> " + Str(s1));
    const hov::RGBA f = hov::IntegrateLinearScalar(tf, s0, s1, length, Settings(hov::EmissionModel::WilliamsMax));
    const hov::RGBA b = hov::IntegrateLinearScalar(tf, s1, s0, length, Settings(hov::EmissionModel::WilliamsMax));
    const double e = std::max(std::abs(f.A - b.A), std::abs(f.R - b.R));
    worst.Add(e, "");
    EXPECT_LE(e, Tolerances.FewUlpAbs) << hovtest::ToString(f) << " vs " << hovtest::ToString(b);
    EXPECT_NEAR(f.R, 0.7 * f.A, Tolerances.FewUlpAbs);
  }
  hovtest::ReportMeasured("reversed ray (absolute)", worst);
}

TEST(RayIntegrator, ApproximateMethodKeepsExactOpacity)
{
  std::mt19937_64 rng(31);
  for (int trial = 0; trial < 200; ++trial)
  {
    const hov::TransferFunctionSpec spec = RandomSpec(rng, hov::OpacitySemantics::VTKUnstructured);
    hov::TransferFunction tf;
    ASSERT_TRUE(tf.Build(spec));
    const double s0 = hovtest::Uniform(rng, -0.3, 1.3), s1 = hovtest::Uniform(rng, -0.3, 1.3);
    const double length = hovtest::LogUniform(rng, 0.05, 5.0);
    SCOPED_TRACE(hovtest::ToString(spec) + " s " + Str(s0) + " -> " + Str(s1));
    int pe = 0, pa = 0;
    const hov::RGBA ex = hov::IntegrateLinearScalar(tf, s0, s1, length, Settings(hov::EmissionModel::WilliamsMax), &pe);
    const hov::RGBA ap = hov::IntegrateLinearScalar(tf, s0, s1, length,
      Settings(hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Approximate), &pa);
    EXPECT_EQ(pe, pa);
    EXPECT_NEAR(ap.A, ex.A, Tolerances.FewUlpAbs);
    // Per piece |error| <= (A_piece/2)|c_front - c_back| <= A_piece/2; composited, <= A/2.
    EXPECT_LE(std::abs(ap.R - ex.R), 0.5 * ex.A + Tolerances.FewUlpAbs);
  }
}

TEST(RayIntegrator, DegenerateInputs)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Color = { { 0.0, 0.5, 0.5, 0.5 } };
  spec.Opacity = { { 0.0, 0.5 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  for (double length : { 0.0, -1.0, std::nan("") })
  {
    int pieces = -1;
    const hov::RGBA out = hov::IntegrateLinearScalar(tf, 0.0, 1.0, length, Settings(hov::EmissionModel::WilliamsMax), &pieces);
    EXPECT_EQ(out.A, 0.0) << length;
    EXPECT_EQ(pieces, 0) << length;
  }
  for (double s : { std::nan(""), std::numeric_limits<double>::infinity() })
  {
    int pieces = -1;
    const hov::RGBA out = hov::IntegrateLinearScalar(tf, s, 1.0, 1.0, Settings(hov::EmissionModel::WilliamsMax), &pieces);
    EXPECT_EQ(out.A, 0.0);
    EXPECT_EQ(pieces, 0);
  }
  // A table that was never built has no nodes: nothing, no crash.
  const hov::TransferFunction empty;
  int pieces = -1;
  const hov::RGBA out = hov::IntegrateLinearScalar(empty, 0.0, 1.0, 1.0, Settings(hov::EmissionModel::WilliamsMax), &pieces);
  EXPECT_EQ(out.A, 0.0);
  EXPECT_EQ(pieces, 0);
}

// Regression test. A scalar range so wide that sBack - sFront overflows
// (finite ends, e.g. -1e308 -> 1e308). The node region [0,1] is a negligible
// fraction of the ray: the exact result is the constant low-end half (length
// L/2) in front of the constant high-end half. Before commit a5a5c71,
// 1/ds = 0 put every breakpoint at fraction 0 and the whole length was
// integrated with the high-end values (A = 0.835 instead of 0.632).
TEST(RayIntegrator, HugeScalarRange)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Color = { { 0.0, 1, 0, 0 }, { 1.0, 0, 0, 1 } };
  spec.Opacity = { { 0.0, 0.1 }, { 1.0, 0.9 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  const double length = 2.0;
  hov::SegmentEnd lo{}, hi{};
  lo.Tau = 0.1;
  lo.Color[0] = 1;
  hi.Tau = 0.9;
  hi.Color[2] = 1;
  const hov::RGBA front = hov::IntegrateSegment(length / 2, lo, lo, hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
  const hov::RGBA back = hov::IntegrateSegment(length / 2, hi, hi, hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
  const hov::RGBA expected = hov::Over(front, back);
  for (double big : { 1e300, 1e308 })
  {
    SCOPED_TRACE("s from " + Str(-big) + " to " + Str(big));
    const hov::RGBA got = hov::IntegrateLinearScalar(tf, -big, big, length, Settings(hov::EmissionModel::WilliamsMax));
    EXPECT_TRUE(hovtest::AllFinite(got));
    EXPECT_LE(hovtest::MaxAbsDiff(got, expected), Tolerances.RayAbs)
      << "got " << hovtest::ToString(got) << " expected " << hovtest::ToString(expected);
  }
}

// IntervalOfRange: the interval that holds a scalar range strictly inside;
// -2 as soon as the range reaches a node (where a jump may sit). And the
// search-free integral agrees bit for bit with the general one there.
TEST(RayIntegrator, IntervalOfRangeAndSearchFreeIntegral)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::VTKUnstructured;
  spec.Color = { { 0.0, 1, 0, 0 }, { 1.0, 0, 1, 0 }, { 1.0, 0, 0, 1 }, { 2.0, 1, 1, 1 } }; // jump at 1
  spec.Opacity = { { 0.0, 0.1 }, { 0.5, 0.8 }, { 2.0, 0.3 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  const std::vector<double>& x = tf.GetNodes();
  EXPECT_EQ(hov::IntervalOfRange(tf, 0.1, 0.4), 0);
  EXPECT_EQ(hov::IntervalOfRange(tf, 0.6, 0.9), tf.FindIntervalUpward(0.6));
  EXPECT_EQ(hov::IntervalOfRange(tf, -3.0, -1.0), -1);              // clamped region below
  EXPECT_EQ(hov::IntervalOfRange(tf, 2.5, 7.0), static_cast<int>(x.size()) - 1); // above
  EXPECT_EQ(hov::IntervalOfRange(tf, 0.1, 0.5), -2);                // touches a node
  EXPECT_EQ(hov::IntervalOfRange(tf, 0.9, 1.0), -2);                // touches the jump
  EXPECT_EQ(hov::IntervalOfRange(tf, 0.4, 0.6), -2);                // contains a node
  EXPECT_EQ(hov::IntervalOfRange(tf, 0.6, 0.4), -2);                // empty range
  EXPECT_EQ(hov::IntervalOfRange(tf, std::nan(""), 0.4), -2);

  std::mt19937_64 rng(5);
  for (int i = 0; i < 2000; ++i)
  {
    const double lo = hovtest::Uniform(rng, -1.0, 3.0);
    const double hi = lo + hovtest::LogUniform(rng, 1e-9, 0.3);
    const int k = hov::IntervalOfRange(tf, lo, hi);
    if (k < -1)
    {
      continue;
    }
    const double s0 = hovtest::Uniform(rng, lo, hi), s1 = hovtest::Uniform(rng, lo, hi);
    const double length = hovtest::LogUniform(rng, 1e-3, 10.0);
    for (auto model : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      SCOPED_TRACE("k=" + Str(k) + " s0=" + Str(s0) + " s1=" + Str(s1) + " L=" + Str(length));
      const hov::RGBA general = hov::IntegrateLinearScalar(tf, s0, s1, length, Settings(model));
      const hov::RGBA direct = hov::IntegrateLinearScalarInInterval(tf, k, s0, s1, length, Settings(model));
      EXPECT_EQ(general.R, direct.R);
      EXPECT_EQ(general.G, direct.G);
      EXPECT_EQ(general.B, direct.B);
      EXPECT_EQ(general.A, direct.A);
    }
  }
}
