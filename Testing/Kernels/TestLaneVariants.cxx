// Tests of the lane kernels' variants (Module/Kernels/hovSegmentBatchLanes.cxx).
// The module compiles them once per instruction set (target_clones: x86-64-v3,
// FMA3, baseline x86-64) and the CPU picks one at load time, so a run of the
// other tests exercises only that one. The kernel test program also holds the
// file built as each variant alone (Testing/Kernels/CMakeLists.txt:
// HOV_LANES_ONLY, a namespace per variant). Here every variant this CPU can
// run gets the same inputs as the module's and must give the same bits: the
// interval counts, the RGBA of the blocks finished in registers, the lanes
// left for the sorted series and the sorted series itself, under each
// rounding of the thin series (hovThinSeries.h: FusedSeries). With the module's
// variant checked against the scalar kernels (TestSegmentBatch.cxx), every
// variant then equals the scalar kernels.

#include "hovSegmentBatchLanes.h" // the module's variant ("cloned")

#include "hovRoundingScope.h"
#include "hovThinSeries.h"
#include "hovTransferFunction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

// The test builds' functions (hovSegmentBatchLanes.cxx built with
// HOV_LANES_ONLY = 1 and 2: Testing/Kernels/CMakeLists.txt), declared with the
// module's types.
#define HOV_DECLARE_LANE_VARIANT(ns)                                                               \
  namespace hov::detail::ns                                                                        \
  {                                                                                                \
  decltype(cloned::ThinWilliamsMaxBlocks) ThinWilliamsMaxBlocks;                                   \
  decltype(cloned::CountIntervals) CountIntervals;                                                 \
  decltype(cloned::EvaluateSegments) EvaluateSegments;                                             \
  }
HOV_DECLARE_LANE_VARIANT(baseline)
HOV_DECLARE_LANE_VARIANT(fma3)

namespace
{
using hov::SegmentBatch;

struct Variant
{
  std::string Name;
  decltype(&hov::detail::ThinWilliamsMaxBlocks) Thin;
  decltype(&hov::detail::CountIntervals) Count;
  decltype(&hov::detail::EvaluateSegments) Evaluate;
};

/// The module's variant (the reference) and every other one this CPU runs.
std::vector<Variant> Variants()
{
  namespace d = hov::detail;
  std::vector<Variant> v;
  v.push_back({ "module", &d::ThinWilliamsMaxBlocks, &d::CountIntervals, &d::EvaluateSegments });
  v.push_back({ "baseline", &d::baseline::ThinWilliamsMaxBlocks, &d::baseline::CountIntervals,
    &d::baseline::EvaluateSegments });
#if HOV_FMA_CLONES
  if (__builtin_cpu_supports("fma"))
  {
    v.push_back({ "fma3", &d::fma3::ThinWilliamsMaxBlocks, &d::fma3::CountIntervals,
      &d::fma3::EvaluateSegments });
  }
  else
  {
    static bool told = false;
    if (!told)
    {
      std::cout << "[note] this CPU has no FMA3: its variant is not run\n";
      told = true;
    }
  }
#endif
  return v;
}

std::uint64_t Bits(double x)
{
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof(b));
  return b;
}

/// A table of @p nodes nodes over [0, 1] (colour and opacity at the same ones).
hov::TransferFunction MakeTable(int nodes, std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::VTKUnstructured;
  spec.UnitDistance = 0.7;
  for (int k = 0; k < nodes; ++k)
  {
    const double s = nodes == 1 ? 0.5 : static_cast<double>(k) / (nodes - 1);
    spec.Color.push_back({ s, u(rng), u(rng), u(rng) });
    spec.Opacity.push_back({ s, k == nodes / 2 ? 0.0 : u(rng) });
  }
  hov::TransferFunction tf;
  tf.Build(spec);
  return tf;
}

/// Segments as a renderer queues them: runs of 1 to 12 from one cell (one
/// interval, mostly thin, the interval known or left to count), segments
/// across nodes or outside the table, and degenerate ones (zero or NaN length,
/// infinite ends).
struct Jobs
{
  std::vector<double> SFront, SBack, Length;
  std::vector<int> Interval;
  SegmentBatch::Arrays Arrays() const
  {
    return { this->SFront.data(), this->SBack.data(), this->Length.data(),
      this->Interval.data() };
  }
};

