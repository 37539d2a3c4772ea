// Tests of hovTwoFieldSegment: extinction from field s1 and colour from field
// s2. Against the independent long double reference of hovSurfaceTestSupport.h
// (raw integrand, separate raw tables), closed forms for constant extinction,
// consistency with IntegratePolynomialScalar / IntegrateLinearScalar when
// s1 = s2, the exact path for two linear fields, and a no-NaN sweep.

#include "hovTwoFieldSegment.h"

#include "hovPolynomialSegment.h"
#include "hovRayIntegrator.h"
#include "hovTransferFunction.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestUtilities.h"
#include "hovSurfaceTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

using hovtest::Str;
using hovtest::Worst;

namespace
{
/// Kernel vs reference, colour relative to its scale: the kernel's tolerance
/// (1e-9 absolute per segment) with no extra margin (measured below).
constexpr double ReferenceTol = 1e-9;
/// s1 = s2 with two equal tables vs IntegratePolynomialScalar: the same
/// pieces and quadrature (degree >= 2: measured 0, bitwise); linear fields
/// go through IntegrateSegment per piece instead of IntegrateLinearScalar's
/// fractions: piece lengths differ by rounding. Measured 4.4e-16.
constexpr double SameFieldTol = 1e-14;
/// Closed forms with constant extinction (a few hundred ulp: the quadrature
/// of the colour polynomial x exponential is accurate to ~1e-15).
constexpr double ClosedFormTol = 1e-13;

std::string Describe(const hov::Polynomial& s)
{
  std::string d = "{";
  for (int i = 0; i <= s.Degree; ++i)
  {
    d += " " + Str(s.C[i]);
  }
  return d + " }";
}

double ColorScale(const hov::TransferFunctionSpec& spec, double length, hov::EmissionModel m)
{
  return m == hov::EmissionModel::WilliamsMax ? 1.0
                                              : std::max(1.0, length * spec.EmissionScale / spec.UnitDistance);
}

hov::PolynomialSegmentSettings Settings(hov::EmissionModel m)
{
  hov::PolynomialSegmentSettings s;
  s.Emission = m;
  return s;
}
}

TEST(TwoFieldSegment, SameFieldReproducesOneFieldIntegral)
{
  std::mt19937_64 rng(11);
  Worst worst;
  for (int trial = 0; trial < 120; ++trial)
  {
    const auto sem = static_cast<hov::OpacitySemantics>(trial % 3);
    const hov::TransferFunctionSpec spec = hovtest::RandomSurfaceSpec(rng, sem, 2 + trial % 5);
    hov::TransferFunction a, b; // equal tables, distinct objects: no shortcut
    ASSERT_TRUE(a.Build(spec));
    ASSERT_TRUE(b.Build(spec));
    const double length = hovtest::LogUniform(rng, 0.1, 10.0);
    const hov::Polynomial s = hovtest::RandomSurfaceField(rng, 1 + trial % 5, length);
    for (int m = 0; m < 2; ++m)
    {
      const auto model = static_cast<hov::EmissionModel>(m);
      const auto one = hov::IntegratePolynomialScalar(a, s, length, Settings(model));
      const auto two = hov::IntegrateTwoFields(a, s, b, s, length, Settings(model));
      const auto same = hov::IntegrateTwoFields(a, s, a, s, length, Settings(model));
      const double scale = ColorScale(spec, length, model);
      const double err = hovtest::MaxAbsDiff(one.Color, two.Color) / scale;
      worst.Add(err, hovtest::ToString(spec) + " s=" + Describe(s));
      EXPECT_LE(err, SameFieldTol) << hovtest::ToString(spec) << " s=" << Describe(s);
      EXPECT_EQ(hovtest::MaxAbsDiff(one.Color, same.Color), 0.0); // the shortcut
      if (hov::EffectiveDegree(s) >= 2)
      {
        EXPECT_EQ(one.Pieces, two.Pieces);
      }
    }
  }
  hovtest::ReportMeasured("TwoFieldSegment.SameFieldVsOneField", worst);
}

