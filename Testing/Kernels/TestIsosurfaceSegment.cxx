// Tests of hovIsosurface: the crossings a segment owns (a surface on a face
// shared by consecutive segments counts once), the segment integral with
// embedded surfaces against an independent long double reference and closed
// forms (occlusion by the volume in front, order of nested surfaces), zero-
// opacity surfaces, lazy shading, hit colours, and a no-NaN sweep.

#include "hovIsosurface.h"

#include "hovPolynomialSegment.h"
#include "hovTransferFunction.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestUtilities.h"
#include "hovSurfaceTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using hovtest::Str;
using hovtest::Worst;

namespace
{
/// Splitting the volume integral at zero-opacity surfaces: exact (linear)
/// pieces compose to rounding (measured 3.3e-16); quadrature pieces to within
/// the quadrature's accuracy, far below its 1e-9 tolerance (measured 4.4e-16).
constexpr double SplitTol = 1e-13;
/// Kernel vs reference with surfaces: the volume tolerance 1e-9.
constexpr double ReferenceTol = 1e-9;

std::string Describe(const hov::Polynomial& s, double length)
{
  std::string d = "L=" + Str(length) + " s={";
  for (int i = 0; i <= s.Degree; ++i)
  {
    d += " " + Str(s.C[i]);
  }
  return d + " }";
}

hov::PolynomialSegmentSettings Settings(hov::EmissionModel m)
{
  hov::PolynomialSegmentSettings s;
  s.Emission = m;
  return s;
}

/// Surface colour per isovalue index (premultiplied), as a shade callable.
struct ConstantShade
{
  std::vector<hov::RGBA> Colors;
  int Calls = 0;
  hov::RGBA operator()(const hov::IsovalueCrossing& c)
  {
    ++this->Calls;
    return this->Colors[c.Index];
  }
};

/// Number of sign changes of s - iso on [0, L] in long double (the true
/// crossing count of a transversal surface), counting a zero at t = 0.
int TrueCrossings(const hov::Polynomial& s, double length, double iso)
{
  std::vector<long double> ts;
  hovtest::ScanLevel(s, iso, 0.0L, length, 20000, ts);
  return static_cast<int>(ts.size());
}
}

TEST(IsosurfaceSegment, NoCrossingIsTheOneFieldIntegral)
{
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 40; ++trial)
  {
    hov::TransferFunction tf;
    ASSERT_TRUE(tf.Build(hovtest::RandomSurfaceSpec(rng, hov::OpacitySemantics::VTKUnstructured, 4)));
    const double length = hovtest::LogUniform(rng, 0.1, 10.0);
    const hov::Polynomial s = hovtest::RandomSurfaceField(rng, 1 + trial % 4, length);
    ConstantShade shade;
    const auto r = hov::IntegrateWithSurfaces(tf, s, length, nullptr, 0, shade, Settings(hov::EmissionModel::WilliamsMax));
    const auto ref = hov::IntegratePolynomialScalar(tf, s, length, Settings(hov::EmissionModel::WilliamsMax));
    EXPECT_EQ(hovtest::MaxAbsDiff(r.Color, ref.Color), 0.0) << Describe(s, length);
    EXPECT_EQ(shade.Calls, 0);
  }
}

TEST(IsosurfaceSegment, ZeroOpacitySurfacesChangeNothing)
{
  std::mt19937_64 rng(4);
  Worst worst;
  int split = 0;
  for (int trial = 0; trial < 80; ++trial)
  {
    hov::TransferFunction tf;
    ASSERT_TRUE(tf.Build(hovtest::RandomSurfaceSpec(rng, static_cast<hov::OpacitySemantics>(trial % 3), 4)));
    const double length = hovtest::LogUniform(rng, 0.1, 10.0);
    const hov::Polynomial s = hovtest::RandomSurfaceField(rng, 1 + trial % 4, length);
    const double iso[3] = { hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1) };
    std::vector<hov::IsovalueCrossing> crossings;
    hov::SurfaceCrossings(s, length, iso, 3, true, crossings);
    split += static_cast<int>(crossings.size());
    ConstantShade shade{ std::vector<hov::RGBA>(3) };
    for (int m = 0; m < 2; ++m)
    {
      const auto model = static_cast<hov::EmissionModel>(m);
      const auto r = hov::IntegrateWithSurfaces(tf, s, length, crossings.data(),
        static_cast<int>(crossings.size()), shade, Settings(model));
      const auto ref = hov::IntegratePolynomialScalar(tf, s, length, Settings(model));
      const double scale = m == 0 ? 1.0 : std::max(1.0, length * tf.GetEmissionFactor());
      const double err = hovtest::MaxAbsDiff(r.Color, ref.Color) / scale;
      worst.Add(err, Describe(s, length));
      EXPECT_LE(err, SplitTol) << Describe(s, length);
      EXPECT_EQ(r.Surfaces, 0);
      EXPECT_LE(r.ErrorEstimate, 1e-9 * (1 + 1e-12));
    }
  }
  EXPECT_GT(split, 40); // the segments were actually split
  hovtest::ReportMeasured("IsosurfaceSegment.ZeroOpacitySplit", worst);
}

