// hovShadedSegment with colours far beyond [0, 1] (a table colour of 1e300,
// as in the robustness test's random tables): an absolute tolerance of 1e-9
// is then below the rounding of the panels' Chebyshev coefficients, which no
// bisection can resolve. The quadrature must accept a panel resolved to
// rounding instead of bisecting to its panel budget (256 per segment in the
// mapper, 4096 by default), and the result must still be the table's colour
// times the same integral: without specular light and clamping, the shaded
// colour is linear in the table's colour.

#include "hovShadedSegment.h"

#include "hovTransferFunction.h"
#include "hovVolumeShading.h"

#include "hovKernelTestUtilities.h"
#include "hovShadedSegmentTestCase.h" // Directional

#include <gtest/gtest.h>

#include <cmath>

using hovtest::Str;
using hovtest::Worst;

TEST(ShadedSegmentRounding, HugeColoursStopAtRounding)
{
  const hov::Polynomial s = hov::Polynomial::FromCoefficients({ 0.05, 2.7, -2.2 }); // peak in (0, 1)
  const hov::Polynomial g[3] = { hov::Polynomial::FromCoefficients({ 2.7, -4.4 }),
    hov::Polynomial::FromCoefficients({ 0.3 }), hov::Polynomial::FromCoefficients({ -0.2, 0.5 }) };
  const hov::ShadingLight light = hovtest::Directional(0.3, -0.2, -1.0);
  const hov::SegmentRay ray;
  Worst panels;
  for (bool shade : { false, true })
  {
    hov::VolumeShadingSettings vs;
    vs.Shade = shade;
    vs.Lights = &light;
    vs.LightCount = 1;
    vs.Material.Specular = 0.0;     // white highlights do not scale with the colour
    vs.Material.ClampColor = false; // nor does a clamped colour
    for (auto m : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      hov::ShadedSegmentResult unit;
      for (double big : { 0.0, 1.0, 1e6, 1e100, 1e300 })
      {
        hov::TransferFunction tf; // linear semantics: three nodes
        ASSERT_TRUE(tf.Build(hovtest::RedAtLastNode(
          big == 0.0 ? 1.0 : big, 0.8, hov::OpacitySemantics::VTKUnstructured)));
        hov::ShadedSegmentSettings settings;
        settings.Emission = m;
        settings.MaxPanels = 256; // the mapper's budget per shaded segment
        const std::string where = Str(big) + (shade ? " shaded" : " unshaded") +
          (m == hov::EmissionModel::WilliamsMax ? " WM" : " WVG");
        if (big == 0.0)
        {
          settings.Tolerance = 1e-14; // the reference: the unit colour, as tight as it goes
          settings.MaxPanels = 4096;
          unit = hov::IntegrateShadedPolynomial(tf, s, g, 1.3, vs, nullptr, ray, settings);
          EXPECT_LE(unit.ErrorEstimate, 1e-13) << where;
          continue;
        }
        const hov::ShadedSegmentResult r =
          hov::IntegrateShadedPolynomial(tf, s, g, 1.3, vs, nullptr, ray, settings);
        EXPECT_LE(r.Panels, 100) << where;
        panels.Add(r.Panels, where);
        hovtest::ExpectLinearInColour(r, unit, big, where);
        // 1e-9 absolute is met for colours of order 1, and cannot be for 1e100
        // (for 1e6 it is at the rounding: either way). A caller with another
        // route is told so too.
        settings.StopWhenUnconverged = true;
        const hov::ShadedSegmentResult stop =
          hov::IntegrateShadedPolynomial(tf, s, g, 1.3, vs, nullptr, ray, settings);
        if (big != 1e6)
        {
          EXPECT_EQ(r.Converged, big == 1.0) << where;
          EXPECT_EQ(stop.Converged, big == 1.0) << where << " (stop when unconverged)";
        }
      }
    }
  }
  hovtest::ReportMeasured("most panels of a shaded segment with huge colours", panels);
}
