/**
 * @file hovTransferFunctionTestCases.h
 * @brief Helpers shared by the hovTransferFunction tests (TestTransferFunction,
 * TestTransferFunctionGPU, TestTransferFunctionInputs): building specs,
 * reading the table at a scalar, the spec's own opacity by direct
 * interpolation, integration settings and Build() messages.
 *
 * A test writes `using namespace hovtest::tf;` to see these and the hovtest
 * helpers it needs (Str, Tolerances, Worst).
 */
#ifndef hovTransferFunctionTestCases_h
#define hovTransferFunctionTestCases_h

#include "hovTransferFunction.h"

#include "hovRayIntegrator.h"
#include "hovSegmentIntegral.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace hovtest
{
namespace tf
{
using hovtest::Str;
using hovtest::Tolerances;
using hovtest::Worst;

constexpr double Inf = std::numeric_limits<double>::infinity();
constexpr double Eps = std::numeric_limits<double>::epsilon();
const double NaN = std::nan("");

inline hov::TransferFunctionSpec Spec(std::vector<hov::ColorNode> color, std::vector<hov::OpacityNode> opacity,
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
inline hov::SegmentEnd At(const hov::TransferFunction& tf, double s, bool up = true, bool emission = false)
{
  hov::SegmentEnd e;
  tf.Evaluate(up ? tf.FindIntervalUpward(s) : tf.FindIntervalDownward(s), s, emission, e);
  return e;
}

/// Direct linear interpolation of opacity nodes (no jumps), clamped outside.
inline double OpacityAt(const std::vector<hov::OpacityNode>& n, double s)
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

inline hov::IntegrationSettings Settings(hov::EmissionModel m)
{
  hov::IntegrationSettings s;
  s.Emission = m;
  s.Method = hov::SegmentMethod::Exact;
  return s;
}

inline bool Contains(const std::vector<std::string>& messages, const std::string& word)
{
  return std::any_of(messages.begin(), messages.end(),
    [&](const std::string& m) { return m.find(word) != std::string::npos; });
}

inline std::string Join(const std::vector<std::string>& messages)
{
  std::string out;
  for (const auto& m : messages)
  {
    out += "[" + m + "] ";
  }
  return out;
}

/// GPU-compatible spec of @p color and @p opacity, unit distance @p unit,
/// GPUTolerance @p tolerance.
inline hov::TransferFunctionSpec GPUSpec(std::vector<hov::ColorNode> color,
  std::vector<hov::OpacityNode> opacity, double unit, double tolerance)
{
  hov::TransferFunctionSpec s =
    Spec(std::move(color), std::move(opacity), hov::OpacitySemantics::GPUCompatible, unit);
  s.GPUTolerance = tolerance;
  return s;
}
}
}

#endif
