// Properties of hovPolynomialSegment: composition ([0,a] over [a,L] equals
// [0,L]), reversal (t -> L - t) consistent with the compositing order,
// degenerate input (zero length, constants, NaN, degree 9), opaque and huge
// extinction without NaN, the piece count of a known case, and the ordered
// isovalue crossings.

#include "hovPolynomialSegment.h"

#include "hovRayIntegrator.h"
#include "hovSegmentIntegral.h"
#include "hovTransferFunction.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestUtilities.h"
#include "hovPolynomialTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using hovtest::Str;
using hovtest::Worst;

namespace
{
hov::TransferFunctionSpec Spec(std::mt19937_64& rng, hov::OpacitySemantics sem)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = sem;
  spec.UnitDistance = hovtest::LogUniform(rng, 0.3, 3.0);
  spec.GPUTolerance = 1e-5;
  for (double x : { 0.1, 0.35, 0.6, 0.85 })
  {
    spec.Color.push_back(
      { x + hovtest::Uniform(rng, -0.05, 0.05), hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1),
        hovtest::Uniform(rng, 0, 1) });
  }
  for (double x : { 0.2, 0.3, 0.5, 0.9 })
  {
    spec.Opacity.push_back({ x + hovtest::Uniform(rng, -0.05, 0.05), hovtest::Uniform(rng, 0, 0.9) });
  }
  return spec;
}

/// A random cubic on [0, L] with values in about [0, 1] and interior extrema.
hov::Polynomial Field(std::mt19937_64& rng, double length)
{
  const double r1 = hovtest::Uniform(rng, 0.1, 0.5), r2 = hovtest::Uniform(rng, 0.5, 0.9);
  // s = 0.5 + k x (x - r1)(x - r2)... use s' roots r1, r2: s = 0.5 + k (x^3/3 - (r1+r2) x^2/2 + r1 r2 x)
  const double k = hovtest::Uniform(rng, 2.0, 8.0) * (rng() % 2 ? 1 : -1);
  hov::Polynomial p = hov::Polynomial::FromCoefficients(
    { 0.5, k * r1 * r2 / length, -k * (r1 + r2) / (2 * length * length), k / (3 * length * length * length) });
  return p;
}

hov::PolynomialSegmentResult Integrate(
  const hov::TransferFunction& tf, const hov::Polynomial& s, double length, hov::EmissionModel m)
{
  hov::PolynomialSegmentSettings settings;
  settings.Emission = m;
  return hov::IntegratePolynomialScalar(tf, s, length, settings);
}
}

TEST(PolynomialSegmentProperties, CompositionAndReversal)
{
  std::mt19937_64 rng(31);
  Worst composition, reversalAlpha, reversalOver;
  for (int trial = 0; trial < 150; ++trial)
  {
    const auto sem = static_cast<hov::OpacitySemantics>(trial % 3);
    const hov::TransferFunctionSpec spec = Spec(rng, sem);
    hov::TransferFunction tf;
    ASSERT_TRUE(tf.Build(spec));
    const double length = hovtest::LogUniform(rng, 0.2, 5.0);
    const hov::Polynomial s = trial % 2 ? Field(rng, length)
                                        : hov::Polynomial::FromCoefficients({ 0.05, 3.6 / length, -3.6 / (length * length) });
    const double a = length * hovtest::Uniform(rng, 0.05, 0.95);
    const auto model = trial % 4 < 2 ? hov::EmissionModel::WilliamsMax : hov::EmissionModel::WilhelmsVanGelder;
    const std::string where = hovtest::ToString(spec) + " L=" + Str(length) + " a=" + Str(a);

    // Composition: [0, a] over [a, L] (the back part as a polynomial in t - a).
    const hov::RGBA whole = Integrate(tf, s, length, model).Color;
    const hov::RGBA front = Integrate(tf, s, a, model).Color;
    const hov::RGBA back = Integrate(tf, hov::ComposeAffine(s, a, 1.0), length - a, model).Color;
    const double e = hovtest::MaxAbsDiff(hov::Over(front, back), whole);
    composition.Add(e, where);
    EXPECT_LE(e, 2e-9) << where; // each side is within the 1e-9 tolerance

    // Reversal: the same ray seen from the other end has the same opacity, and
    // its halves composite in the opposite order.
    const hov::Polynomial rev = hov::ComposeAffine(s, length, -1.0);
    const hov::RGBA wholeRev = Integrate(tf, rev, length, model).Color;
    reversalAlpha.Add(std::fabs(wholeRev.A - whole.A), where);
    EXPECT_NEAR(wholeRev.A, whole.A, 1e-14) << where;
    const hov::RGBA backRev = Integrate(tf, rev, length - a, model).Color; // old [a, L] seen from L
    const hov::RGBA frontRev = Integrate(tf, hov::ComposeAffine(rev, length - a, 1.0), a, model).Color;
    EXPECT_NEAR(backRev.A, back.A, 1e-14) << where;
    EXPECT_NEAR(frontRev.A, front.A, 1e-14) << where;
    const double o = hovtest::MaxAbsDiff(hov::Over(backRev, frontRev), wholeRev);
    reversalOver.Add(o, where);
    EXPECT_LE(o, 2e-9) << where;
  }
  hovtest::ReportMeasured("PolynomialSegment.CompositionAbs", composition);
  hovtest::ReportMeasured("PolynomialSegment.ReversalAlphaAbs", reversalAlpha);
  hovtest::ReportMeasured("PolynomialSegment.ReversalCompositionAbs", reversalOver);
}

