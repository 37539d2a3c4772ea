// Tests of hovVolumeShading: the shaded, gradient-opacity-scaled exact
// integral of a linear segment (IntegrateLinearScalarShaded) on a constant-
// gradient slab with known lights (closed forms), on random tetrahedra against
// an independent long double reference (raw-node transfer function, Blinn-
// Phong transcribed in long double, Boost Gauss-Kronrod quadrature,
// hovFeatureTestReference.h), the bitwise identity with the unshaded kernel,
// zero gradients, gamma as a unit-distance rescale, clamp-kink continuity,
// composition and degenerate input.

#include "hovVolumeShading.h"

#include "hovFieldGradient.h"
#include "hovGradientOpacity.h"
#include "hovRayIntegrator.h"
#include "hovTransferFunction.h"

#include "hovFeatureTestReference.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"
#include "hovShadingTestMaterial.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using hovtest::LD;
using hovtest::Str;
using hovtest::Tolerances;
using hovtest::Worst;

namespace
{
hov::IntegrationSettings Exact(hov::EmissionModel m = hov::EmissionModel::WilliamsMax)
{
  hov::IntegrationSettings s;
  s.Emission = m;
  return s;
}

hov::TransferFunction Build(const hov::TransferFunctionSpec& spec)
{
  hov::TransferFunction tf;
  tf.Build(spec);
  return tf;
}

hov::ShadingLight Directional(double x, double y, double z, double intensity = 1.0)
{
  hov::ShadingLight l;
  l.Direction[0] = x;
  l.Direction[1] = y;
  l.Direction[2] = z;
  l.Intensity = intensity;
  return l;
}

double MaxDiff(const hov::RGBA& p, const hovtest::RefRGBA& q, double colorScale = 1.0)
{
  return hovtest::MaxAbsDiff(p, q, colorScale);
}
}

TEST(VolumeShading, ConstantGradientSlabClosedForms)
{
  // A slab 0 <= z <= H with s = z / H (gradient (0, 0, 1/H)), constant colour
  // and opacity; a ray at angle theta to the slab normal crosses it over
  // L = H / cos(theta). n = (0, 0, 1), v = -d.
  hov::TransferFunctionSpec spec;
  spec.Color = { { 0.0, 0.8, 0.5, 0.2 } };
  spec.Opacity = { { 0.0, 0.4 } };
  spec.Semantics = hov::OpacitySemantics::VTKUnstructured;
  spec.UnitDistance = 0.5;
  const hov::TransferFunction tf = Build(spec);
  Worst err;
  const double H = 1.3;
  for (double theta : { 0.0, 0.3, 0.9, 1.3 })
  {
    const double d[3] = { std::sin(theta), 0.0, -std::cos(theta) }; // travels toward -z
    const double v[3] = { -d[0], -d[1], -d[2] };
    const double g[3] = { 0.0, 0.0, 1.0 / H };
    const double L = H / std::cos(theta);
    const LD cosNV = std::cos(static_cast<LD>(theta)); // |n . v|
    for (int lightCase = 0; lightCase < 3; ++lightCase)
    {
      hov::VolumeShadingSettings vs;
      vs.Shade = true;
      vs.Material.Ambient = 0.15;
      vs.Material.Diffuse = 0.6;
      vs.Material.Specular = 0.5;
      vs.Material.SpecularPower = 12.0;
      std::vector<hov::ShadingLight> lights;
      LD M, K;
      if (lightCase == 0)
      {
        // Headlight (VTK's automatic light): l = v, h = v.
        lights.push_back(Directional(d[0], d[1], d[2]));
        M = 0.15L + 0.6L * cosNV;
        K = 0.5L * std::pow(cosNV, 12.0L);
      }
      else
      {
        // A light travelling along (0, 0, -1) (from above, l = +z), intensity 0.8.
        lights.push_back(Directional(0.0, 0.0, -1.0, 0.8));
        // n . l = 1; h = (l + v)/|l + v|, v = (-sin, 0, cos): n . h = cos(theta/2).
        M = 0.15L + 0.6L * 0.8L;
        K = 0.5L * 0.8L * std::pow(std::cos(static_cast<LD>(theta) / 2), 12.0L);
        if (lightCase == 2)
        {
          vs.Ambient = hov::AmbientTerm::LightAmbient; // VTK with a non-headlight
          vs.AmbientLight[0] = vs.AmbientLight[1] = vs.AmbientLight[2] = 0.25;
          M -= 0.15L;
          K += 0.15L * 0.25L;
        }
      }
      vs.Lights = lights.data();
      vs.LightCount = static_cast<int>(lights.size());
      const hov::ShadingTransform shade = hov::ComputeShadingTransform(vs, g, g, v);
      for (double gamma : { 1.0, 0.35, 2.0 })
      {
        const hov::RGBA got = hov::IntegrateLinearScalarShaded(tf, 0.0, 1.0, L, shade, gamma, Exact());
        const LD tau = gamma * 0.4L / 0.5L;
        const LD alpha = -std::expm1(-tau * L);
        const LD base[3] = { 0.8L, 0.5L, 0.2L };
        hovtest::RefRGBA ref;
        LD* out[3] = { &ref.R, &ref.G, &ref.B };
        for (int c = 0; c < 3; ++c)
        {
          *out[c] = std::min(1.0L, M * base[c] + K) * alpha;
        }
        ref.A = alpha;
        err.Add(MaxDiff(got, ref), "theta " + Str(theta) + " light " + std::to_string(lightCase) +
            " gamma " + Str(gamma));
      }
    }
  }
  hovtest::ReportMeasured("VolumeShading.SlabClosedForm", err);
  EXPECT_LE(err.Value, Tolerances.ShadedClosedFormAbs) << err.Where;
}

