// Tests of hovTransferFunction: the piecewise-linear table (breakpoints,
// clamping, jumps) and the linear opacity semantics. The GPU-compatible
// semantics: TestTransferFunctionGPU.cxx; absurd inputs:
// TestTransferFunctionInputs.cxx.

#include "hovTransferFunctionTestCases.h"

#include <gtest/gtest.h>

#include <random>

using namespace hovtest::tf;

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

// Raw extinction values are extinction per unit length: values above 1 are
// kept (only negative values are clamped), unlike opacities.
TEST(TransferFunction, RawExtinctionKeepsValuesAboveOne)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Color = { { 0.0, 1, 1, 1 } };
  spec.Opacity = { { 0.0, 3.5 }, { 1.0, -2.0 } };
  hov::TransferFunction tf;
  std::vector<std::string> messages;
  ASSERT_TRUE(tf.Build(spec, &messages));
  EXPECT_EQ(messages.size(), 1u) << "the negative value is reported";
  hov::SegmentEnd end;
  tf.Evaluate(tf.FindIntervalUpward(0.0), 0.0, false, end);
  EXPECT_EQ(end.Tau, 3.5);
  tf.Evaluate(tf.FindIntervalUpward(0.5), 0.5, false, end);
  EXPECT_NEAR(end.Tau, 1.75, 1e-15);
  spec.Semantics = hov::OpacitySemantics::VTKUnstructured;
  ASSERT_TRUE(tf.Build(spec, &messages));
  tf.Evaluate(tf.FindIntervalUpward(0.0), 0.0, false, end);
  EXPECT_EQ(end.Tau, 1.0) << "an opacity is clamped to 1 (u = 1)";
}

TEST(TransferFunction, IntervalSearchIsExactNextToNodes)
{
  // FindIntervalUpward / Downward must be the largest k with X[k] <= s (< s)
  // for every s, in particular one ulp either side of a node, where the
  // bucket lookup's rounding can land one interval too high (nodes
  // {0, 0.2, 0.5, 0.6, 0.8}, s = 0.2 - ulp: bucket 5 starts in interval 1).
  std::mt19937_64 rng(20261203);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::vector<double>> tables{ { 0.0, 0.2, 0.5, 0.6, 0.8 } };
  for (int t = 0; t < 40; ++t)
  {
    std::vector<double> x{ 0.0 };
    const int n = 2 + static_cast<int>(30 * u(rng));
    for (int k = 1; k < n; ++k)
    {
      x.push_back(x.back() + (u(rng) < 0.3 ? 0.1 : 1e-3 + u(rng)));
    }
    tables.push_back(x);
  }
  // Nodes crowded into a few buckets (a span of 1e300: every node but the
  // last in bucket 0), where the lookup searches instead of walking.
  for (const double far : { 1e300, 1e12 })
  {
    std::vector<double> x{ -1e3 };
    for (int k = 0; k < 3000; ++k)
    {
      x.push_back(k * 1e-3 + (k % 7 == 0 ? 0.0 : 1e-4 * u(rng)));
    }
    x.push_back(far);
    tables.push_back(x);
  }
  int checked = 0;
  for (const std::vector<double>& nodes : tables)
  {
    hov::TransferFunctionSpec spec;
    spec.Semantics = hov::OpacitySemantics::RawExtinction;
    for (const double s : nodes)
    {
      spec.Color.push_back({ s, 0.5, 0.5, 0.5 });
      spec.Opacity.push_back({ s, 0.5 });
    }
    hov::TransferFunction tf;
    tf.Build(spec);
    const std::vector<double>& x = tf.GetNodes();
    ASSERT_EQ(x.size(), nodes.size());
    std::vector<double> probes;
    for (const double node : x)
    {
      probes.insert(probes.end(), { std::nextafter(node, -1e300), node, std::nextafter(node, 1e300) });
    }
    for (int i = 0; i < 200; ++i)
    {
      probes.push_back(x.front() - 0.1 + (x.back() - x.front() + 0.2) * u(rng));
    }
    for (const double s : probes)
    {
      int atOrBelow = -1, below = -1;
      for (size_t k = 0; k < x.size(); ++k)
      {
        atOrBelow += x[k] <= s ? 1 : 0;
        below += x[k] < s ? 1 : 0;
      }
      ASSERT_EQ(tf.FindIntervalUpward(s), atOrBelow) << "s " << s << ", " << x.size() << " nodes";
      ASSERT_EQ(tf.FindIntervalDownward(s), below) << "s " << s << ", " << x.size() << " nodes";
      ++checked;
    }
  }
  EXPECT_GT(checked, 20000);
}
