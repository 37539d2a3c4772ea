// Tests of the thin series' two roundings (hovThinSeries.h: FusedSeries,
// SetFusedSeries). The process's setting must follow the CPU (fused exactly
// where it has FMA instructions). Each rounding must meet the thin branch's
// tolerance against the 50-digit reference (hovKernelTestReference.h). The two
// must differ in some bits, so the setting really reaches the scalar kernel.
// TestSegmentBatch checks that the batched kernel equals the scalar one under
// each rounding.

#include "hovRoundingScope.h"
#include "hovSegmentTestCases.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace hovtest::segment;

namespace
{
/// Whether /proc/cpuinfo lists the "fma" flag (x86-64 Linux); -1 if unknown.
int CpuInfoHasFma()
{
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
  {
    if (line.compare(0, 5, "flags") == 0)
    {
      std::istringstream words(line.substr(line.find(':') + 1));
      std::string word;
      while (words >> word)
      {
        if (word == "fma")
        {
          return 1;
        }
      }
      return 0;
    }
  }
  return -1;
}

/// Thin segments (total depth D(1) = (a + c)/2 log-uniform over [1e-8, 1/4],
/// every front/back share) with their reference weights.
std::vector<GridCase> ThinCases(int n)
{
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<GridCase> cases;
  for (int i = 0; i < n; ++i)
  {
    const double d1 = std::pow(10.0, -8.0 + (8.0 + std::log10(0.25)) * u(rng));
    const double f = u(rng);
    const double a = 2.0 * d1 * f, c = 2.0 * d1 * (1.0 - f);
    cases.push_back({ a, c, hovtest::ReferenceSegmentWeights(a, c) });
  }
  return cases;
}
}

TEST(ThinSeriesRounding, FollowsTheCpu)
{
#if HOV_FMA_CLONES && defined(__linux__)
  const int hasFma = CpuInfoHasFma();
  ASSERT_NE(hasFma, -1) << "no flags line in /proc/cpuinfo";
#elif defined(__aarch64__)
  const int hasFma = 1;
#else
  // No independent check here; the kernels have no FMA code for this platform
  // (hovThinSeries.h: HOV_FMA_CLONES), so the series must be separate.
  const int hasFma = 0;
#endif
  EXPECT_EQ(hov::detail::FusedSeries(), hasFma == 1);
  std::cout << "[measured] thin series rounding on this CPU: "
            << (hov::detail::FusedSeries() ? "fused" : "separate") << std::endl;
  {
    const hovtest::RoundingScope separate(false);
    EXPECT_TRUE(separate.Active); // always available
    EXPECT_FALSE(hov::detail::FusedSeries());
  }
  {
    const hovtest::RoundingScope fused(true);
    EXPECT_EQ(fused.Active, hasFma == 1); // only with the hardware
  }
  EXPECT_EQ(hov::detail::FusedSeries(), hasFma == 1); // restored
}

TEST(ThinSeriesRounding, BothMeetTheThinToleranceAndDiffer)
{
  const std::vector<GridCase> cases = ThinCases(400);
  std::vector<hov::SegmentWeights> results[2];
  for (const bool fused : { false, true })
  {
    const hovtest::RoundingScope rounding(fused);
    if (!rounding.Active)
    {
      std::cout << "[measured] no FMA on this CPU: the fused series is not checked" << std::endl;
      continue;
    }
    hovtest::Worst worst;
    for (const GridCase& g : cases)
    {
      const hov::SegmentWeights w = hov::ExactSegmentWeights(g.A, g.C, false);
      const double e = std::max(std::max(hovtest::RelErr(w.Alpha, g.Ref.Alpha),
                                  hovtest::RelErr(w.Transmittance, g.Ref.Transmittance)),
        std::max(hovtest::RelErr(w.WFront, g.Ref.WFront), hovtest::RelErr(w.WBack, g.Ref.WBack)));
      worst.Add(e, Pair(g.A, g.C));
      results[fused].push_back(w);
    }
    hovtest::ReportMeasured(std::string("thin WM weights relative error, ") +
        (fused ? "fused" : "separate") + " series",
      worst);
    EXPECT_LE(worst.Value, Tolerances.WeightsRelThin) << worst.Where;
  }
  if (results[1].empty())
  {
    GTEST_SKIP() << "no FMA on this CPU: the two roundings are not compared";
  }
  // Some segment must come out differently: otherwise the setting did not
  // reach the kernel (or the series has no step where the roundings differ).
  int differ = 0;
  for (size_t i = 0; i < cases.size(); ++i)
  {
    differ += results[0][i].WFront != results[1][i].WFront ||
      results[0][i].WBack != results[1][i].WBack || results[0][i].Alpha != results[1][i].Alpha;
  }
  hovtest::ReportMeasured("thin segments whose weights differ between the roundings (of 400)",
    static_cast<double>(differ));
  EXPECT_GT(differ, 0);
}