TEST(IsosurfaceSegment, MatchesReferenceWithSurfaces)
{
  std::mt19937_64 rng(8);
  Worst worst;
  int surfaces = 0;
  for (int trial = 0; trial < 30; ++trial)
  {
    const auto sem = trial % 2 ? hov::OpacitySemantics::RawExtinction : hov::OpacitySemantics::VTKUnstructured;
    const hov::TransferFunctionSpec spec = hovtest::RandomSurfaceSpec(rng, sem, 2 + trial % 4);
    hov::TransferFunction tf;
    ASSERT_TRUE(tf.Build(spec));
    const double length = hovtest::LogUniform(rng, 0.1, 3.0);
    const hov::Polynomial s = hovtest::RandomSurfaceField(rng, 1 + trial % 4, length);
    const double iso[2] = { hovtest::Uniform(rng, 0.1, 0.9), hovtest::Uniform(rng, 0.1, 0.9) };
    ConstantShade shade;
    for (int i = 0; i < 2; ++i)
    {
      const double a = hovtest::Uniform(rng, 0.1, 0.9);
      shade.Colors.push_back({ a * hovtest::Uniform(rng, 0, 1), a * hovtest::Uniform(rng, 0, 1), a * 0.5, a });
    }
    std::vector<hov::IsovalueCrossing> crossings;
    hov::SurfaceCrossings(s, length, iso, 2, true, crossings);
    // Reference: crossings by scan + bisection in long double, volume pieces
    // by the raw integrand, surfaces composited by hand.
    std::vector<std::pair<long double, int>> refCross;
    for (int i = 0; i < 2; ++i)
    {
      std::vector<long double> ts;
      hovtest::ScanLevel(s, iso[i], 0.0L, length, 20000, ts);
      for (long double t : ts)
      {
        refCross.push_back({ t, i });
      }
    }
    std::sort(refCross.begin(), refCross.end());
    ASSERT_EQ(refCross.size(), crossings.size()) << Describe(s, length);
    const auto ref = hovtest::ToReference(spec);
    const auto model = static_cast<hov::EmissionModel>(trial % 2);
    hovtest::RefRGBA expect;
    long double tPrev = 0.0L;
    for (const auto& c : refCross)
    {
      hovtest::RefCompositeBehind(expect, hovtest::ReferenceTwoFieldRange(ref, s, ref, s, tPrev, c.first,
        hovtest::ToReference(model)));
      const hov::RGBA& sc = shade.Colors[c.second];
      hovtest::RefCompositeBehind(expect, hovtest::RefRGBA{ sc.R, sc.G, sc.B, sc.A });
      tPrev = c.first;
    }
    hovtest::RefCompositeBehind(expect,
      hovtest::ReferenceTwoFieldRange(ref, s, ref, s, tPrev, length, hovtest::ToReference(model)));
    const auto r = hov::IntegrateWithSurfaces(tf, s, length, crossings.data(),
      static_cast<int>(crossings.size()), shade, Settings(model));
    const double scale = model == hov::EmissionModel::WilliamsMax ? 1.0
                                                                  : std::max(1.0, length * tf.GetEmissionFactor());
    const double err = hovtest::MaxAbsDiff(r.Color, expect, scale);
    worst.Add(err, Describe(s, length));
    EXPECT_LE(err, ReferenceTol) << Describe(s, length) << " got " << hovtest::ToString(r.Color)
                                 << " ref " << hovtest::ToString(expect);
    surfaces += r.Surfaces;
  }
  EXPECT_GT(surfaces, 20);
  hovtest::ReportMeasured("IsosurfaceSegment.ReferenceWithSurfaces", worst);
}

