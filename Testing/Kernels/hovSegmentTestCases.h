/**
 * @file hovSegmentTestCases.h
 * @brief Inputs shared by the hovSegmentIntegral tests (TestSegmentReference,
 * TestSegmentClosedForms, TestSegmentProperties): segment ends, the branch
 * thresholds of the kernel, the grid of depth rates and the pairs straddling
 * the thresholds, and the 50-digit reference weights over them.
 *
 * A test writes `using namespace hovtest::segment;` to see these and the
 * hovtest helpers it needs (Mp, Str, Tolerances, Worst).
 */
#ifndef hovSegmentTestCases_h
#define hovSegmentTestCases_h

#include "hovSegmentIntegral.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace hovtest
{
namespace segment
{
using hovtest::Mp;
using hovtest::Str;
using hovtest::Tolerances;
using hovtest::Worst;

constexpr double Inf = std::numeric_limits<double>::infinity();
constexpr double Denorm = std::numeric_limits<double>::denorm_min();

inline hov::SegmentEnd End(double tau, double r, double g, double b)
{
  hov::SegmentEnd e;
  e.Tau = tau;
  e.Color[0] = r;
  e.Color[1] = g;
  e.Color[2] = b;
  return e;
}

inline std::string Pair(double a, double c)
{
  return "a=" + Str(a) + " c=" + Str(c);
}

// Branch thresholds of hovSegmentIntegral.cxx (duplicated on purpose: if the
// kernel moves a threshold, the continuity tests still probe the old place and
// the reference tests still cover the new one through the grid).
constexpr double ThinDepth = 0.125;
constexpr double SmallSlope = 1.0 / 16.0;
constexpr double MomentUpwardFrom = 40.0;
constexpr double ZeroSlopeRelative = 1e-15;

/// Depth rates of the reference grid: 0, tiny, every decade that matters, and
/// both sides of the thresholds that depend on one rate alone.
inline const std::vector<double>& GridValues()
{
  static const std::vector<double> v = { 0.0, 1e-300, 1e-200, 1e-100, 1e-30, 1e-16, 1e-12, 1e-8,
    1e-4, 1e-2, 0.1, 0.124, 0.125, 0.126, 0.2, 0.2499, 0.25, 0.2501, 0.3, 0.5, 1.0, 2.0, 3.7, 5.0,
    10.0, 20.0, 39.0, 39.99, 40.0, 40.01, 41.0, 80.0, 100.0, 1e3, 1e4, 1e6, 1e12, 1e100, 1e300 };
  return v;
}

/// Pairs straddling each threshold that depends on both rates.
inline std::vector<std::pair<double, double>> ThresholdPairs()
{
  std::vector<std::pair<double, double>> p;
  // Total depth (a + c)/2 around ThinDepth, for several front/back ratios.
  for (double t : { ThinDepth * (1 - 1e-3), ThinDepth, std::nextafter(ThinDepth, 1.0),
         ThinDepth * (1 + 1e-3) })
  {
    for (double f : { 0.0, 0.1, 0.3, 0.5, 0.9, 1.0 })
    {
      p.emplace_back(2 * t * f, 2 * t * (1 - f));
    }
  }
  // |c - a|/2 around SmallSlope, both signs, at several depths (thin ones excluded
  // automatically by the kernel).
  for (double a : { 0.1, 0.2, 1.0, 3.0, 10.0, 39.9, 40.1, 100.0 })
  {
    for (double db : { SmallSlope * (1 - 1e-3), SmallSlope, SmallSlope * (1 + 1e-3) })
    {
      p.emplace_back(a, a + 2 * db);
      if (a - 2 * db >= 0)
      {
        p.emplace_back(a, a - 2 * db);
      }
    }
  }
  // MomentUpwardFrom on a with a small slope.
  for (double a : { 40.0 - 1e-9, 40.0, 40.0 + 1e-9 })
  {
    for (double dc : { -0.1, -0.05, -1e-6, 0.0, 1e-6, 0.05, 0.1 })
    {
      p.emplace_back(a, a + dc);
    }
  }
  // b around ZeroSlopeRelative * D(1) and through b = 0.
  for (double a : { 0.2, 1.0, 7.0, 50.0, 1e4 })
  {
    for (double rel : { -1e-9, -4e-15, -2.1e-15, -1.9e-15, 1.9e-15, 2.1e-15, 4e-15, 1e-9 })
    {
      p.emplace_back(a, a * (1 + rel));
    }
  }
  // Large depth with a comparatively small slope (closed-form K1 cancels).
  for (double a : { 1e3, 1e4 })
  {
    for (double dc : { -1.0, -0.2, 0.2, 1.0 })
    {
      p.emplace_back(a, a + dc);
    }
  }
  return p;
}

struct GridCase
{
  double A, C;
  hovtest::ReferenceWeights Ref;
};

/// The reference weights over the grid (computed once, ~3 ms per pair).
inline const std::vector<GridCase>& ReferenceGrid()
{
  static const std::vector<GridCase> grid = [] {
    std::vector<GridCase> g;
    for (double a : GridValues())
    {
      for (double c : GridValues())
      {
        g.push_back({ a, c, hovtest::ReferenceSegmentWeights(a, c) });
      }
    }
    for (const auto& p : ThresholdPairs())
    {
      g.push_back({ p.first, p.second, hovtest::ReferenceSegmentWeights(p.first, p.second) });
    }
    return g;
  }();
  return grid;
}
}
}

#endif