TEST(VolumeShading, LinearTetrahedraAgainstLongDoubleReference)
{
  std::mt19937_64 rng(1906);
  Worst err;
  for (int trial = 0; trial < 50; ++trial)
  {
    // Random tetrahedron, node scalars, ray; the segment [0, L] inside it.
    double p[12], s[4];
    for (double& x : p)
    {
      x = hovtest::Uniform(rng, 0, 1);
    }
    for (double& x : s)
    {
      x = hovtest::Uniform(rng, -0.1, 1.1);
    }
    double g[3];
    if (!hov::TetraGradient(p, s, g))
    {
      continue;
    }
    // Independent gradient in long double (solve E^T g = ds by Cramer).
    LD e[3][3], ds[3];
    for (int i = 0; i < 3; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        e[i][k] = static_cast<LD>(p[3 * (i + 1) + k]) - p[k];
      }
      ds[i] = static_cast<LD>(s[i + 1]) - s[0];
    }
    auto det3 = [](const LD m[3][3]) {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
        m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const LD det = det3(e);
    LD gRef[3];
    for (int k = 0; k < 3; ++k)
    {
      LD m[3][3];
      for (int i = 0; i < 3; ++i)
      {
        for (int j = 0; j < 3; ++j)
        {
          m[i][j] = j == k ? ds[i] : e[i][j];
        }
      }
      gRef[k] = det3(m) / det;
    }
    const LD gl = std::sqrt(gRef[0] * gRef[0] + gRef[1] * gRef[1] + gRef[2] * gRef[2]);
    std::normal_distribution<double> nd;
    double d[3] = { nd(rng), nd(rng), nd(rng) };
    const double dl = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& x : d)
    {
      x /= dl;
    }
    const double v[3] = { -d[0], -d[1], -d[2] };
    // The field along the segment: linear from sF to sB over length L.
    const double sF = hovtest::Uniform(rng, -0.1, 1.1), L = hovtest::LogUniform(rng, 0.05, 4.0);
    const double sB = sF + L * (g[0] * d[0] + g[1] * d[1] + g[2] * d[2]);
    // Transfer function, lights, material.
    hov::TransferFunctionSpec spec;
    const int nc = 2 + trial % 4, no = 2 + trial % 3;
    for (int i = 0; i < nc; ++i)
    {
      spec.Color.push_back({ -0.2 + 1.4 * i / (nc - 1), hovtest::Uniform(rng, 0, 1),
        hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1) });
    }
    for (int i = 0; i < no; ++i)
    {
      spec.Opacity.push_back({ hovtest::Uniform(rng, -0.2, 1.2), hovtest::Uniform(rng, 0, 1) });
    }
    std::sort(spec.Opacity.begin(), spec.Opacity.end(),
      [](const hov::OpacityNode& a, const hov::OpacityNode& b) { return a.X < b.X; });
    spec.Semantics = trial % 2 ? hov::OpacitySemantics::VTKUnstructured : hov::OpacitySemantics::RawExtinction;
    spec.UnitDistance = hovtest::Uniform(rng, 0.2, 2.0);
    spec.EmissionScale = 0.7;
    const hov::TransferFunction tf = Build(spec);
    const hovtest::RefRawTransfer raw(spec);
    std::vector<hov::ShadingLight> lights;
    for (int i = 0; i < 1 + trial % 3; ++i)
    {
      lights.push_back(Directional(nd(rng), nd(rng), nd(rng), hovtest::Uniform(rng, 0.3, 1.2)));
      for (double& c : lights.back().Color)
      {
        c = hovtest::Uniform(rng, 0.5, 1.0);
      }
    }
    hov::VolumeShadingSettings vs;
    vs.Shade = true;
    vs.Material.Ambient = hovtest::Uniform(rng, 0, 0.5);
    vs.Material.Diffuse = hovtest::Uniform(rng, 0.3, 1.0);
    vs.Material.Specular = hovtest::Uniform(rng, 0, 0.8);
    vs.Material.SpecularPower = hovtest::Uniform(rng, 1, 60);
    vs.Material.TwoSidedLighting = trial % 5 != 0;
    vs.Lights = lights.data();
    vs.LightCount = static_cast<int>(lights.size());
    const double gamma = trial % 3 == 0 ? 1.0 : hovtest::Uniform(rng, 0.0, 2.0);
    const double point[3] = { 0.0, 0.0, 0.0 };
    const hov::ShadingTransform shade = hov::ComputeShadingTransform(vs, g, point, v);
    // Reference M, K from the long double gradient.
    const LD n[3] = { gRef[0] / gl, gRef[1] / gl, gRef[2] / gl };
    const LD vv[3] = { v[0], v[1], v[2] };
    const LD zero[3] = { 0, 0, 0 };
    LD M[3], K[3];
    hovtest::ReferenceBlinnPhong(n, vv, lights, vs.Material, false, zero, M, K);
    for (hov::EmissionModel em : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      const bool wvg = em == hov::EmissionModel::WilhelmsVanGelder;
      const hov::RGBA got = hov::IntegrateLinearScalarShaded(tf, sF, sB, L, shade, gamma, Exact(em));
      hovtest::RefMedium m;
      m.Length = L;
      auto sOf = [&](LD t) { return sF + (static_cast<LD>(sB) - sF) * t / L; };
      m.Tau = [&](LD t) { return gamma * raw.Tau(sOf(t)); };
      m.Emission = [&](LD t, int ch) {
        LD c[3];
        raw.Color(sOf(t), c);
        const LD sh = std::min(std::max(M[ch] * c[ch] + K[ch], 0.0L), 1.0L);
        return wvg ? spec.EmissionScale / spec.UnitDistance * sh : sh * gamma * raw.Tau(sOf(t));
      };
      for (const auto* nodes : { &raw.R.X, &raw.A.X })
      {
        for (LD x : *nodes)
        {
          if (sB != sF)
          {
            m.Breaks.push_back((x - sF) / (static_cast<LD>(sB) - sF) * L);
          }
        }
      }
      for (int ch = 0; ch < 3; ++ch)
      {
        auto u = [&](LD t) {
          LD c[3];
          raw.Color(sOf(t), c);
          return M[ch] * c[ch] + K[ch];
        };
        for (LD t : hovtest::LevelCrossings(u, 1.0L, 0.0L, L, 400))
        {
          m.Breaks.push_back(t);
        }
      }
      const hovtest::RefRGBA ref = hovtest::ReferenceMedium(m);
      const double scale = wvg ? std::max(1.0, L * spec.EmissionScale / spec.UnitDistance) : 1.0;
      err.Add(MaxDiff(got, ref, scale), "trial " + std::to_string(trial) + (wvg ? " WVG" : " WM") +
          " sF=" + Str(sF) + " sB=" + Str(sB) + " L=" + Str(L) + " gamma=" + Str(gamma));
    }
  }
  hovtest::ReportMeasured("VolumeShading.TetraVsReference", err);
  EXPECT_LE(err.Value, Tolerances.ShadedReferenceAbs) << err.Where;
}

