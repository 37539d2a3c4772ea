// Tests of hovSegmentBatch: SegmentBatch::Integrate must give, bit for bit, what
// the scalar kernels give segment by segment (IntegrateLinearScalarInInterval for
// a known interval, IntegrateLinearScalar otherwise), for every emission model and
// method, on a mix of thin, thick, multi-interval, opaque, zero-length and
// non-finite segments, in batches of every size (so that every lane and padding
// pattern of the thin-series blocks occurs), under each rounding of the thin
// series the CPU offers (hovThinSeries.h: FusedSeries).

#include "hovSegmentBatch.h"

#include "hovRayIntegrator.h"
#include "hovRoundingScope.h"
#include "hovThinSeries.h" // ThinTerms, AtLeast
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
  spec.UnitDistance = 0.7;
  spec.Color = { { 0.0, 0.1, 0.2, 0.9 }, { 0.3, 0.2, 0.9, 0.1 }, { 0.55, 1.0, 1.0, 0.0 },
    { 1.0, 1.0, 0.1, 0.0 } };
  spec.Opacity = { { 0.0, 0.0 }, { 0.2, 0.05 }, { 0.5, 0.4 }, { 0.8, withOpaque ? 1.0 : 0.7 },
    { 1.0, withOpaque ? 1.0 : 0.9 } };
  hov::TransferFunction tf;
  tf.Build(spec);
  return tf;
}

/// Random segments: lengths log-uniform over 1e-6..1e2 (thin and thick), scalar
/// ends inside one interval, across nodes, outside the table; a few degenerate ones.
std::vector<hov::SegmentJob> MakeJobs(const hov::TransferFunction& tf, std::mt19937_64& rng, int n)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<hov::SegmentJob> jobs(n);
  for (hov::SegmentJob& job : jobs)
  {
    job.Length = std::pow(10.0, -6.0 + 8.0 * u(rng));
    const double kind = u(rng);
    if (kind < 0.6)
    {
      // Inside one interval: the interval is known (as for a cell whose range fits it).
      const double lo = u(rng) * 1.2 - 0.1, hi = lo + 0.05 * u(rng);
      job.SFront = u(rng) < 0.5 ? lo : hi;
      job.SBack = job.SFront == lo ? hi : lo;
      job.Interval = u(rng) < 0.8 ? hov::IntervalOfRange(tf, lo, hi) : -2;
    }
    else if (kind < 0.95)
    {
      job.SFront = u(rng) * 1.4 - 0.2;
      job.SBack = u(rng) * 1.4 - 0.2;
      job.Interval = -2;
    }
    else
    {
      const double bad[] = { 0.0, -1.0, std::numeric_limits<double>::quiet_NaN() };
      job.Length = bad[static_cast<int>(3 * u(rng)) % 3];
      job.SFront = u(rng);
      job.SBack = u(rng) < 0.5 ? job.SFront : std::numeric_limits<double>::infinity();
      job.Interval = -2;
    }
  }
  return jobs;
}

void ExpectSameAsScalarWithRounding(const hov::TransferFunction& tf,
  const hov::IntegrationSettings& settings, const std::vector<hov::SegmentJob>& jobs,
  hov::SegmentBatch& batch)
{
  for (int count : { 1, 2, 3, 4, 5, 7, 8, 9, 31, static_cast<int>(jobs.size()) })
  {
    std::vector<hov::RGBA> out(count);
    std::vector<int> perJob(count, -1);
    const long long pieces =
      batch.Integrate(tf, settings, jobs.data(), count, out.data(), perJob.data());
    long long expectedPieces = 0;
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
      expectedPieces += p;
      ASSERT_EQ(perJob[i], p) << "segment " << i;
      // Bit for bit: the batch promises exactly the scalar kernels' operations.
      ASSERT_EQ(out[i].R, ref.R) << "segment " << i << " of " << count << ": s " << job.SFront
                                 << " -> " << job.SBack << ", L " << job.Length;
      ASSERT_EQ(out[i].G, ref.G) << "segment " << i;
      ASSERT_EQ(out[i].B, ref.B) << "segment " << i;
      ASSERT_EQ(out[i].A, ref.A) << "segment " << i;
    }
    EXPECT_EQ(pieces, expectedPieces) << count << " segments";
  }
}

/// The comparison above under each rounding of the thin series this CPU
/// offers (separate always, fused with FMA): both kernels must follow the
/// process's setting alike.
void ExpectSameAsScalar(const hov::TransferFunction& tf, const hov::IntegrationSettings& settings,
  const std::vector<hov::SegmentJob>& jobs, hov::SegmentBatch& batch)
{
  for (const bool fused : { false, true })
  {
    const hovtest::RoundingScope rounding(fused);
    if (rounding.Active)
    {
      SCOPED_TRACE(fused ? "fused series" : "separate series");
      ExpectSameAsScalarWithRounding(tf, settings, jobs, batch);
    }
  }
}
}

