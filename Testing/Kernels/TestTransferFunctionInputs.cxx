// Tests of hovTransferFunction with absurd inputs (NaN, Inf, negative or
// missing nodes, invalid unit distances and tolerances, an exhausted
// refinement budget): Build() reports them and every ray stays finite.

#include "hovTransferFunctionTestCases.h"

#include <gtest/gtest.h>

#include <array>

using namespace hovtest::tf;

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
    if (sem != hov::OpacitySemantics::RawExtinction) // raw values are extinctions: > 1 is fine
    {
      cases.push_back({ "opacity > 1" + tag, Spec(goodColor, { { 0.0, 1.5 }, { 1.0, 0.5 } }, sem), "clamped" });
    }
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
  const hov::TransferFunctionSpec spec =
    GPUSpec({ { 0.0, 1, 1, 1 } }, { { 0.0, 0.0 }, { 1.0, 1.0 }, { 2.0, 1.0 } }, 1.0, 1e-14);
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