Jobs MakeJobs(const hov::TransferFunction& tf, std::mt19937_64& rng, int n)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<double>& x = tf.GetNodes();
  const int intervals = static_cast<int>(x.size()) - 1;
  Jobs jobs;
  auto add = [&](double s0, double s1, double length, int interval) {
    jobs.SFront.push_back(s0);
    jobs.SBack.push_back(s1);
    jobs.Length.push_back(length);
    jobs.Interval.push_back(interval);
  };
  while (static_cast<int>(jobs.SFront.size()) < n)
  {
    const double kind = u(rng);
    if (kind < 0.7 && intervals > 0)
    {
      const int k = static_cast<int>(u(rng) * intervals) % intervals;
      const int interval = u(rng) < 0.7 ? k : -2;
      const int run = 1 + static_cast<int>(12 * u(rng));
      for (int r = 0; r < run; ++r)
      {
        const double s0 = x[k] + u(rng) * (x[k + 1] - x[k]);
        const double s1 = x[k] + u(rng) * (x[k + 1] - x[k]);
        add(s0, s1, std::pow(10.0, -5.0 + 5.0 * u(rng)), interval);
      }
    }
    else if (kind < 0.95)
    {
      add(u(rng) * 1.4 - 0.2, u(rng) * 1.4 - 0.2, std::pow(10.0, -4.0 + 6.0 * u(rng)), -2);
    }
    else
    {
      const double bad[] = { 0.0, -1.0, std::numeric_limits<double>::quiet_NaN() };
      const double s = u(rng);
      add(s, u(rng) < 0.5 ? s : std::numeric_limits<double>::infinity(),
        bad[static_cast<int>(3 * u(rng)) % 3], u(rng) < 0.5 ? 0 : -2);
    }
  }
  for (auto* v : { &jobs.SFront, &jobs.SBack, &jobs.Length })
  {
    v->resize(n + hov::detail::Lanes, 0.5); // padding: the lanes may read a block further
  }
  jobs.Interval.resize(n + hov::detail::Lanes, 0);
  return jobs;
}

constexpr int Skip = -1000000;
constexpr int Unset = -7777777; // what an output slot holds before a kernel writes it

/// Intervals for EvaluateSegments(), from the module's CountIntervals() as
/// SegmentBatch takes them (known and counted ones as they are, a segment that
/// crosses a node and an invalid one skipped); a segment still unknown gets
/// the interval of its lower end (SegmentBatch would split it if it crosses a
/// node: any interval is a valid input here, evaluated on that interval).
std::vector<int> Resolve(const hov::TransferFunction& tf, const Jobs& jobs, int count)
{
  std::vector<int> resolved(count + hov::detail::Lanes, Unset), start(count, Unset),
    left(count, Unset);
  const std::vector<double>& x = tf.GetNodes();
  const int numLeft = hov::detail::CountIntervals(x.data(), static_cast<int>(x.size()),
    jobs.Arrays(), count, resolved.data(), start.data(), left.data());
  for (int j = 0; j < numLeft; ++j)
  {
    const int i = left[j];
    const bool valid = jobs.Length[i] > 0.0 && std::isfinite(jobs.SFront[i]) &&
      std::isfinite(jobs.SBack[i]);
    resolved[i] = resolved[i] == hov::detail::NeedsSplit || !valid
      ? Skip
      : tf.FindIntervalUpward(std::min(jobs.SFront[i], jobs.SBack[i]));
  }
  return resolved;
}

/// What EvaluateSegments() wrote: the RGBA slots and the pending thin lanes.
struct Evaluated
{
  std::vector<hov::RGBA> Out;
  std::vector<double> Store;
  std::vector<int> Terms, Pending;
  int NumPending = 0;
};

Evaluated Evaluate(const Variant& v, const hov::TransferFunction& tf, const Jobs& jobs,
  const std::vector<int>& resolved, int count)
{
  Evaluated e;
  const size_t stride = count + hov::detail::Lanes;
  const double unset = static_cast<double>(Unset);
  e.Out.assign(stride, hov::RGBA{ unset, unset, unset, unset });
  e.Store.assign(10 * stride, unset);
  e.Terms.assign(stride, Unset);
  e.Pending.assign(stride, Unset);
  double* f = e.Store.data();
  const SegmentBatch::ThinArrays t{ f, f + stride, f + 2 * stride, f + 3 * stride,
    f + 4 * stride, f + 5 * stride, f + 6 * stride, f + 7 * stride, f + 8 * stride,
    f + 9 * stride, e.Terms.data(), e.Pending.data(), &e.NumPending };
  v.Evaluate(tf, resolved.data(), Skip, jobs.Arrays(), count, t, e.Out.data());
  return e;
}

