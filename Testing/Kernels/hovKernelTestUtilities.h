/**
 * @file hovKernelTestUtilities.h
 * @brief Small helpers shared by the kernel tests: printing of measured worst
 * errors (so that the numbers quoted in the documentation can be re-measured
 * by running the tests) and a tracker of the worst case with its inputs.
 */
#ifndef hovKernelTestUtilities_h
#define hovKernelTestUtilities_h

#include "hovCompositing.h"
#include "hovTransferFunction.h"

#include "hovKernelTestReference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

namespace hovtest
{
/// Keeps the largest value seen and a description of the inputs that gave it.
struct Worst
{
  double Value = 0.0;
  std::string Where;

  void Add(double v, const std::string& where)
  {
    if (v > this->Value || std::isnan(v))
    {
      this->Value = v;
      this->Where = where;
    }
  }
};

/// Prints "[measured] name = value (at ...)" and records it in the test's
/// XML/JSON output (--gtest_output) as a property.
inline void ReportMeasured(const std::string& name, const Worst& w)
{
  std::ostringstream os;
  os.precision(3);
  os << w.Value;
  std::cout << "[measured] " << name << " = " << os.str();
  if (!w.Where.empty())
  {
    std::cout << "  (at " << w.Where << ")";
  }
  std::cout << std::endl;
  ::testing::Test::RecordProperty(name, os.str());
}

inline void ReportMeasured(const std::string& name, double v)
{
  Worst w;
  w.Value = v;
  ReportMeasured(name, w);
}

inline std::string ToString(const hov::RGBA& c)
{
  std::ostringstream os;
  os.precision(17);
  os << "(" << c.R << ", " << c.G << ", " << c.B << ", " << c.A << ")";
  return os.str();
}

inline bool AllFinite(const hov::RGBA& c)
{
  return std::isfinite(c.R) && std::isfinite(c.G) && std::isfinite(c.B) && std::isfinite(c.A);
}

/**
 * The huge-colour tests' checks of a result @p r (colour @p big at the last
 * node of RedAtLastNode(), tolerance 1e-9) against @p unit (colour 1, run at
 * 1e-14): finite, linear in the colour (R / big and G within 1e-10 relative
 * of the unit's: measured at most 1e-14, also on the optically thin segment
 * where R ~ 1e-7; the tolerances alone would allow about 1e-12 absolute; A
 * to 1e-14 absolute), and an estimate within the target or the rounding.
 * R: a segment result type.
 */
template <typename R>
void ExpectLinearInColour(const R& r, const R& unit, double big, const std::string& where)
{
  EXPECT_TRUE(AllFinite(r.Color)) << where;
  EXPECT_NEAR(r.Color.R / big, unit.Color.R, 1e-10 * std::abs(unit.Color.R)) << where;
  EXPECT_NEAR(r.Color.G, unit.Color.G, 1e-10 * std::abs(unit.Color.G)) << where;
  EXPECT_NEAR(r.Color.A, unit.Color.A, 1e-14) << where;
  EXPECT_TRUE(std::isfinite(r.ErrorEstimate)) << where;
  EXPECT_LE(r.ErrorEstimate / big, 1e-9 / big + 1e-12) << where; // the target, or rounding
}

/// The huge-colour tests' table (TestPolynomialSegmentProperties,
/// TestShadedSegmentRounding): red only at the last node, where it is @p red;
/// opacity @p opacity / 8, @p opacity, @p opacity / 3 at 0, 0.5 and 1.
inline hov::TransferFunctionSpec RedAtLastNode(
  double red, double opacity, hov::OpacitySemantics semantics)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = semantics;
  spec.Color = { { 0.0, 0.0, 0.4, 0.6 }, { 0.45, 0.0, 0.1, 0.3 }, { 1.0, red, 0.5, 0.5 } };
  spec.Opacity = { { 0.0, opacity / 8 }, { 0.5, opacity }, { 1.0, opacity / 3 } };
  return spec;
}

/// The reference description (raw nodes, hovKernelTestReference.h) of a
/// transfer-function spec whose nodes are already valid and sorted.
inline RefTransferFunction ToReference(const hov::TransferFunctionSpec& spec)
{
  RefTransferFunction r;
  for (const hov::ColorNode& n : spec.Color)
  {
    r.ColorX.push_back(n.X);
    r.Color.push_back({ n.R, n.G, n.B });
  }
  for (const hov::OpacityNode& n : spec.Opacity)
  {
    r.OpacityX.push_back(n.X);
    r.Opacity.push_back(n.Opacity);
  }
  switch (spec.Semantics)
  {
    case hov::OpacitySemantics::GPUCompatible:
      r.Semantics = RefSemantics::GPU;
      break;
    case hov::OpacitySemantics::VTKUnstructured:
      r.Semantics = RefSemantics::Unstructured;
      break;
    default:
      r.Semantics = RefSemantics::Raw;
  }
  r.Unit = spec.UnitDistance;
  r.EmissionScale = spec.EmissionScale;
  return r;
}

inline RefEmission ToReference(hov::EmissionModel m)
{
  return m == hov::EmissionModel::WilliamsMax ? RefEmission::WilliamsMax : RefEmission::WilhelmsVanGelder;
}

/// Max absolute difference between a kernel result and a reference, colour
/// divided by @p colorScale.
inline double MaxAbsDiff(const hov::RGBA& p, const RefRGBA& q, double colorScale)
{
  const long double s = colorScale;
  return static_cast<double>(std::max(std::max(std::fabs(p.R - q.R) / s, std::fabs(p.G - q.G) / s),
    std::max(std::fabs(p.B - q.B) / s, std::fabs(p.A - q.A))));
}

inline std::string ToString(const RefRGBA& c)
{
  std::ostringstream os;
  os.precision(17);
  os << "(" << static_cast<double>(c.R) << ", " << static_cast<double>(c.G) << ", "
     << static_cast<double>(c.B) << ", " << static_cast<double>(c.A) << ")";
  return os.str();
}

inline std::string ToString(const hov::TransferFunctionSpec& spec)
{
  std::ostringstream os;
  os.precision(17);
  os << "semantics=" << static_cast<int>(spec.Semantics) << " u=" << spec.UnitDistance
     << " tol=" << spec.GPUTolerance << " colour{";
  for (const auto& n : spec.Color)
  {
    os << " (" << n.X << ": " << n.R << "," << n.G << "," << n.B << ")";
  }
  os << " } opacity{";
  for (const auto& n : spec.Opacity)
  {
    os << " (" << n.X << ": " << n.Opacity << ")";
  }
  os << " }";
  return os.str();
}

inline double MaxAbsDiff(const hov::RGBA& p, const hov::RGBA& q)
{
  return std::max(std::max(std::abs(p.R - q.R), std::abs(p.G - q.G)),
    std::max(std::abs(p.B - q.B), std::abs(p.A - q.A)));
}
}

#endif