/// Three fields (HIAC 5): extinction from s1, colour from s2 (separate
/// tables), surfaces of a third field s3; against the reference.
TEST(IsosurfaceSegment, ThreeFieldsMatchReference)
{
  std::mt19937_64 rng(18);
  Worst worst;
  int surfaces = 0;
  for (int trial = 0; trial < 16; ++trial)
  {
    const auto sem = trial % 2 ? hov::OpacitySemantics::RawExtinction : hov::OpacitySemantics::VTKUnstructured;
    const hov::TransferFunctionSpec specE = hovtest::RandomSurfaceSpec(rng, sem, 2 + trial % 3);
    hov::TransferFunctionSpec specC = hovtest::RandomSurfaceSpec(rng, sem, 2 + trial % 4);
    specC.UnitDistance = specE.UnitDistance;
    hov::TransferFunction tfE, tfC;
    ASSERT_TRUE(tfE.Build(specE));
    ASSERT_TRUE(tfC.Build(specC));
    const double length = hovtest::LogUniform(rng, 0.1, 3.0);
    const hov::Polynomial s1 = hovtest::RandomSurfaceField(rng, 1 + trial % 3, length);
    const hov::Polynomial s2 = hovtest::RandomSurfaceField(rng, 1 + (trial / 3) % 3, length);
    const hov::Polynomial s3 = hovtest::RandomSurfaceField(rng, 1 + (trial / 2) % 3, length);
    const double iso[1] = { hovtest::Uniform(rng, 0.2, 0.8) };
    ConstantShade shade{ { hov::RGBA{ 0.3, 0.2, 0.1, 0.4 } } };
    std::vector<hov::IsovalueCrossing> crossings;
    hov::SurfaceCrossings(s3, length, iso, 1, true, crossings);
    std::vector<long double> ts;
    hovtest::ScanLevel(s3, iso[0], 0.0L, length, 20000, ts);
    ASSERT_EQ(ts.size(), crossings.size());
    const auto model = static_cast<hov::EmissionModel>(trial % 2);
    const auto refE = hovtest::ToReference(specE), refC = hovtest::ToReference(specC);
    hovtest::RefRGBA expect;
    long double tPrev = 0.0L;
    ts.push_back(length);
    for (size_t k = 0; k < ts.size(); ++k)
    {
      hovtest::RefCompositeBehind(expect,
        hovtest::ReferenceTwoFieldRange(refE, s1, refC, s2, tPrev, ts[k], hovtest::ToReference(model)));
      if (k + 1 < ts.size())
      {
        hovtest::RefCompositeBehind(expect, hovtest::RefRGBA{ 0.3, 0.2, 0.1, 0.4 });
      }
      tPrev = ts[k];
    }
    const auto r = hov::IntegrateWithSurfaces(tfE, s1, tfC, s2, length, crossings.data(),
      static_cast<int>(crossings.size()),
      [](void* u, const hov::IsovalueCrossing& c) { return (*static_cast<ConstantShade*>(u))(c); }, &shade,
      Settings(model));
    const double scale = model == hov::EmissionModel::WilliamsMax ? 1.0
                                                                  : std::max(1.0, length * tfC.GetEmissionFactor());
    const double err = hovtest::MaxAbsDiff(r.Color, expect, scale);
    worst.Add(err, Describe(s3, length));
    EXPECT_LE(err, ReferenceTol) << "trial " << trial;
    surfaces += r.Surfaces;
  }
  EXPECT_GT(surfaces, 8);
  hovtest::ReportMeasured("IsosurfaceSegment.ThreeFieldsReference", worst);
}