TEST(TwoFieldSegment, MatchesIndependentReference)
{
  std::mt19937_64 rng(23);
  Worst worst[2], ratio;
  int panels = 0;
  for (int trial = 0; trial < 40; ++trial)
  {
    const auto sem = trial % 2 ? hov::OpacitySemantics::RawExtinction : hov::OpacitySemantics::VTKUnstructured;
    const hov::TransferFunctionSpec specE = hovtest::RandomSurfaceSpec(rng, sem, 2 + trial % 4);
    hov::TransferFunctionSpec specC = hovtest::RandomSurfaceSpec(rng, sem, 2 + (trial / 2) % 4);
    specC.UnitDistance = specE.UnitDistance; // WVG emission scale read from the colour table
    hov::TransferFunction tfE, tfC;
    ASSERT_TRUE(tfE.Build(specE));
    ASSERT_TRUE(tfC.Build(specC));
    const double length = hovtest::LogUniform(rng, 0.1, 5.0);
    const hov::Polynomial s1 = hovtest::RandomSurfaceField(rng, 1 + trial % 4, length);
    const hov::Polynomial s2 = hovtest::RandomSurfaceField(rng, 1 + (trial / 4) % 4, length);
    for (int m = 0; m < 2; ++m)
    {
      const auto model = static_cast<hov::EmissionModel>(m);
      const auto r = hov::IntegrateTwoFields(tfE, s1, tfC, s2, length, Settings(model));
      const hovtest::RefRGBA ref = hovtest::ReferenceTwoFieldRange(hovtest::ToReference(specE), s1,
        hovtest::ToReference(specC), s2, 0.0L, length, hovtest::ToReference(model));
      const double scale = ColorScale(specC, length, model);
      const double err = hovtest::MaxAbsDiff(r.Color, ref, scale);
      const std::string where = "E:" + hovtest::ToString(specE) + " C:" + hovtest::ToString(specC) +
        " L=" + Str(length) + " s1=" + Describe(s1) + " s2=" + Describe(s2);
      worst[m].Add(err, where);
      EXPECT_LE(err, ReferenceTol) << where << " got " << hovtest::ToString(r.Color) << " ref "
                                   << hovtest::ToString(ref);
      EXPECT_TRUE(r.Converged);
      EXPECT_LE(r.ErrorEstimate, 1e-9 * (1 + 1e-12));
      // The estimate bounds the true colour error (opacity is exact).
      EXPECT_LE(err * scale, r.ErrorEstimate + 1e-13) << where;
      if (r.ErrorEstimate > 1e-13) // below, both are rounding
      {
        ratio.Add(err * scale / r.ErrorEstimate, where);
      }
      panels += r.Panels;
    }
  }
  hovtest::ReportMeasured("TwoFieldSegment.ReferenceWM", worst[0]);
  hovtest::ReportMeasured("TwoFieldSegment.ReferenceWVG", worst[1]);
  hovtest::ReportMeasured("TwoFieldSegment.TrueErrorOverEstimate", ratio);
  EXPECT_GT(panels, 0); // the quadrature path was exercised
}

TEST(TwoFieldSegment, TwoLinearFieldsAreExact)
{
  std::mt19937_64 rng(5);
  Worst worst;
  for (int trial = 0; trial < 60; ++trial)
  {
    const auto sem = trial % 2 ? hov::OpacitySemantics::RawExtinction : hov::OpacitySemantics::VTKUnstructured;
    const hov::TransferFunctionSpec specE = hovtest::RandomSurfaceSpec(rng, sem, 2 + trial % 5);
    hov::TransferFunctionSpec specC = hovtest::RandomSurfaceSpec(rng, sem, 2 + trial % 3);
    specC.UnitDistance = specE.UnitDistance;
    hov::TransferFunction tfE, tfC;
    ASSERT_TRUE(tfE.Build(specE));
    ASSERT_TRUE(tfC.Build(specC));
    const double length = hovtest::LogUniform(rng, 0.1, 10.0);
    const hov::Polynomial s1 = hovtest::RandomSurfaceField(rng, 1, length);
    const hov::Polynomial s2 = hovtest::RandomSurfaceField(rng, 1, length);
    for (int m = 0; m < 2; ++m)
    {
      const auto model = static_cast<hov::EmissionModel>(m);
      const auto r = hov::IntegrateTwoFields(tfE, s1, tfC, s2, length, Settings(model));
      EXPECT_EQ(r.Panels, 0); // closed form on every piece
      EXPECT_EQ(r.ErrorEstimate, 0.0);
      const hovtest::RefRGBA ref = hovtest::ReferenceTwoFieldRange(hovtest::ToReference(specE), s1,
        hovtest::ToReference(specC), s2, 0.0L, length, hovtest::ToReference(model));
      const double err = hovtest::MaxAbsDiff(r.Color, ref, ColorScale(specC, length, model));
      worst.Add(err, "s1=" + Describe(s1) + " s2=" + Describe(s2));
      EXPECT_LE(err, 1e-13) << "s1=" << Describe(s1) << " s2=" << Describe(s2);
    }
  }
  hovtest::ReportMeasured("TwoFieldSegment.LinearLinearVsReference", worst);
}