namespace
{
/// One interval, raw extinction 0.2 to 1 over [0, 1]: depth D(1) in [0.2 L, L].
hov::TransferFunction RawRampTable()
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Color = { { 0.0, 0.0, 0.5, 1.0 }, { 1.0, 1.0, 0.5, 0.0 } };
  spec.Opacity = { { 0.0, 0.2 }, { 1.0, 1.0 } };
  hov::TransferFunction tf;
  tf.Build(spec);
  return tf;
}
}

TEST(SegmentBatch, BitIdenticalToScalarKernels)
{
  std::mt19937_64 rng(20240611);
  hov::SegmentBatch batch; // reused across calls, as in the renderer
  for (const auto semantics : { hov::OpacitySemantics::VTKUnstructured,
         hov::OpacitySemantics::GPUCompatible, hov::OpacitySemantics::RawExtinction })
  {
    for (const bool opaque : { false, true })
    {
      const hov::TransferFunction tf = MakeTable(semantics, opaque);
      const std::vector<hov::SegmentJob> jobs = MakeJobs(tf, rng, 600);
      for (const auto emission : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
      {
        for (const auto method : { hov::SegmentMethod::Exact, hov::SegmentMethod::Approximate })
        {
          hov::IntegrationSettings settings;
          settings.Emission = emission;
          settings.Method = method;
          ExpectSameAsScalar(tf, settings, jobs, batch);
        }
      }
    }
  }
}

TEST(SegmentBatch, ThinSegmentsOfEveryTermCount)
{
  // Depths D(1) from 1e-20 to 0.25 (every number of series terms), each block
  // of four mixing neighbouring term counts.
  const hov::TransferFunction tf = RawRampTable();
  std::vector<hov::SegmentJob> jobs;
  for (double depth = 1e-20; depth < 0.25; depth *= 1.37)
  {
    hov::SegmentJob job;
    job.SFront = 0.1 + 0.8 * std::fmod(depth * 1e6, 1.0);
    job.SBack = 0.9 - 0.8 * std::fmod(depth * 3e5, 1.0);
    job.Length = depth; // tau in [0.2, 1]: D(1) in [0.2 L, L]
    job.Interval = 0;
    jobs.push_back(job);
  }
  hov::SegmentBatch batch;
  ExpectSameAsScalar(tf, hov::IntegrationSettings(), jobs, batch);
}

TEST(SegmentBatch, BlocksMixingFarApartTermCounts)
{
  // The lane kernel evaluates a block of four thin segments with the largest
  // number of terms among them, each lane's extra terms replaced by exact
  // zeros: a lane of one term beside one of thirteen must still equal the
  // scalar kernel with its own count. Depths drawn independently, log-uniform
  // over [1e-20, 0.25], so blocks span far-apart counts; one interval known.
  const hov::TransferFunction tf = RawRampTable();
  std::mt19937_64 rng(20261203);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<hov::SegmentJob> jobs;
  for (int i = 0; i < 4000; ++i)
  {
    hov::SegmentJob job;
    job.SFront = u(rng);
    job.SBack = u(rng);
    job.Length = std::pow(10.0, -20.0 + 19.4 * u(rng)); // tau in [0.2, 1]
    job.Interval = 0;
    jobs.push_back(job);
  }
  hov::SegmentBatch batch;
  ExpectSameAsScalar(tf, hov::IntegrationSettings(), jobs, batch);
}

TEST(SegmentBatch, TermThresholdsMatchTermCounts)
{
  // The lane kernel decides "lane takes term n" by d1 >= AtLeast[n] instead
  // of looking up each lane's count: both must agree for every depth a thin
  // segment can have, binade edges included.
  const hov::detail::ThinTermByExponent& terms = hov::detail::ThinTerms();
  std::vector<double> depths{ std::numeric_limits<double>::denorm_min(), 1e-300, 0.25 };
  for (int e = -90; e <= -2; ++e)
  {
    const double p = std::ldexp(1.0, e);
    depths.insert(depths.end(), { std::nextafter(p, 0.0), p, std::nextafter(p, 1.0), 1.5 * p });
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-25.0, std::log10(0.25));
  for (int i = 0; i < 20000; ++i)
  {
    depths.push_back(std::pow(10.0, u(rng)));
  }
  int checked = 0;
  for (const double d1 : depths)
  {
    if (!(d1 > 0.0 && d1 <= hov::detail::ThinDepth))
    {
      continue;
    }
    const int count = terms(d1);
    ASSERT_GE(count, 1);
    for (int n = 1; n <= hov::detail::MaxThinOrder; ++n)
    {
      ASSERT_EQ(n <= count, terms.AtLeast[n] <= d1) << "d1 " << d1 << ", n " << n;
      ++checked;
    }
  }
  EXPECT_GT(checked, 300000);
}