/// Constant extinction tau and colour c, s = t: one surface S at t*, seen
/// through the volume in front: C = c(1 - e^{-tau t*}) + e^{-tau t*}
/// (S + (1 - S.A) c (1 - e^{-tau (L - t*)})).
TEST(IsosurfaceSegment, OcclusionByVolumeClosedForm)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Opacity = { { 0.0, 0.7 } };
  spec.Color = { { 0.0, 0.2, 0.4, 0.6 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  const double tau = 0.7, length = 2.0;
  const hov::Polynomial s = hov::Polynomial::FromCoefficients({ 0.0, 1.0 });
  Worst worst;
  for (double tStar : { 0.1, 0.75, 1.9 })
  {
    const double iso[1] = { tStar };
    std::vector<hov::IsovalueCrossing> crossings;
    ASSERT_EQ(hov::SurfaceCrossings(s, length, iso, 1, false, crossings), 1);
    EXPECT_DOUBLE_EQ(crossings[0].T, tStar);
    EXPECT_EQ(crossings[0].Direction, 1);
    ConstantShade shade{ { hov::RGBA{ 0.5, 0.25, 0.0, 0.5 } } };
    const auto r = hov::IntegrateWithSurfaces(tf, s, length, crossings.data(), 1, shade, Settings(hov::EmissionModel::WilliamsMax));
    const double front = std::exp(-tau * tStar), back = -std::expm1(-tau * (length - tStar));
    const double sc[3] = { 0.5, 0.25, 0.0 }, c[3] = { 0.2, 0.4, 0.6 };
    const double got[3] = { r.Color.R, r.Color.G, r.Color.B };
    for (int k = 0; k < 3; ++k)
    {
      const double expect = c[k] * (1 - front) + front * (sc[k] + 0.5 * c[k] * back);
      worst.Add(std::fabs(got[k] - expect), "t*=" + Str(tStar));
      EXPECT_NEAR(got[k], expect, 1e-15) << "t*=" << tStar;
    }
    EXPECT_NEAR(r.Color.A, 1 - front * 0.5 * (1 - back), 1e-15);
  }
  hovtest::ReportMeasured("IsosurfaceSegment.OcclusionClosedForm", worst);
}

/// Transparent volume, two nested surfaces crossed in both directions: the
/// front one is composited first (S_front over S_back), whatever their index.
TEST(IsosurfaceSegment, NestedSurfacesCompositeInDepthOrder)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Opacity = { { 0.0, 0.0 } };
  spec.Color = { { 0.0, 1.0, 1.0, 1.0 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  const double iso[2] = { 0.3, 0.7 };
  const hov::RGBA red{ 0.6, 0.0, 0.0, 0.6 }, blue{ 0.0, 0.0, 0.8, 0.8 };
  ConstantShade shade{ { red, blue } };
  for (double slope : { 1.0, -1.0 })
  {
    const hov::Polynomial s = hov::Polynomial::FromCoefficients({ slope > 0 ? 0.0 : 1.0, slope });
    std::vector<hov::IsovalueCrossing> crossings;
    ASSERT_EQ(hov::SurfaceCrossings(s, 1.0, iso, 2, false, crossings), 2);
    const auto r = hov::IntegrateWithSurfaces(tf, s, 1.0, crossings.data(), 2, shade, Settings(hov::EmissionModel::WilliamsMax));
    const hov::RGBA expect = slope > 0 ? hov::Over(red, blue) : hov::Over(blue, red);
    EXPECT_LE(hovtest::MaxAbsDiff(r.Color, expect), 1e-16) << "slope " << slope;
    EXPECT_EQ(r.Surfaces, 2);
  }
  // A quadratic s = 1 - 4 (t - 1/2)^2 on [0, 1] crosses 0.3 twice and 0.7
  // twice: red, blue, blue, red.
  const hov::Polynomial q = hov::Polynomial::FromCoefficients({ 0.0, 4.0, -4.0 });
  std::vector<hov::IsovalueCrossing> crossings;
  ASSERT_EQ(hov::SurfaceCrossings(q, 1.0, iso, 2, false, crossings), 4);
  const auto r = hov::IntegrateWithSurfaces(tf, q, 1.0, crossings.data(), 4, shade, Settings(hov::EmissionModel::WilliamsMax));
  const hov::RGBA expect = hov::Over(red, hov::Over(blue, hov::Over(blue, red)));
  EXPECT_LE(hovtest::MaxAbsDiff(r.Color, expect), 1e-15);
}

TEST(IsosurfaceSegment, ShadingIsLazyBehindOpaqueSurface)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = hov::OpacitySemantics::RawExtinction;
  spec.Opacity = { { 0.0, 0.1 } };
  spec.Color = { { 0.0, 1.0, 1.0, 1.0 } };
  hov::TransferFunction tf;
  ASSERT_TRUE(tf.Build(spec));
  const double iso[2] = { 0.3, 0.7 };
  ConstantShade shade{ { hov::RGBA{ 0.2, 0.3, 0.4, 1.0 }, hov::RGBA{ 1, 1, 1, 1 } } };
  const hov::Polynomial s = hov::Polynomial::FromCoefficients({ 0.0, 1.0 });
  std::vector<hov::IsovalueCrossing> crossings;
  hov::SurfaceCrossings(s, 1.0, iso, 2, false, crossings);
  const auto r = hov::IntegrateWithSurfaces(tf, s, 1.0, crossings.data(), 2, shade, Settings(hov::EmissionModel::WilliamsMax));
  EXPECT_EQ(shade.Calls, 1);
  EXPECT_EQ(r.Color.A, 1.0);
  const double front = std::exp(-0.1 * 0.3);
  EXPECT_NEAR(r.Color.R, (1 - front) + front * 0.2, 1e-15);
}

/// A surface on the face shared by two consecutive segments is owned by the
/// front segment only, also when the two cells' values at the face differ by
/// rounding (here: perturbations up to 1000 ulp of the isovalue).
TEST(IsosurfaceSegment, SharedFaceSurfaceCountsOnce)
{
  const double iso[1] = { 0.5 };
  int worstCount = 1;
  for (int k = -1000; k <= 1000; k += 7)
  {
    for (int side = 0; side < 2; ++side)
    {
      const double delta = k * 0.5 * 2.220446049250313e-16;
      // Front segment [0, 1]: s from 0 to 0.5 (+ delta if side 0); back
      // segment [0, 1]: from 0.5 (+ delta if side 1) to 1.
      const hov::Polynomial a = hov::Polynomial::FromCoefficients({ 0.0, 0.5 + (side == 0 ? delta : 0.0) });
      const hov::Polynomial b = hov::Polynomial::FromCoefficients({ 0.5 + (side == 1 ? delta : 0.0), 0.5 - (side == 1 ? delta : 0.0) });
      std::vector<hov::IsovalueCrossing> ca, cb;
      const int n = hov::SurfaceCrossings(a, 1.0, iso, 1, true, ca) + hov::SurfaceCrossings(b, 1.0, iso, 1, false, cb);
      EXPECT_EQ(n, 1) << "k=" << k << " side " << side;
      worstCount = std::max(worstCount, n);
      if (n == 1 && !ca.empty())
      {
        EXPECT_EQ(ca[0].T, 1.0);
      }
    }
  }
  // Quadratic cells meeting at the face (s = iso on the face, the field
  // turning back in the second cell): still once.
  const hov::Polynomial a = hov::Polynomial::FromCoefficients({ 0.1, 0.6, -0.2 }); // s(1) = 0.5
  const hov::Polynomial b = hov::Polynomial::FromCoefficients({ 0.5, 0.2, -0.1 });
  std::vector<hov::IsovalueCrossing> ca, cb;
  EXPECT_EQ(hov::SurfaceCrossings(a, 1.0, iso, 1, true, ca) + hov::SurfaceCrossings(b, 1.0, iso, 1, false, cb), 1);
  // The ray's first segment owns a surface at its front only with includeFront.
  EXPECT_EQ(hov::SurfaceCrossings(b, 1.0, iso, 1, false, cb), 0);
  EXPECT_EQ(hov::SurfaceCrossings(b, 1.0, iso, 1, true, cb), 1);
  EXPECT_EQ(cb[0].T, 0.0);
  // A segment entirely on the isovalue has no surface (HIAC 5.1).
  EXPECT_EQ(hov::SurfaceCrossings(hov::Polynomial::FromCoefficients({ 0.5 }), 1.0, iso, 1, true, cb), 0);
}

/// A ray cut into segments at random points and at points on the surfaces,
/// each segment with its own (rounded) restriction: every transversal
/// crossing of the whole ray is owned by exactly one segment.
TEST(IsosurfaceSegment, ConsecutiveSegmentsOwnEachCrossingOnce)
{
  std::mt19937_64 rng(12);
  int total = 0, exactSplits = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    const double length = hovtest::LogUniform(rng, 0.5, 4.0);
    const hov::Polynomial s = hovtest::RandomSurfaceField(rng, 1 + trial % 3, length);
    const double iso[2] = { hovtest::Uniform(rng, 0.1, 0.9), hovtest::Uniform(rng, 0.1, 0.9) };
    std::vector<double> cuts{ 0.0, length };
    for (int i = 0; i < 3; ++i)
    {
      cuts.push_back(hovtest::Uniform(rng, 0, length));
    }
    for (int i = 0; i < 2; ++i)
    {
      std::vector<long double> ts;
      hovtest::ScanLevel(s, iso[i], 0.0L, length, 20000, ts);
      for (long double t : ts)
      {
        cuts.push_back(static_cast<double>(t)); // a cut (nearly) on the surface
        ++exactSplits;
      }
    }
    std::sort(cuts.begin(), cuts.end());
    int owned[2] = { 0, 0 };
    for (size_t c = 0; c + 1 < cuts.size(); ++c)
    {
      const double len = cuts[c + 1] - cuts[c];
      if (!(len > 0.0))
      {
        continue;
      }
      const hov::Polynomial piece = hov::ComposeAffine(s, cuts[c], 1.0);
      std::vector<hov::IsovalueCrossing> out;
      hov::SurfaceCrossings(piece, len, iso, 2, c == 0, out);
      for (const auto& x : out)
      {
        ++owned[x.Index];
      }
    }
    for (int i = 0; i < 2; ++i)
    {
      const int expect = TrueCrossings(s, length, iso[i]);
      EXPECT_EQ(owned[i], expect) << Describe(s, length) << " iso " << iso[i];
      total += expect;
    }
  }
  EXPECT_GT(exactSplits, 100);
  hovtest::ReportMeasured("IsosurfaceSegment.CrossingsChecked", total);
}