TEST(PolynomialSegmentProperties, ReversalOfConstantChromaticityIsSymmetric)
{
  // Williams-Max with one colour everywhere: C = c A both ways, whatever the order.
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Color = { { 0.0, 0.3, 0.6, 0.9 } };
  spec.Opacity = { { 0.0, 0.1 }, { 0.4, 2.0 }, { 0.7, 0.3 }, { 1.0, 1.5 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  const double length = 2.0;
  const hov::Polynomial s = hov::Polynomial::FromCoefficients({ 0.1, 1.0, -0.3, -0.05 });
  const hov::RGBA f = Integrate(tf, s, length, hov::EmissionModel::WilliamsMax).Color;
  const hov::RGBA r = Integrate(tf, hov::ComposeAffine(s, length, -1.0), length, hov::EmissionModel::WilliamsMax).Color;
  EXPECT_NEAR(f.A, r.A, 1e-15);
  EXPECT_NEAR(f.R, 0.3 * f.A, 1e-15);
  EXPECT_NEAR(r.G, 0.6 * r.A, 1e-15);
  EXPECT_GT(f.A, 0.5);
}

TEST(PolynomialSegmentProperties, DegenerateInputs)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Color = { { 0.0, 1.0, 0.0, 0.0 }, { 1.0, 0.0, 0.0, 1.0 } };
  spec.Opacity = { { 0.0, 0.5 }, { 1.0, 1.5 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  const hov::Polynomial q = hov::Polynomial::FromCoefficients({ 0.2, 1.0, -1.0 });
  for (double len : { 0.0, -1.0, double(NAN), double(INFINITY) })
  {
    const hov::PolynomialSegmentResult r = Integrate(tf, q, len, hov::EmissionModel::WilliamsMax);
    EXPECT_EQ(r.Color.A, 0.0);
    EXPECT_EQ(r.Color.R, 0.0);
    EXPECT_EQ(r.Pieces, 0);
  }
  hov::Polynomial bad = q;
  bad.C[1] = NAN;
  EXPECT_EQ(Integrate(tf, bad, 1.0, hov::EmissionModel::WilliamsMax).Color.A, 0.0);
  // Degree 9 is rejected (its depth does not fit), without NaN.
  hov::Polynomial nine = q;
  nine.Degree = 9;
  nine.C[9] = 1.0;
  const hov::PolynomialSegmentResult r9 = Integrate(tf, nine, 1.0, hov::EmissionModel::WilliamsMax);
  EXPECT_FALSE(r9.Converged);
  EXPECT_EQ(r9.Color.A, 0.0);
  // Constant field: the closed form of a constant segment.
  const hov::Polynomial c = hov::Polynomial::FromCoefficients({ 0.5, 0.0, 0.0 });
  const hov::PolynomialSegmentResult rc = Integrate(tf, c, 2.0, hov::EmissionModel::WilliamsMax);
  const double A = -std::expm1(-1.0 * 2.0); // tau(0.5) = 1
  EXPECT_NEAR(rc.Color.A, A, 1e-15);
  EXPECT_NEAR(rc.Color.R, 0.5 * A, 1e-15);
  EXPECT_NEAR(rc.Color.B, 0.5 * A, 1e-15);
  // Empty table: transparent.
  hov::TransferFunction empty;
  EXPECT_EQ(Integrate(empty, q, 1.0, hov::EmissionModel::WilliamsMax).Color.A, 0.0);
}

TEST(PolynomialSegmentProperties, PieceCountOfAKnownCase)
{
  // s = 1 - 4 (t - 0.5)^2 on [0, 1]: 0 -> 1 -> 0. Nodes 0.25, 0.5, 0.75 are
  // crossed twice each: 4 intervals on the way up, 4 on the way down.
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Color = { { 0.25, 1, 0, 0 }, { 0.5, 0, 1, 0 }, { 0.75, 0, 0, 1 } };
  spec.Opacity = { { 0.25, 0.5 }, { 0.5, 2.0 }, { 0.75, 1.0 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  const hov::Polynomial s = hov::Polynomial::FromCoefficients({ 0.0, 4.0, -4.0 });
  for (auto m : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
  {
    const hov::PolynomialSegmentResult r = Integrate(tf, s, 1.0, m);
    EXPECT_EQ(r.Pieces, 8);
    EXPECT_TRUE(r.Converged);
    const hovtest::RefRGBA ref = hovtest::ReferencePolynomialRay(
      hovtest::ToReference(spec), s, 1.0, hovtest::ToReference(m));
    EXPECT_LE(hovtest::MaxAbsDiff(r.Color, ref, 1.0), 1e-12);
  }
}

TEST(PolynomialSegmentProperties, OpaqueAndHugeExtinctionNoNaN)
{
  // GPU-compatible semantics with opacity 1 on [0.6, 0.8]: tau = +inf there.
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::GPUCompatible;
  spec.Color = { { 0.0, 0.2, 0.4, 0.6 }, { 1.0, 0.8, 0.6, 0.4 } };
  spec.Opacity = { { 0.0, 0.1 }, { 0.6, 1.0 }, { 0.8, 1.0 }, { 1.0, 0.2 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  const hov::Polynomial s = hov::Polynomial::FromCoefficients({ 0.0, 4.0, -4.0 }); // peak 1 at 0.5
  for (auto m : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
  {
    const hov::PolynomialSegmentResult r = Integrate(tf, s, 1.0, m);
    EXPECT_TRUE(hovtest::AllFinite(r.Color));
    EXPECT_EQ(r.Color.A, 1.0);
    const hovtest::RefRGBA ref = hovtest::ReferencePolynomialRay(
      hovtest::ToReference(spec), s, 1.0, hovtest::ToReference(m));
    // GPU bound 2 GPUTolerance (1e-4) plus the OpaqueClamp region near a = 1.
    EXPECT_LE(hovtest::MaxAbsDiff(r.Color, ref, 1.0), 2e-4) << hovtest::ToString(r.Color) << " "
                                                            << hovtest::ToString(ref);
  }
  // Huge finite extinction (raw): the segment is opaque within ~1/tau of its
  // front, so the WM colour is the front colour to O(1/tau); no NaN.
  for (double big : { 1e6, 1e100, 1e300 })
  {
    hov::TransferFunctionSpec raw;
    raw.Semantics = hov::OpacitySemantics::RawExtinction;
    raw.Color = { { 0.0, 0.0, 0.5, 1.0 }, { 1.0, 1.0, 0.5, 0.0 } };
    raw.Opacity = { { 0.0, big }, { 1.0, 2 * big } };
    hov::TransferFunction t2;
    ASSERT_TRUE(t2.Build(raw));
    const hov::Polynomial f = hov::Polynomial::FromCoefficients({ 0.3, 1.0, -1.2 });
    for (auto m : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      const hov::PolynomialSegmentResult r = Integrate(t2, f, 1.0, m);
      EXPECT_TRUE(hovtest::AllFinite(r.Color)) << big;
      EXPECT_TRUE(r.Converged) << big;
      EXPECT_EQ(r.Color.A, 1.0);
      if (m == hov::EmissionModel::WilliamsMax)
      {
        EXPECT_NEAR(r.Color.R, 0.3, 10.0 / big);
        EXPECT_NEAR(r.Color.B, 0.7, 10.0 / big);
      }
      else
      {
        EXPECT_LE(r.Color.R, 1.0 / big); // emission g / tau absorbed at once
      }
    }
  }
}

// Colours far beyond [0, 1] (a table with a colour of 1e300, the robustness
// test's case 4711048797): an absolute tolerance of 1e-9 is then below the
// rounding of the integrals, which the quadrature cannot resolve. It must not
// bisect until the panel budget (4096 per segment) is gone: a panel whose
// Kronrod-Gauss difference is at the rule's rounding is accepted, Converged
// says that the target was missed, and the colour is still the table's colour
// times the same integral (the integral is linear in the colours), compared
// to 1e-10 relative with the unit colour's integral (a run at tolerance 1e-14).
TEST(PolynomialSegmentProperties, HugeColoursStopAtRounding)
{
  const hov::Polynomial s = hov::Polynomial::FromCoefficients({ 0.05, 2.7, -2.2 }); // peak in (0, 1)
  Worst panels;
  // Moderate opacity, and an optically thin segment (depth ~1e-7: Williams-Max's
  // integrand u' (e^-D - e^-D(1)) then cancels to far below its terms).
  for (double opacity : { 0.8, 3e-7 })
  {
    for (auto m : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      hov::PolynomialSegmentResult unit;
      for (double big : { 0.0, 1.0, 1e6, 1e100, 1e300 })
      {
        // The red channel of the last node only: colour big there, 0 elsewhere.
        hov::TransferFunction tf;
        ASSERT_TRUE(tf.Build(hovtest::RedAtLastNode(
          big == 0.0 ? 1.0 : big, opacity, hov::OpacitySemantics::GPUCompatible)));
        hov::PolynomialSegmentSettings settings;
        settings.Emission = m;
        const std::string where = Str(big) + " opacity " + Str(opacity) +
          (m == hov::EmissionModel::WilliamsMax ? " WM" : " WVG");
        if (big == 0.0)
        {
          settings.Tolerance = 1e-14; // the reference: the unit colour, as tight as it goes
          unit = hov::IntegratePolynomialScalar(tf, s, 1.3, settings);
          EXPECT_LE(unit.ErrorEstimate, 1e-13) << where;
          continue;
        }
        const hov::PolynomialSegmentResult r = hov::IntegratePolynomialScalar(tf, s, 1.3, settings);
        EXPECT_LE(r.Panels, 400) << where << ": " << r.Panels << " panels";
        panels.Add(r.Panels, where);
        hovtest::ExpectLinearInColour(r, unit, big, where);
        // 1e-9 absolute is met for colours of order 1, and cannot be for 1e100
        // (for 1e6 it is at the rounding: either way).
        if (big != 1e6)
        {
          EXPECT_EQ(r.Converged, big == 1.0) << where;
        }
      }
    }
  }
  hovtest::ReportMeasured("most panels of a segment with huge colours", panels);
}

TEST(PolynomialSegmentProperties, IsovalueCrossingsOrdered)
{
  // s = 1 - 4 (t - 0.5)^2 on [0, 1].
  const hov::Polynomial s = hov::Polynomial::FromCoefficients({ 0.0, 4.0, -4.0 });
  const double iso[] = { 0.75, 0.5, 1.0, 2.0, 0.0 };
  std::vector<hov::IsovalueCrossing> out;
  ASSERT_EQ(hov::IsovalueCrossings(s, 1.0, iso, 5, out), 7);
  const double h = std::sqrt(0.125);
  const double t[] = { 0.0, 0.5 - h, 0.25, 0.5, 0.75, 0.5 + h, 1.0 };
  const int index[] = { 4, 1, 0, 2, 0, 1, 4 };
  const int dir[] = { 1, 1, 1, 0, -1, -1, -1 };
  for (int i = 0; i < 7; ++i)
  {
    EXPECT_NEAR(out[i].T, t[i], 2e-16) << i;
    EXPECT_EQ(out[i].Index, index[i]) << i;
    EXPECT_EQ(out[i].Direction, dir[i]) << i;
  }
  // A constant field has no crossings; a bad length gives none.
  EXPECT_EQ(hov::IsovalueCrossings(hov::Polynomial::FromCoefficients({ 0.5 }), 1.0, iso, 5, out), 0);
  EXPECT_EQ(hov::IsovalueCrossings(s, NAN, iso, 5, out), 0);
}