void ExpectSameEvaluation(const Evaluated& ref, const Evaluated& e, int count)
{
  ASSERT_EQ(e.NumPending, ref.NumPending);
  const size_t stride = count + hov::detail::Lanes;
  for (size_t i = count; i < stride; ++i)
  {
    ASSERT_EQ(e.Out[i].A, static_cast<double>(Unset)) << "padding " << i; // none written
    ASSERT_EQ(e.Terms[i], Unset) << "padding " << i;
  }
  for (size_t j = e.NumPending; j < stride; ++j)
  {
    ASSERT_EQ(e.Pending[j], Unset) << "pending list, " << j;
  }
  for (int i = 0; i < count; ++i)
  {
    ASSERT_EQ(Bits(e.Out[i].R), Bits(ref.Out[i].R)) << "segment " << i;
    ASSERT_EQ(Bits(e.Out[i].G), Bits(ref.Out[i].G)) << "segment " << i;
    ASSERT_EQ(Bits(e.Out[i].B), Bits(ref.Out[i].B)) << "segment " << i;
    ASSERT_EQ(Bits(e.Out[i].A), Bits(ref.Out[i].A)) << "segment " << i;
  }
  for (int j = 0; j < ref.NumPending; ++j)
  {
    const int m = ref.Pending[j];
    ASSERT_EQ(e.Pending[j], m) << "pending lane " << j;
    ASSERT_EQ(e.Terms[m], ref.Terms[m]) << "lane " << m;
    for (int field = 0; field < 8; ++field) // A, D1 and the colours at both ends
    {
      ASSERT_EQ(Bits(e.Store[field * stride + m]), Bits(ref.Store[field * stride + m]))
        << "lane " << m << ", field " << field;
    }
  }
}
}

TEST(LaneVariants, CountTheSameIntervals)
{
  std::mt19937_64 rng(20261206);
  const std::vector<Variant> variants = Variants();
  // 7 nodes are counted in the lanes, 20 are more than MaxCountedNodes (searched).
  int counted = 0, splits = 0; // by the module's variant: the paths taken
  for (int nodes : { 1, 2, 7, hov::detail::MaxCountedNodes, 20 })
  {
    const hov::TransferFunction tf = MakeTable(nodes, rng);
    const Jobs jobs = MakeJobs(tf, rng, 2000);
    const std::vector<double>& x = tf.GetNodes();
    for (int count : { 1, 3, 4, 5, 8, 37, 2000 })
    {
      std::vector<int> refResolved, refStart, refLeft;
      int refLeftCount = 0;
      for (const Variant& v : variants)
      {
        SCOPED_TRACE(v.Name + ", " + std::to_string(nodes) + " nodes, " +
          std::to_string(count) + " segments");
        // A block of padding after each array: no kernel writes there.
        const int padded = count + hov::detail::Lanes;
        std::vector<int> resolved(padded, Unset), start(padded, Unset), left(padded, Unset);
        const int numLeft = v.Count(x.data(), static_cast<int>(x.size()), jobs.Arrays(), count,
          resolved.data(), start.data(), left.data());
        for (int i = count; i < padded; ++i)
        {
          ASSERT_EQ(resolved[i], Unset);
          ASSERT_EQ(start[i], Unset);
          ASSERT_EQ(left[i], Unset);
        }
        if (&v == &variants.front())
        {
          refResolved = resolved;
          refStart = start;
          refLeft = left;
          refLeftCount = numLeft;
          for (int i = 0; i < count; ++i)
          {
            counted += jobs.Interval[i] < -1 && refResolved[i] >= -1;
            splits += refResolved[i] == hov::detail::NeedsSplit;
          }
          continue;
        }
        ASSERT_EQ(numLeft, refLeftCount);
        EXPECT_EQ(resolved, refResolved);
        for (int i = 0; i < count; ++i)
        {
          if (resolved[i] == hov::detail::NeedsSplit)
          {
            ASSERT_EQ(start[i], refStart[i]) << "segment " << i;
          }
        }
        EXPECT_TRUE(std::equal(left.begin(), left.begin() + numLeft, refLeft.begin()));
      }
    }
  }
  EXPECT_GT(counted, 100); // blocks of unknown intervals counted in the lanes
  EXPECT_GT(splits, 100);  // segments marked to split
}

