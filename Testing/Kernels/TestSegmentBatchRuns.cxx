// Tests of hovSegmentBatch on segments queued as the CPU tiles queue them: runs
// of consecutive segments of one cell (one known transfer-function interval,
// or -2 or a search hint -3 - h for a cell whose range meets a node), whose
// four-lane blocks take the batch's vector evaluation when they share an
// interior interval. Every result must equal, bit for bit, what the scalar
// kernels give segment by segment (IntegrateLinearScalarInInterval for a known
// interval, IntegrateLinearScalar otherwise), with the same number of pieces;
// runs mix thin, thick and opaque segments, scalars a rounding error outside
// their interval, invalid segments, and runs of every length so that blocks
// straddle runs in every way.

#include "hovSegmentBatch.h"

#include "hovRayIntegrator.h"
#include "hovTransferFunction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace
{
hov::TransferFunction MakeTable(hov::OpacitySemantics semantics, bool withOpaque)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = semantics;
  spec.UnitDistance = 0.5;
  spec.Color = { { 0.0, 0.9, 0.2, 0.1 }, { 0.25, 0.2, 0.8, 0.3 }, { 0.6, 0.1, 0.3, 1.0 },
    { 1.0, 1.0, 1.0, 0.2 } };
  spec.Opacity = { { 0.0, 0.02 }, { 0.3, 0.3 }, { 0.7, withOpaque ? 1.0 : 0.6 },
    { 1.0, 0.1 } };
  hov::TransferFunction tf;
  tf.Build(spec);
  return tf;
}

/// One cell's run: @p n segments with scalars in [lo, hi] (one interval or
/// across nodes), lengths around @p length; a few invalid or nudged ones.
void AddRun(const hov::TransferFunction& tf, std::mt19937_64& rng, int n, double length,
  std::vector<hov::SegmentJob>& jobs)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::vector<double>& x = tf.GetNodes();
  const bool crossing = u(rng) < 0.3;
  double lo, hi;
  if (crossing)
  {
    lo = u(rng) * 1.1 - 0.05;
    hi = lo + 0.4 * u(rng);
  }
  else
  {
    // Inside one interval, outer regions included (k = -1 and k = n - 1).
    const int k = static_cast<int>(u(rng) * (x.size() + 1)) - 1;
    const double a = k < 0 ? x.front() - 0.3 : x[k];
    const double b = k + 1 >= static_cast<int>(x.size()) ? x.back() + 0.3 : x[k + 1];
    lo = a + (b - a) * (0.01 + 0.5 * u(rng));
    hi = lo + (b - lo) * 0.98 * u(rng);
  }
  int interval = hov::IntervalOfRange(tf, lo, hi); // -2 when crossing
  if (interval == -2 && u(rng) < 0.7)
  {
    // A search hint, as the renderer gives: the interval of the cell's
    // smallest scalar, or a wrong one (the result must not depend on it).
    interval = -3 - (u(rng) < 0.8 ? tf.FindIntervalUpward(lo) : static_cast<int>(u(rng) * 5));
  }
  for (int i = 0; i < n; ++i)
  {
    hov::SegmentJob job;
    job.SFront = lo + (hi - lo) * u(rng);
    job.SBack = lo + (hi - lo) * u(rng);
    job.Length = length * (0.5 + u(rng));
    job.Interval = interval;
    const double kind = u(rng);
    if (kind < 0.04)
    {
      job.Length = kind < 0.02 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    }
    else if (kind < 0.08 && interval >= 0)
    {
      // A rounding error outside the cell's range (Evaluate clamps it).
      job.SFront = std::nextafter(lo, -1e300);
    }
    jobs.push_back(job);
  }
}

