// Tests of hovShadedSegment with positional lights (attenuation, spot cones
// containing the segment): the light direction varies along the ray even
// where the gradient is constant, so no closed form exists; the adaptive
// quadrature is checked against the independent long double reference of
// hovShadedSegmentTestCase.h (positional lights evaluated per point), within
// its tolerance and its own error estimate.

#include "hovShadedSegment.h"

#include "hovGradientOpacity.h"
#include "hovTransferFunction.h"
#include "hovVolumeShading.h"

#include "hovShadedSegmentTestCase.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <string>

using hovtest::Case;
using hovtest::LD;
using hovtest::RandomCase;
using hovtest::Reference;
using hovtest::Str;
using hovtest::Worst;

namespace
{
TEST(ShadedSegment, PositionalLightsAgainstLongDoubleReference)
{
  // Positional lights (attenuation, spot cones containing the segment): l
  // varies along the ray even where the gradient is constant, so no closed
  // form exists; the quadrature must meet its tolerance and its estimate.
  std::mt19937_64 rng(1924);
  std::normal_distribution<double> nd;
  Worst err, ratio;
  int spots = 0;
  for (int trial = 0; trial < 30; ++trial)
  {
    Case c = RandomCase(rng, trial);
    c.Lights.clear();
    for (int k = 0; k < 1 + trial % 2; ++k)
    {
      hov::ShadingLight light;
      light.Positional = true;
      double u[3] = { nd(rng), nd(rng), nd(rng) };
      const double ul = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      const double r = hovtest::Uniform(rng, 0.4, 2.0);
      for (int i = 0; i < 3; ++i)
      {
        const double mid = c.F.O[i] + 0.5 * c.Length * c.F.D[i];
        light.Position[i] = mid + r * u[i] / ul;
        light.Direction[i] = mid - light.Position[i]; // the spot axis aims at the midpoint
        light.Color[i] = hovtest::Uniform(rng, 0.6, 1.0);
      }
      light.Intensity = hovtest::Uniform(rng, 0.5, 1.5);
      light.Attenuation[1] = hovtest::Uniform(rng, 0.0, 0.5);
      light.Attenuation[2] = hovtest::Uniform(rng, 0.0, 0.5);
      light.ConeAngle = 70.0;
      light.Exponent = hovtest::Uniform(rng, 1.0, 4.0);
      for (int j = 0; j <= 64; ++j) // keep the cone only if it holds the whole segment
      {
        const LD t = c.Length * j / 64.0L;
        const LD p[3] = { c.F.O[0] + t * c.F.D[0], c.F.O[1] + t * c.F.D[1], c.F.O[2] + t * c.F.D[2] };
        LD l[3], f;
        if (!hovtest::ReferenceLightAt(light, p, l, f))
        {
          light.ConeAngle = 180.0;
          break;
        }
      }
      spots += light.ConeAngle < 90.0;
      c.Lights.push_back(light);
    }
    const hovtest::CaseInputs in(c);
    const hov::TransferFunction& tf = in.TF;
    const hov::GradientOpacityFunction& go = in.GO;
    const hov::VolumeShadingSettings& vs = in.Shading;
    const hov::Polynomial& s = in.S;
    const hov::Polynomial* g = in.G;
    const hov::SegmentRay& ray = in.Ray;
    for (hov::EmissionModel em : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      const hovtest::RefRGBA ref = Reference(c, em);
      hov::ShadedSegmentSettings settings;
      settings.Emission = em;
      settings.Tolerance = 1e-9;
      const hov::ShadedSegmentResult r =
        hov::IntegrateShadedPolynomial(tf, s, g, c.Length, vs, c.GO.Nodes.empty() ? nullptr : &go, ray, settings);
      EXPECT_FALSE(r.ExactPath);
      const std::string where = "trial " + std::to_string(trial) + " estimate " + Str(r.ErrorEstimate);
      EXPECT_TRUE(r.Converged) << where;
      const double e = hovtest::MaxAbsDiff(r.Color, ref, 1.0);
      err.Add(e, where);
      ratio.Add(e / (r.ErrorEstimate + 1e-14), where);
    }
  }
  hovtest::ReportMeasured("ShadedSegment.PositionalVsReference tol 1e-9", err);
  hovtest::ReportMeasured("ShadedSegment.PositionalErrorOverEstimate", ratio);
  std::cout << "[measured] spot lights kept: " << spots << "\n";
  EXPECT_GT(spots, 3); // the cone branch was exercised
  EXPECT_LE(err.Value, 1e-9) << err.Where;
  EXPECT_LE(ratio.Value, 1.0) << ratio.Where;
}
}