TEST(IsosurfaceSegment, HitColorAndSweep)
{
  hov::Isosurface iso;
  iso.Color[0] = 0.8;
  iso.Color[1] = 0.4;
  iso.Color[2] = 0.2;
  iso.Opacity = 0.3;
  hov::ShadingMaterial unshaded;
  unshaded.Ambient = 1.0;
  unshaded.Diffuse = 0.0;
  unshaded.Specular = 0.0;
  const double p[3] = { 0, 0, 0 }, v[3] = { 0, 0, 1 };
  // Normal incidence (gradient along the view, either sign): base colour and opacity.
  for (double g : { 2.0, -3.0 })
  {
    const double grad[3] = { 0, 0, g };
    const hov::RGBA c = hov::IsosurfaceHitColor(iso, p, grad, v, nullptr, 0, unshaded);
    EXPECT_EQ(c.A, 0.3);
    EXPECT_NEAR(c.R, 0.3 * 0.8, 1e-16);
    EXPECT_NEAR(c.B, 0.3 * 0.2, 1e-16);
  }
  // Oblique: more opaque; grazing: capped, finite.
  const double oblique[3] = { 1, 0, 1 }, grazing[3] = { 1, 0, 0 };
  EXPECT_NEAR(hov::IsosurfaceHitColor(iso, p, oblique, v, nullptr, 0, unshaded).A,
    1 - std::pow(0.7, std::sqrt(2.0)), 1e-15);
  EXPECT_NEAR(hov::IsosurfaceHitColor(iso, p, grazing, v, nullptr, 0, unshaded).A,
    1 - std::pow(0.7, 100.0), 1e-15);
  // Sweep of odd gradients and lights: finite, premultiplied (RGB <= A).
  std::mt19937_64 rng(31);
  hov::ShadingLight light;
  hov::ShadingMaterial m;
  for (int i = 0; i < 2000; ++i)
  {
    double grad[3];
    for (double& x : grad)
    {
      const int kind = static_cast<int>(rng() % 6);
      x = kind == 0 ? 0.0 : kind == 1 ? NAN : kind == 2 ? INFINITY : kind == 3 ? 1e-310 : hovtest::Uniform(rng, -1, 1) * 1e300;
    }
    iso.Opacity = hovtest::Uniform(rng, -0.5, 1.5);
    const hov::RGBA c = hov::IsosurfaceHitColor(iso, p, grad, v, &light, 1, m);
    ASSERT_TRUE(hovtest::AllFinite(c));
    EXPECT_GE(c.A, 0.0);
    EXPECT_LE(c.A, 1.0);
    EXPECT_LE(c.R, c.A + 1e-16);
  }
}