TEST(VolumeShading, IdentityZeroGradientAndGammaRescale)
{
  std::mt19937_64 rng(1907);
  hov::TransferFunctionSpec spec;
  spec.Color = { { 0.0, 0.1, 0.9, 0.3 }, { 0.5, 0.9, 0.2, 0.6 }, { 1.0, 0.4, 0.4, 1.0 } };
  spec.Opacity = { { 0.0, 0.1 }, { 0.3, 0.9 }, { 0.7, 0.2 }, { 1.0, 0.6 } };
  spec.Semantics = hov::OpacitySemantics::VTKUnstructured;
  spec.UnitDistance = 0.8;
  const hov::TransferFunction tf = Build(spec);
  Worst rescale;
  for (int trial = 0; trial < 200; ++trial)
  {
    const double sF = hovtest::Uniform(rng, -0.2, 1.2), sB = hovtest::Uniform(rng, -0.2, 1.2);
    const double L = hovtest::LogUniform(rng, 1e-3, 10.0);
    // Shade off and gamma = 1: bitwise the unshaded kernel.
    for (hov::EmissionModel em : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      const hov::RGBA a = hov::IntegrateLinearScalarShaded(tf, sF, sB, L, hov::ShadingTransform(), 1.0, Exact(em));
      const hov::RGBA b = hov::IntegrateLinearScalar(tf, sF, sB, L, Exact(em));
      EXPECT_TRUE(a.R == b.R && a.G == b.G && a.B == b.B && a.A == b.A) << trial;
    }
    // gamma scales a/u: the same as unit distance u / gamma (Williams-Max).
    const double gamma = hovtest::LogUniform(rng, 1e-3, 1e3);
    hov::TransferFunctionSpec scaled = spec;
    scaled.UnitDistance = spec.UnitDistance / gamma;
    const hov::TransferFunction tf2 = Build(scaled);
    hov::ShadingTransform almostIdentity; // forces the shaded path
    almostIdentity.Clamp = true;
    const hov::RGBA a = hov::IntegrateLinearScalarShaded(tf, sF, sB, L, almostIdentity, gamma, Exact());
    const hov::RGBA b = hov::IntegrateLinearScalar(tf2, sF, sB, L, Exact());
    rescale.Add(hovtest::MaxAbsDiff(a, b), "trial " + std::to_string(trial) + " gamma=" + Str(gamma));
  }
  hovtest::ReportMeasured("VolumeShading.GammaAsUnitDistance", rescale);
  EXPECT_LE(rescale.Value, Tolerances.ShadedRescaleAbs) << rescale.Where;

  // Zero gradient (a constant field on a tetrahedron gives exactly 0): ambient only.
  const double p[12] = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const double s[4] = { 0.3, 0.3, 0.3, 0.3 };
  double g[3];
  ASSERT_TRUE(hov::TetraGradient(p, s, g));
  EXPECT_EQ(g[0], 0.0);
  EXPECT_EQ(g[1], 0.0);
  EXPECT_EQ(g[2], 0.0);
  hov::ShadingLight light = Directional(0, 0, -1);
  hov::VolumeShadingSettings vs;
  vs.Shade = true;
  vs.Lights = &light;
  vs.LightCount = 1;
  const double v[3] = { 0, 0, 1 };
  hov::ShadingTransform t = hov::ComputeShadingTransform(vs, g, g, v);
  EXPECT_FALSE(t.Lit);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(t.Scale[c], vs.Material.Ambient);
    EXPECT_EQ(t.Offset[c], 0.0);
  }
  vs.Ambient = hov::AmbientTerm::LightAmbient;
  vs.AmbientLight[1] = 0.5;
  t = hov::ComputeShadingTransform(vs, g, g, v);
  EXPECT_EQ(t.Scale[1], 0.0);
  EXPECT_EQ(t.Offset[1], vs.Material.Ambient * 0.5);
  // Tiny, huge and non-finite gradients: a unit normal or none, never NaN.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double mag : { 1e-310, 1e-200, 1e200, 1e307 }) // 2 x 1e308 would overflow the input itself
  {
    const double gg[3] = { mag, -2 * mag, 0.5 * mag };
    double n[3];
    ASSERT_TRUE(hov::VolumeNormal(gg, 0.0, n)) << mag;
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 4e-16) << mag;
  }
  // (The gradients outlive the loop: temporaries here were freed before use;
  // the sanitizer run caught it.)
  const double badGradients[2][3] = { { nan, 0, 0 }, { 1e308, 1e308, 1e308 } };
  for (const double* gg : badGradients)
  {
    double n[3];
    hov::VolumeNormal(gg, 0.0, n);
    EXPECT_TRUE(std::isfinite(n[0] + n[1] + n[2]));
  }
}