void ExpectSameAsScalar(const hov::TransferFunction& tf, const std::vector<hov::SegmentJob>& jobs,
  hov::SegmentBatch& batch)
{
  const hov::IntegrationSettings settings; // Williams-Max, exact: the batched path
  for (int count : { 3, 4, 5, 17, 64, 255, static_cast<int>(jobs.size()) })
  {
    std::vector<hov::RGBA> out(count);
    std::vector<int> perJob(count, -1);
    batch.Integrate(tf, settings, jobs.data(), count, out.data(), perJob.data());
    for (int i = 0; i < count; ++i)
    {
      const hov::SegmentJob& job = jobs[i];
      hov::RGBA ref;
      int p = 1;
      if (job.Interval >= -1)
      {
        ref = hov::IntegrateLinearScalarInInterval(
          tf, job.Interval, job.SFront, job.SBack, job.Length, settings);
      }
      else
      {
        ref = hov::IntegrateLinearScalar(tf, job.SFront, job.SBack, job.Length, settings, &p);
      }
      ASSERT_EQ(perJob[i], p) << "segment " << i;
      ASSERT_EQ(out[i].R, ref.R) << "segment " << i << " of " << count << ": s " << job.SFront
                                 << " -> " << job.SBack << ", L " << job.Length << ", interval "
                                 << job.Interval;
      ASSERT_EQ(out[i].G, ref.G) << "segment " << i;
      ASSERT_EQ(out[i].B, ref.B) << "segment " << i;
      ASSERT_EQ(out[i].A, ref.A) << "segment " << i;
    }
  }
}
}

TEST(SegmentBatch, RunsOfCellsBitIdenticalToScalarKernels)
{
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  hov::SegmentBatch batch;
  for (const auto semantics : { hov::OpacitySemantics::VTKUnstructured,
         hov::OpacitySemantics::GPUCompatible, hov::OpacitySemantics::RawExtinction })
  {
    for (const bool opaque : { false, true })
    {
      const hov::TransferFunction tf = MakeTable(semantics, opaque);
      std::vector<hov::SegmentJob> jobs;
      while (jobs.size() < 1500)
      {
        // Mostly thin segments (the common case), some thick ones.
        const double length = std::pow(10.0, u(rng) < 0.8 ? -4.0 + 3.0 * u(rng) : 1.0 * u(rng));
        AddRun(tf, rng, 1 + static_cast<int>(12 * u(rng)), length, jobs);
      }
      ExpectSameAsScalar(tf, jobs, batch);
    }
  }
}

TEST(SegmentBatch, RunsOfCellsWithManyNodesAndEndsOnNodes)
{
  // Tables of up to 16 nodes take the counted interval search, larger ones
  // the walk: both must give the scalar kernels' intervals and pieces, also
  // for ends exactly on a node (where walking up and down differ) or one ulp
  // beside it (where the scalar search's bucket lookup rounds).
  std::mt19937_64 rng(20261203);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  hov::SegmentBatch batch;
  for (const int numNodes : { 2, 15, 16, 17, 40 })
  {
    hov::TransferFunctionSpec spec;
    spec.Semantics = hov::OpacitySemantics::VTKUnstructured;
    spec.UnitDistance = 0.5;
    for (int k = 0; k < numNodes; ++k)
    {
      const double s = static_cast<double>(k) / (numNodes - 1);
      spec.Color.push_back({ s, 0.5 + 0.5 * std::sin(7.0 * s), s, 1.0 - s });
      spec.Opacity.push_back({ s, 0.05 + 0.9 * u(rng) });
    }
    hov::TransferFunction tf;
    tf.Build(spec);
    ASSERT_EQ(static_cast<int>(tf.GetNodes().size()), numNodes);
    const std::vector<double>& x = tf.GetNodes();
    std::vector<hov::SegmentJob> jobs;
    while (jobs.size() < 1500)
    {
      const double length = std::pow(10.0, u(rng) < 0.8 ? -4.0 + 3.0 * u(rng) : 1.0 * u(rng));
      AddRun(tf, rng, 1 + static_cast<int>(12 * u(rng)), length, jobs);
    }
    int onNode = 0;
    for (hov::SegmentJob& job : jobs)
    {
      if (job.Interval < -1 && u(rng) < 0.6)
      {
        // One end on a node or one ulp either side of it (any node: inside or
        // outside the run's range).
        const int k = static_cast<int>(u(rng) * x.size());
        const double side = u(rng);
        const double s = side < 0.4 ? x[k] : std::nextafter(x[k], side < 0.7 ? -1e300 : 1e300);
        (u(rng) < 0.5 ? job.SFront : job.SBack) = s;
        ++onNode;
      }
    }
    EXPECT_GT(onNode, 10) << numNodes << " nodes";
    ExpectSameAsScalar(tf, jobs, batch);
  }
}
