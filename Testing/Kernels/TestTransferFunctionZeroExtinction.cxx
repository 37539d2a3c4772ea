// Tests of hov::TransferFunction::ZeroExtinctionOver, the test by which the
// CPU path skips cells that cannot absorb (hovCellRecords.cxx): it must be
// sound (true only where tau is zero at every scalar of the range, as
// Evaluate() computes it, in every semantics, next to jumps and beyond the
// ends) and not vacuous (true inside zero regions), and false for NaN,
// infinite or reversed ranges and for an empty table. Oracle: Evaluate() at
// the range's ends, at every node inside it, at both limits of each such node
// and at random scalars between.

#include "hovTransferFunctionTestCases.h"

#include <gtest/gtest.h>

#include <algorithm> // std::max, std::swap
#include <random>

using namespace hovtest::tf;

namespace
{
/// tau at @p s from the left and from the right (both limits at a jump).
double MaxTauAt(const hov::TransferFunction& tf, double s)
{
  return std::max(At(tf, s, true).Tau, At(tf, s, false).Tau);
}

/// Largest tau over [lo, hi] seen by the oracle (see the file doc).
double MaxTauOver(const hov::TransferFunction& tf, double lo, double hi, std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = std::max(MaxTauAt(tf, lo), MaxTauAt(tf, hi));
  for (double x : tf.GetNodes())
  {
    if (lo <= x && x <= hi)
    {
      worst = std::max(worst, MaxTauAt(tf, x));
    }
  }
  for (int i = 0; i < 64; ++i)
  {
    worst = std::max(worst, MaxTauAt(tf, lo + u(rng) * (hi - lo)));
  }
  return worst;
}

/// Opacity 0 on [0.2, 0.45] (nodes 0.2, 0.3, 0.45) and from 0.9 on, a jump
/// at 0.6 from 0 (left) to 0.5 (right), positive elsewhere.
std::vector<hov::OpacityNode> ZeroRegions()
{
  return { { 0.0, 0.4 }, { 0.2, 0.0 }, { 0.3, 0.0 }, { 0.45, 0.0 }, { 0.5, 0.3 }, { 0.55, 0.0 },
    { 0.6, 0.0 }, { 0.6, 0.5 }, { 0.8, 0.7 }, { 0.9, 0.0 }, { 1.0, 0.0 } };
}
}

