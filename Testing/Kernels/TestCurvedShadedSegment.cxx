// Shaded segments through curved Lagrange cells (hovCurvedShadedSegment.h)
// with a constant field: the gradient is zero, so the sample has no normal
// and is ambient only (VolumeShadingSettings::GradientFloor), the same at
// every point: the segment equals the closed form of a constant field with
// that ambient-only transform, and its adaptive quadrature converges at
// once. Before the sampler subtracted the first node's scalar, the gradient
// was the rounding of sum_i dN_i s_i (~1e-16 in a random direction), each
// sample was lit from a random normal, and every segment ran to the panel
// limit unconverged (the robustness test's case 21001434 shows the same on
// the straight-edged quadratic cells of OPENGL_PROJECTION:
// FieldGradient.ConstantFieldHasZeroGradientSmallSlopesStay).
#include "hovCurvedRayCell.h"
#include "hovCurvedShadedSegment.h"
#include "hovEnclosure.h"
#include "hovTransferFunction.h"
#include "hovVolumeShading.h"

#include "hovKernelTestUtilities.h"
#include "hovLagrangeTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
TEST(CurvedShadedSegment, ConstantFieldIsUnlitAndConvergesAtOnce)
{
  std::mt19937_64 rng(311);
  hov::TransferFunctionSpec spec;
  spec.Color = { { 0.0, 0.9, 0.5, 0.2 }, { 10.0, 0.1, 0.6, 0.9 } };
  spec.Opacity = { { 0.0, 0.4 }, { 10.0, 0.9 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  hov::ShadingLight light;
  light.Direction[0] = 0.3;
  light.Direction[1] = -0.2;
  light.Direction[2] = -1.0;
  hov::VolumeShadingSettings vs;
  vs.Shade = true;
  vs.Lights = &light;
  vs.LightCount = 1;
  hov::CurvedSegmentSettings settings;
  settings.Shading = &vs;
  settings.Quadrature.Tolerance = 1e-9;
  double worst = 0.0;
  int segments = 0;
  for (const hovtest::LagrangeCase& c : hovtest::AllLagrangeCases(4))
  {
    hovtest::LagrangeTestCell cell;
    ASSERT_TRUE(hovtest::InitBasis(c, cell.Basis));
    const double value = 1.685406566 + segments; // any constant, not a round number
    hovtest::PlaceNodes(cell, hovtest::RandomMap(rng, 0.15), 0.0, rng,
      [value](const double*) { return value; });
    const hov::LagrangeCellView view = cell.View();
    hov::CurvedCellFaces faces;
    ASSERT_TRUE(hov::BuildCurvedFaces(view, faces));
    hov::CellDerivativeBounds bounds;
    ASSERT_TRUE(hov::ComputeCellDerivativeBounds(view, bounds));
    double pc[3], x[3];
    hovtest::RandomPC(cell.Basis, rng, 0.1, pc);
    hov::EvaluateLagrangePosition(view, pc, x);
    const double d[3] = { 0.0, 0.0, 1.0 }, o[3] = { x[0], x[1], x[2] - 3.0 };
    hov::CurvedRayInterval iv[8];
    const int n = hov::RayCurvedCellIntervals(view, faces, o, d, 0.0, 6.0, iv, 8);
    ASSERT_GE(n, 1) << c.Name();
    const hov::CurvedSegmentResult r = hov::IntegrateCurvedShadedSegment(
      view, bounds, tf, o, d, iv[0].T0, iv[0].T1, iv[0].PC0, settings);
    // The closed form: constant field, the unlit (ambient-only) transform.
    const double toViewer[3] = { 0.0, 0.0, -1.0 }, zero[3] = { 0.0, 0.0, 0.0 };
    const hov::ShadingTransform shade = hov::ComputeShadingTransform(vs, zero, x, toViewer);
    EXPECT_FALSE(shade.Lit);
    const hov::RGBA want = hov::IntegrateLinearScalarShaded(
      tf, value, value, iv[0].T1 - iv[0].T0, shade, 1.0, hov::IntegrationSettings());
    const double e = std::max({ std::abs(r.Color.R - want.R), std::abs(r.Color.G - want.G),
      std::abs(r.Color.B - want.B), std::abs(r.Color.A - want.A) });
    EXPECT_LE(e, 1e-12) << c.Name();
    EXPECT_TRUE(r.Converged) << c.Name();
    EXPECT_LE(r.Pieces, 4) << c.Name() << ": panels";
    worst = std::max(worst, e);
    ++segments;
  }
  hovtest::ReportMeasured("CurvedShadedSegment.ConstantFieldVsClosedForm", worst);
}
}