/// Constant extinction tau (s1 constant), colour c(t) = c0 + c1 t + c2 t^2 (a
/// linear colour table read along a quadratic s2 that crosses no node).
TEST(TwoFieldSegment, ConstantExtinctionClosedForm)
{
  hov::TransferFunctionSpec specE;
  specE.Semantics = hov::OpacitySemantics::RawExtinction;
  specE.Opacity = { { 0.0, 0.0 }, { 1.0, 2.0 } }; // tau = 2 s1
  specE.Color = { { 0.0, 0, 0, 0 } };
  hov::TransferFunctionSpec specC;
  specC.Semantics = hov::OpacitySemantics::RawExtinction;
  specC.Color = { { -10.0, 0.0, 0.0, 0.0 }, { 10.0, 1.0, 0.5, 0.25 } }; // c = (s + 10)/20 (1, .5, .25)
  specC.Opacity = { { 0.0, 0.0 } };
  hov::TransferFunction tfE, tfC;
  ASSERT_TRUE(tfE.Build(specE));
  ASSERT_TRUE(tfC.Build(specC));
  Worst worst;
  for (double s1Value : { 0.05, 0.3, 0.5 })
  {
    for (double length : { 0.1, 1.0, 7.0 })
    {
      const double tau = 2.0 * s1Value;
      const hov::Polynomial s1 = hov::Polynomial::FromCoefficients({ s1Value });
      // s2 = 1 + 2 t - 0.5 t^2 / L (|s2| < 10 on [0, L] for L <= 7)
      const hov::Polynomial s2 = hov::Polynomial::FromCoefficients({ 1.0, 0.5, -0.5 / length });
      const auto r = hov::IntegrateTwoFields(tfE, s1, tfC, s2, length, Settings(hov::EmissionModel::WilliamsMax));
      // c(t)/w = (s2 + 10)/20: c0 = 11/20, c1 = 0.5/20, c2 = -0.5/(20 L);
      // int_0^L t^k tau e^{-tau t} = k!/tau^k (1 - e^{-x} sum_{j<=k} x^j/j!), x = tau L.
      const long double x = static_cast<long double>(tau) * length, e = std::exp(-x);
      const long double m0 = 1 - e, m1 = (1 - e * (1 + x)) / tau,
                        m2 = 2 * (1 - e * (1 + x + x * x / 2)) / (static_cast<long double>(tau) * tau);
      const long double base = (11.0L / 20) * m0 + (0.5L / 20) * m1 - (0.5L / (20 * length)) * m2;
      const double weights[3] = { 1.0, 0.5, 0.25 };
      const double got[3] = { r.Color.R, r.Color.G, r.Color.B };
      for (int c = 0; c < 3; ++c)
      {
        const double err = std::fabs(got[c] - static_cast<double>(weights[c] * base));
        worst.Add(err, "tau=" + Str(tau) + " L=" + Str(length));
        EXPECT_LE(err, ClosedFormTol) << "tau=" << tau << " L=" << length;
      }
      EXPECT_NEAR(r.Color.A, static_cast<double>(m0), 1e-15);
    }
  }
  hovtest::ReportMeasured("TwoFieldSegment.ConstantExtinctionClosedForm", worst);
}

TEST(TwoFieldSegment, SweepHasNoNaN)
{
  std::mt19937_64 rng(77);
  for (int trial = 0; trial < 300; ++trial)
  {
    const auto sem = static_cast<hov::OpacitySemantics>(trial % 3);
    hov::TransferFunctionSpec specE = hovtest::RandomSurfaceSpec(rng, sem, 1 + trial % 4);
    if (trial % 7 == 0)
    {
      specE.Opacity.back().Opacity = 1.0; // opaque medium in GPU semantics
    }
    const hov::TransferFunctionSpec specC = hovtest::RandomSurfaceSpec(rng, sem, 1 + trial % 3);
    hov::TransferFunction tfE, tfC;
    tfE.Build(specE);
    tfC.Build(specC);
    const double length = hovtest::LogUniform(rng, 1e-12, 1e6);
    hov::Polynomial s1 = hovtest::RandomSurfaceField(rng, trial % 9, length);
    hov::Polynomial s2 = hovtest::RandomSurfaceField(rng, (trial / 9) % 9, length);
    for (int m = 0; m < 2; ++m)
    {
      const auto r = hov::IntegrateTwoFields(tfE, s1, tfC, s2, length, Settings(static_cast<hov::EmissionModel>(m)));
      EXPECT_TRUE(hovtest::AllFinite(r.Color)) << trial;
      EXPECT_GE(r.Color.A, 0.0);
      EXPECT_LE(r.Color.A, 1.0);
      EXPECT_TRUE(std::isfinite(r.ErrorEstimate));
    }
  }
  // Degenerate input: transparent.
  hov::TransferFunction empty, tf;
  tf.Build(hovtest::RandomSurfaceSpec(rng, hov::OpacitySemantics::RawExtinction, 3));
  const hov::Polynomial p = hov::Polynomial::FromCoefficients({ 0.5, 0.1 });
  hov::Polynomial bad = p;
  bad.C[1] = NAN;
  const auto st = Settings(hov::EmissionModel::WilliamsMax);
  EXPECT_EQ(hov::IntegrateTwoFields(empty, p, tf, p, 1.0, st).Color.A, 0.0);
  EXPECT_EQ(hov::IntegrateTwoFields(tf, bad, tf, p, 1.0, st).Color.A, 0.0);
  EXPECT_EQ(hov::IntegrateTwoFields(tf, p, tf, p, -1.0, st).Color.A, 0.0);
  EXPECT_EQ(hov::IntegrateTwoFields(tf, p, tf, p, INFINITY, st).Color.A, 0.0);
}