TEST(VolumeShading, ClampKinkContinuityCompositionAndDegenerateInput)
{
  std::mt19937_64 rng(1908);
  hov::TransferFunctionSpec spec;
  spec.Color = { { 0.0, 0.0, 0.3, 1.0 }, { 1.0, 1.0, 0.6, 0.0 } };
  spec.Opacity = { { 0.0, 0.3 }, { 0.6, 0.8 }, { 1.0, 0.5 } };
  spec.Semantics = hov::OpacitySemantics::GPUCompatible;
  spec.UnitDistance = 0.5;
  const hov::TransferFunction tf = Build(spec);
  Worst kink, split;
  for (int trial = 0; trial < 200; ++trial)
  {
    const double sF = hovtest::Uniform(rng, 0, 1), sB = hovtest::Uniform(rng, 0, 1), L = 1.5;
    hov::ShadingTransform shade;
    shade.Clamp = true;
    for (int c = 0; c < 3; ++c)
    {
      shade.Scale[c] = hovtest::Uniform(rng, 0.5, 2.0);
      shade.Offset[c] = 0.0;
    }
    // Red channel's kink exactly at the front end (u = 1 there), then +-1e-12.
    const double cFront = sF; // red ramps 0 -> 1 over [0, 1]
    const double offset = 1.0 - shade.Scale[0] * cFront;
    hov::ShadingTransform lo = shade, hi = shade;
    lo.Offset[0] = offset - 1e-12;
    hi.Offset[0] = offset + 1e-12;
    const double gamma = hovtest::Uniform(rng, 0.5, 1.5);
    const hov::RGBA a = hov::IntegrateLinearScalarShaded(tf, sF, sB, L, lo, gamma, Exact());
    const hov::RGBA b = hov::IntegrateLinearScalarShaded(tf, sF, sB, L, hi, gamma, Exact());
    kink.Add(hovtest::MaxAbsDiff(a, b), "trial " + std::to_string(trial));
    // Composition: [0, L] = [0, xL] over [xL, L].
    const double x = hovtest::Uniform(rng, 0.05, 0.95);
    const double sx = sF + (sB - sF) * x;
    const hov::RGBA whole = hov::IntegrateLinearScalarShaded(tf, sF, sB, L, shade, gamma, Exact());
    const hov::RGBA front = hov::IntegrateLinearScalarShaded(tf, sF, sx, L * x, shade, gamma, Exact());
    const hov::RGBA back = hov::IntegrateLinearScalarShaded(tf, sx, sB, L * (1 - x), shade, gamma, Exact());
    split.Add(hovtest::MaxAbsDiff(whole, hov::Over(front, back)), "trial " + std::to_string(trial));
  }
  hovtest::ReportMeasured("VolumeShading.ClampKinkContinuity", kink);
  hovtest::ReportMeasured("VolumeShading.Composition", split);
  EXPECT_LE(kink.Value, Tolerances.ShadedContinuityAbs) << kink.Where;
  EXPECT_LE(split.Value, Tolerances.CompositionAbs) << split.Where;

  // Degenerate input: transparent or finite, never NaN.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  hov::ShadingTransform shade;
  shade.Clamp = true;
  shade.Scale[0] = 2.0;
  for (double L : { 0.0, -1.0, nan, inf })
  {
    const hov::RGBA c = hov::IntegrateLinearScalarShaded(tf, 0.2, 0.8, L, shade, 0.5, Exact());
    EXPECT_EQ(c.A, 0.0) << L;
  }
  for (double gamma : { nan, -1.0, 0.0, inf, 1e300 })
  {
    const hov::RGBA c = hov::IntegrateLinearScalarShaded(tf, 0.2, 0.8, 1.0, shade, gamma, Exact());
    EXPECT_TRUE(hovtest::AllFinite(c)) << gamma;
    EXPECT_GE(c.A, 0.0);
    EXPECT_LE(c.A, 1.0);
  }
  EXPECT_EQ(hov::IntegrateLinearScalarShaded(tf, nan, 0.8, 1.0, shade, 0.5, Exact()).A, 0.0);
  // An opaque interval (GPU semantics, a = 1) times gamma = 0 is transparent.
  hov::TransferFunctionSpec opaque;
  opaque.Color = { { 0.0, 1.0, 1.0, 1.0 } };
  opaque.Opacity = { { 0.0, 1.0 }, { 1.0, 1.0 } };
  const hov::TransferFunction tfo = Build(opaque);
  EXPECT_EQ(hov::IntegrateLinearScalarShaded(tfo, 0.2, 0.8, 1.0, shade, 0.0, Exact()).A, 0.0);
  const hov::RGBA full = hov::IntegrateLinearScalarShaded(tfo, 0.2, 0.8, 1.0, shade, 0.5, Exact());
  EXPECT_EQ(full.A, 1.0);
  EXPECT_EQ(full.R, 1.0); // 2 x 1 clamped to 1
}