TEST(LaneVariants, EvaluateTheSameSegments)
{
  std::mt19937_64 rng(61202026);
  const std::vector<Variant> variants = Variants();
  int pending = 0; // thin lanes the module's variant left for the sorted series
  for (int nodes : { 2, 7, 20 })
  {
    const hov::TransferFunction tf = MakeTable(nodes, rng);
    const Jobs jobs = MakeJobs(tf, rng, 3000);
    for (const bool fused : { false, true })
    {
      const hovtest::RoundingScope rounding(fused);
      if (!rounding.Active)
      {
        continue;
      }
      for (int count : { 1, 4, 7, 64, 3000 })
      {
        const std::vector<int> resolved = Resolve(tf, jobs, count);
        const Evaluated ref = Evaluate(variants.front(), tf, jobs, resolved, count);
        pending += ref.NumPending;
        for (size_t k = 1; k < variants.size(); ++k)
        {
          SCOPED_TRACE(variants[k].Name + (fused ? ", fused series, " : ", separate series, ") +
            std::to_string(nodes) + " nodes, " + std::to_string(count) + " segments");
          ExpectSameEvaluation(ref, Evaluate(variants[k], tf, jobs, resolved, count), count);
        }
      }
    }
  }
  EXPECT_GT(pending, 100);
}

TEST(LaneVariants, FinishThinBlocksInRegisters)
{
  // 64 thin segments of one interval: every block is finished in registers
  // (none pending), by every variant alike.
  std::mt19937_64 rng(6122026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const hov::TransferFunction tf = MakeTable(7, rng);
  const std::vector<double>& x = tf.GetNodes();
  constexpr int count = 64;
  Jobs jobs;
  for (int i = 0; i < count + hov::detail::Lanes; ++i)
  {
    jobs.SFront.push_back(x[2] + u(rng) * (x[3] - x[2]));
    jobs.SBack.push_back(x[2] + u(rng) * (x[3] - x[2]));
    jobs.Length.push_back(std::pow(10.0, -4.0 + 2.0 * u(rng)));
    jobs.Interval.push_back(2);
  }
  const std::vector<int> resolved = Resolve(tf, jobs, count);
  const std::vector<Variant> variants = Variants();
  for (const bool fused : { false, true })
  {
    const hovtest::RoundingScope rounding(fused);
    if (!rounding.Active)
    {
      continue;
    }
    const Evaluated ref = Evaluate(variants.front(), tf, jobs, resolved, count);
    for (const Variant& v : variants)
    {
      SCOPED_TRACE(v.Name + (fused ? ", fused series" : ", separate series"));
      const Evaluated e = Evaluate(v, tf, jobs, resolved, count);
      EXPECT_EQ(e.NumPending, 0);
      for (int i = 0; i < count; ++i)
      {
        EXPECT_GT(e.Out[i].A, 0.0) << "segment " << i;
        EXPECT_LT(e.Out[i].A, 1.0) << "segment " << i;
      }
      ExpectSameEvaluation(ref, e, count);
    }
  }
}

TEST(LaneVariants, SumTheSameThinSeries)
{
  std::mt19937_64 rng(12062026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<Variant> variants = Variants();
  constexpr int blocks = 25, n = blocks * hov::detail::Lanes;
  for (int terms = 1; terms <= hov::detail::MaxThinOrder; ++terms)
  {
    std::vector<double> a(n), d1(n);
    for (int i = 0; i < n; ++i)
    {
      d1[i] = hov::detail::ThinDepth * std::pow(2.0, -30.0 * u(rng));
      a[i] = 2.0 * d1[i] * u(rng);
    }
    for (const bool fused : { false, true })
    {
      const hovtest::RoundingScope rounding(fused);
      if (!rounding.Active)
      {
        continue;
      }
      std::vector<double> refW(n), refAlpha(n);
      variants.front().Thin(terms, a.data(), d1.data(), blocks, refW.data(), refAlpha.data());
      for (size_t k = 1; k < variants.size(); ++k)
      {
        SCOPED_TRACE(variants[k].Name + (fused ? ", fused series, " : ", separate series, ") +
          std::to_string(terms) + " terms");
        std::vector<double> w(n), alpha(n);
        variants[k].Thin(terms, a.data(), d1.data(), blocks, w.data(), alpha.data());
        for (int i = 0; i < n; ++i)
        {
          ASSERT_EQ(Bits(w[i]), Bits(refW[i])) << "lane " << i;
          ASSERT_EQ(Bits(alpha[i]), Bits(refAlpha[i])) << "lane " << i;
        }
      }
    }
  }
}