TEST(TransferFunctionZeroExtinction, FixedRanges)
{
  for (auto sem : { hov::OpacitySemantics::GPUCompatible, hov::OpacitySemantics::VTKUnstructured,
         hov::OpacitySemantics::RawExtinction })
  {
    hov::TransferFunction tf;
    ASSERT_TRUE(tf.Build(Spec({ { 0.0, 1, 0, 0 }, { 0.37, 0, 1, 0 }, { 1.0, 0, 0, 1 } },
      ZeroRegions(), sem, 0.5)));
    SCOPED_TRACE(static_cast<int>(sem));
    ASSERT_TRUE(tf.HasZeroExtinctionNode());
    // Inside the zero region, across a colour node (0.37) and the zero node 0.3.
    EXPECT_TRUE(tf.ZeroExtinctionOver(0.21, 0.44));
    EXPECT_TRUE(tf.ZeroExtinctionOver(0.25, 0.25));
    // An end on a node reads the next node out: 0.2 has tau > 0 to its left.
    EXPECT_FALSE(tf.ZeroExtinctionOver(0.2, 0.3));
    EXPECT_FALSE(tf.ZeroExtinctionOver(0.3, 0.45));
    // Into a positive interval.
    EXPECT_FALSE(tf.ZeroExtinctionOver(0.21, 0.46));
    EXPECT_FALSE(tf.ZeroExtinctionOver(0.19, 0.3));
    // Up to a jump whose left value is 0: the jump node has tau > 0 on its right.
    EXPECT_TRUE(tf.ZeroExtinctionOver(0.56, 0.59));
    EXPECT_FALSE(tf.ZeroExtinctionOver(0.56, 0.6));
    // Beyond the last node: clamped to its zero tau.
    EXPECT_TRUE(tf.ZeroExtinctionOver(0.95, 1e30));
    EXPECT_TRUE(tf.ZeroExtinctionOver(2.0, 3.0));
    EXPECT_FALSE(tf.ZeroExtinctionOver(0.85, 3.0));
    // Below the first node: clamped to its tau > 0.
    EXPECT_FALSE(tf.ZeroExtinctionOver(-3.0, -2.0));
    // Not a range.
    EXPECT_FALSE(tf.ZeroExtinctionOver(0.3, 0.25));
    EXPECT_FALSE(tf.ZeroExtinctionOver(NaN, 0.25));
    EXPECT_FALSE(tf.ZeroExtinctionOver(0.25, NaN));
    EXPECT_FALSE(tf.ZeroExtinctionOver(2.0, Inf));
    EXPECT_FALSE(tf.ZeroExtinctionOver(-Inf, 0.25));
  }
  // Opaque: a = 1 on [0.6, 1] (tau = +inf there), 0 below 0.5.
  hov::TransferFunction opaque;
  ASSERT_TRUE(opaque.Build(Spec({ { 0.0, 1, 1, 1 } },
    { { 0.0, 0.0 }, { 0.5, 0.0 }, { 0.6, 1.0 }, { 1.0, 1.0 } },
    hov::OpacitySemantics::GPUCompatible)));
  EXPECT_TRUE(opaque.ZeroExtinctionOver(0.1, 0.4));
  EXPECT_FALSE(opaque.ZeroExtinctionOver(0.1, 0.55));
  EXPECT_FALSE(opaque.ZeroExtinctionOver(0.7, 0.8));
  EXPECT_FALSE(opaque.ZeroExtinctionOver(2.0, 3.0));
  // No zero node, and no table.
  hov::TransferFunction positive;
  ASSERT_TRUE(positive.Build(Spec({ { 0.0, 1, 1, 1 } }, { { 0.0, 0.1 }, { 1.0, 0.2 } },
    hov::OpacitySemantics::VTKUnstructured)));
  EXPECT_FALSE(positive.HasZeroExtinctionNode());
  EXPECT_FALSE(positive.ZeroExtinctionOver(0.2, 0.3));
  const hov::TransferFunction empty;
  EXPECT_FALSE(empty.HasZeroExtinctionNode());
  EXPECT_FALSE(empty.ZeroExtinctionOver(0.2, 0.3));
}

TEST(TransferFunctionZeroExtinction, SoundOnRandomTables)
{
  // Random tables with runs of zero opacity (some nodes repeated: jumps; some
  // opacities 1: opaque intervals, tau = +inf, in the GPU-compatible
  // semantics), random ranges from below the first node to beyond the last,
  // some ends exactly on nodes: every range called zero has tau == 0
  // wherever the oracle looks, and the zero answers are many.
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int zero = 0, ranges = 0;
  for (int table = 0; table < 300; ++table)
  {
    std::vector<hov::OpacityNode> opacity;
    double x = -1.0 + u(rng);
    const int n = 2 + static_cast<int>(12 * u(rng));
    for (int i = 0; i < n; ++i)
    {
      const double a = u(rng) < 0.5 ? 0.0 : (u(rng) < 0.2 ? 1.0 : u(rng));
      opacity.push_back({ x, a });
      if (u(rng) < 0.15)
      {
        opacity.push_back({ x, u(rng) < 0.5 ? 0.0 : u(rng) }); // a jump
      }
      x += 0.05 + 0.3 * u(rng);
    }
    const auto sem = static_cast<hov::OpacitySemantics>(table % 3);
    hov::TransferFunction tf;
    ASSERT_TRUE(tf.Build(Spec({ { 0.0, 0.2, 0.5, 0.9 } }, opacity, sem, 0.7)));
    const std::vector<double>& nodes = tf.GetNodes();
    for (int r = 0; r < 40; ++r)
    {
      auto pick = [&]() {
        return u(rng) < 0.3 ? nodes[static_cast<size_t>(u(rng) * nodes.size())]
                            : -1.5 + (x + 2.0) * u(rng); // to 0.5 past the last node
      };
      double lo = pick(), hi = pick();
      if (hi < lo)
      {
        std::swap(lo, hi);
      }
      ++ranges;
      if (tf.ZeroExtinctionOver(lo, hi))
      {
        ++zero;
        ASSERT_EQ(MaxTauOver(tf, lo, hi, rng), 0.0)
          << "table " << table << ", [" << Str(lo) << ", " << Str(hi) << "]";
      }
    }
  }
  EXPECT_GT(zero, ranges / 20) << zero << " of " << ranges << " ranges called zero";
}