// ComputeShadingTransform lights once (hov::PhongLightSums) and composes the
// sums twice: Scale and Offset must be, bit for bit, the two ShadePhong calls
// the file doc defines them by (a unit colour with ka' + kd D, a zero colour
// with ks S), for every kind of light, both ambient terms and edge-on normals.
TEST(VolumeShading, TransformIsTwoPhongCallsBitForBit)
{
  std::mt19937_64 rng(2026);
  std::normal_distribution<double> nd;
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    std::vector<hov::ShadingLight> lights(1 + trial % 3);
    for (hov::ShadingLight& l : lights)
    {
      for (int i = 0; i < 3; ++i)
      {
        l.Direction[i] = nd(rng);
        l.Position[i] = hovtest::Uniform(rng, -3, 3);
        l.Color[i] = hovtest::Uniform(rng, 0, 1);
      }
      l.Intensity = hovtest::Uniform(rng, 0.2, 2);
      l.Positional = rng() % 2;
      l.Attenuation[1] = hovtest::Uniform(rng, 0, 0.5);
      l.ConeAngle = rng() % 2 ? hovtest::Uniform(rng, 10, 89) : 180.0;
    }
    hov::VolumeShadingSettings vs;
    vs.Shade = true;
    hovtest::RandomShadingMaterial(rng, trial, vs);
    vs.Lights = lights.data();
    vs.LightCount = static_cast<int>(lights.size());
    const double g[3] = { nd(rng), nd(rng), trial % 7 == 0 ? 0.0 : nd(rng) };
    const double point[3] = { nd(rng), nd(rng), nd(rng) };
    double v[3] = { nd(rng), nd(rng), nd(rng) };
    const double vl = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (double& c : v)
    {
      c /= vl;
    }
    const hov::ShadingTransform t = hov::ComputeShadingTransform(vs, g, point, v);
    double normal[3];
    ASSERT_EQ(t.Lit, hov::VolumeNormal(g, vs.GradientFloor, normal));
    hov::ShadingMaterial diffuse = vs.Material, specular = vs.Material;
    diffuse.Ambient = vs.Ambient == hov::AmbientTerm::MaterialColor ? vs.Material.Ambient : 0.0;
    diffuse.Specular = 0.0;
    diffuse.ClampColor = false;
    specular.Ambient = 0.0;
    specular.Diffuse = 0.0;
    specular.ClampColor = false;
    const double one[3] = { 1.0, 1.0, 1.0 }, zero[3] = { 0.0, 0.0, 0.0 };
    double scale[3], offset[3];
    hov::ShadePhong(one, point, normal, v, lights.data(), vs.LightCount, diffuse, scale);
    hov::ShadePhong(zero, point, normal, v, lights.data(), vs.LightCount, specular, offset);
    for (int c = 0; c < 3; ++c)
    {
      if (vs.Ambient == hov::AmbientTerm::LightAmbient)
      {
        offset[c] += vs.Material.Ambient * vs.AmbientLight[c];
      }
      ASSERT_EQ(t.Scale[c], scale[c]) << "trial " << trial << " channel " << c;
      ASSERT_EQ(t.Offset[c], offset[c]) << "trial " << trial << " channel " << c;
    }
    checked += t.Offset[0] > 0.0; // a highlight reached the transform
  }
  EXPECT_GT(checked, 300); // the specular part was exercised
}
