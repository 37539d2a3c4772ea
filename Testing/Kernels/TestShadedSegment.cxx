// Tests of hovShadedSegment: the adaptive spectral quadrature of a shaded,
// gradient-opacity-modulated segment whose gradient varies along the ray
// (quadratic fields: s(t) quadratic, grad s(t) linear in t, as in a quadratic
// tetrahedron) against an independent long double reference (raw-node
// transfer and gradient-opacity functions, Blinn-Phong transcribed in long
// double per point, breakpoints located by bisection, Boost Gauss-Kronrod,
// hovFeatureTestReference.h): the error is below the requested tolerance AND
// below the reported ErrorEstimate (the estimate is an upper bound in
// practice, measured), for tolerances 1e-6, 1e-9, 1e-12; the closed-form path
// for constant gradients; degenerate input.

#include "hovShadedSegment.h"

#include "hovGradientOpacity.h"
#include "hovTransferFunction.h"
#include "hovVolumeShading.h"

#include "hovFeatureTestReference.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"

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
hov::ShadingLight Directional(double x, double y, double z, double intensity = 1.0)
{
  hov::ShadingLight l;
  l.Direction[0] = x;
  l.Direction[1] = y;
  l.Direction[2] = z;
  l.Intensity = intensity;
  return l;
}

/// A quadratic field s(x) = a + b.x + x^T Q x / 2 along x(t) = o + t d.
struct QuadraticField
{
  double A = 0.0, B[3] = { 0, 0, 0 }, Q[3][3] = {};
  double O[3] = { 0, 0, 0 }, D[3] = { 0, 0, 1 };

  LD S(LD t) const
  {
    LD x[3], v = A;
    for (int i = 0; i < 3; ++i)
    {
      x[i] = O[i] + t * D[i];
      v += B[i] * x[i];
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        v += 0.5L * x[i] * Q[i][j] * x[j];
      }
    }
    return v;
  }
  void G(LD t, LD g[3]) const
  {
    for (int i = 0; i < 3; ++i)
    {
      g[i] = B[i];
      for (int j = 0; j < 3; ++j)
      {
        g[i] += Q[i][j] * (O[j] + t * D[j]);
      }
    }
  }
  /// The same as polynomials in t (what a cell's restriction would give).
  void Polynomials(hov::Polynomial& s, hov::Polynomial g[3]) const
  {
    double g0[3], qd[3], dqd = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      g0[i] = B[i];
      qd[i] = 0.0;
      for (int j = 0; j < 3; ++j)
      {
        g0[i] += Q[i][j] * O[j];
        qd[i] += Q[i][j] * D[j];
      }
      dqd += D[i] * qd[i];
    }
    const double s0 = static_cast<double>(S(0.0L));
    s = hov::Polynomial::FromCoefficients({ s0, g0[0] * D[0] + g0[1] * D[1] + g0[2] * D[2], 0.5 * dqd });
    for (int i = 0; i < 3; ++i)
    {
      g[i] = hov::Polynomial::FromCoefficients({ g0[i], qd[i] });
    }
  }
};

struct Case
{
  QuadraticField F;
  hov::TransferFunctionSpec Spec;
  hov::GradientOpacitySpec GO;
  std::vector<hov::ShadingLight> Lights;
  hov::ShadingMaterial Material;
  double Length = 1.0;
};

Case RandomCase(std::mt19937_64& rng, int trial)
{
  Case c;
  std::normal_distribution<double> nd;
  c.F.A = hovtest::Uniform(rng, 0.2, 0.8);
  for (int i = 0; i < 3; ++i)
  {
    c.F.B[i] = hovtest::Uniform(rng, -1, 1);
    c.F.O[i] = hovtest::Uniform(rng, -0.3, 0.3);
    for (int j = 0; j <= i; ++j)
    {
      c.F.Q[i][j] = c.F.Q[j][i] = hovtest::Uniform(rng, -1.5, 1.5);
    }
  }
  double dl = 0.0;
  for (double& x : c.F.D)
  {
    x = nd(rng);
    dl += x * x;
  }
  for (double& x : c.F.D)
  {
    x /= std::sqrt(dl);
  }
  c.Length = hovtest::LogUniform(rng, 0.1, 1.5);
  const int nc = 2 + trial % 3, no = 2 + trial % 4;
  for (int i = 0; i < nc; ++i)
  {
    c.Spec.Color.push_back({ -0.5 + 2.0 * i / (nc - 1), hovtest::Uniform(rng, 0, 1),
      hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1) });
  }
  for (int i = 0; i < no; ++i)
  {
    c.Spec.Opacity.push_back({ hovtest::Uniform(rng, -0.5, 1.5), hovtest::Uniform(rng, 0.05, 0.9) });
  }
  std::sort(c.Spec.Opacity.begin(), c.Spec.Opacity.end(),
    [](const hov::OpacityNode& x, const hov::OpacityNode& y) { return x.X < y.X; });
  c.Spec.Semantics = trial % 2 ? hov::OpacitySemantics::VTKUnstructured : hov::OpacitySemantics::RawExtinction;
  c.Spec.UnitDistance = hovtest::Uniform(rng, 0.3, 1.5);
  c.Spec.EmissionScale = 0.7;
  if (trial % 3 != 0)
  {
    c.GO.Nodes = { { 0.0, hovtest::Uniform(rng, 0.1, 0.5) }, { hovtest::Uniform(rng, 0.3, 1.5), 1.0 },
      { 2.5, hovtest::Uniform(rng, 0.5, 1.5) } };
  }
  for (int i = 0; i < 1 + trial % 2; ++i)
  {
    c.Lights.push_back(Directional(nd(rng), nd(rng), nd(rng), hovtest::Uniform(rng, 0.5, 1.2)));
  }
  c.Material.Ambient = hovtest::Uniform(rng, 0.05, 0.4);
  c.Material.Diffuse = hovtest::Uniform(rng, 0.4, 1.0);
  c.Material.Specular = hovtest::Uniform(rng, 0.0, 0.6);
  c.Material.SpecularPower = hovtest::Uniform(rng, 2, 30);
  c.Material.TwoSidedLighting = trial % 4 != 3;
  return c;
}

/// The independent reference of a case (file doc).
hovtest::RefRGBA Reference(const Case& c, hov::EmissionModel em, double* selfError = nullptr)
{
  const hovtest::RefRawTransfer raw(c.Spec);
  hovtest::RefPwl go;
  for (const auto& n : c.GO.Nodes)
  {
    go.X.push_back(n.X);
    go.V.push_back(n.Opacity);
  }
  const bool wvg = em == hov::EmissionModel::WilhelmsVanGelder;
  const LD ef = static_cast<LD>(c.Spec.EmissionScale) / c.Spec.UnitDistance;
  auto gMag = [&](LD t) {
    LD g[3];
    c.F.G(t, g);
    return std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  };
  auto gammaOf = [&](LD t) { return go.X.empty() ? 1.0L : std::max(0.0L, go(gMag(t))); };
  const LD v[3] = { -c.F.D[0], -c.F.D[1], -c.F.D[2] };
  auto unclamped = [&](LD t, int ch) {
    LD g[3];
    c.F.G(t, g);
    const LD gl = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    const LD n[3] = { g[0] / gl, g[1] / gl, g[2] / gl };
    const LD zero[3] = { 0, 0, 0 };
    LD M[3], K[3], col[3];
    hovtest::ReferenceBlinnPhong(n, v, c.Lights, c.Material, false, zero, M, K);
    raw.Color(c.F.S(t), col);
    return M[ch] * col[ch] + K[ch];
  };
  hovtest::RefMedium m;
  m.Length = c.Length;
  m.Tau = [&](LD t) { return gammaOf(t) * raw.Tau(c.F.S(t)); };
  m.Emission = [&](LD t, int ch) {
    const LD sh = std::min(std::max(unclamped(t, ch), 0.0L), 1.0L);
    return wvg ? ef * sh : sh * gammaOf(t) * raw.Tau(c.F.S(t));
  };
  auto s = [&](LD t) { return c.F.S(t); };
  for (const auto* nodes : { &raw.R.X, &raw.A.X })
  {
    for (LD x : *nodes)
    {
      for (LD t : hovtest::LevelCrossings(s, x, 0.0L, c.Length, 400))
      {
        m.Breaks.push_back(t);
      }
    }
  }
  for (LD x : go.X)
  {
    for (LD t : hovtest::LevelCrossings(gMag, x, 0.0L, c.Length, 400))
    {
      m.Breaks.push_back(t);
    }
  }
  // Kinks of Blinn-Phong along the ray: n.l = 0 and n.h = 0 (|.| two-sided,
  // max(0, .) one-sided), i.e. where g(t).l and g(t).h change sign.
  for (const auto& light : c.Lights)
  {
    LD l[3] = { -light.Direction[0], -light.Direction[1], -light.Direction[2] };
    const LD ll = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    LD h[3];
    for (int i = 0; i < 3; ++i)
    {
      l[i] /= ll;
      h[i] = l[i] + v[i];
    }
    for (const LD* dir : { static_cast<const LD*>(l), static_cast<const LD*>(h) })
    {
      auto dot = [&](LD t) {
        LD g[3];
        c.F.G(t, g);
        return g[0] * dir[0] + g[1] * dir[1] + g[2] * dir[2];
      };
      for (LD t : hovtest::LevelCrossings(dot, 0.0L, 0.0L, c.Length, 400))
      {
        m.Breaks.push_back(t);
      }
    }
  }
  for (int ch = 0; ch < 3; ++ch)
  {
    for (LD level : { 0.0L, 1.0L })
    {
      for (LD t : hovtest::LevelCrossings([&](LD t) { return unclamped(t, ch); }, level, 0.0L, c.Length, 400))
      {
        m.Breaks.push_back(t);
      }
    }
  }
  const hovtest::RefRGBA a = hovtest::ReferenceMediumComposite(m, 8);
  const hovtest::RefRGBA b = hovtest::ReferenceMediumComposite(m, 16);
  if (selfError)
  {
    *selfError = static_cast<double>(std::max({ std::fabs(a.R - b.R), std::fabs(a.G - b.G),
      std::fabs(a.B - b.B), std::fabs(a.A - b.A) }));
  }
  return b;
}
}

TEST(ShadedSegment, QuadraticFieldsAgainstLongDoubleReference)
{
  std::mt19937_64 rng(1921);
  Worst err[3], ratio, refSelf;
  int panels[3] = { 0, 0, 0 };
  const double tolerances[3] = { 1e-6, 1e-9, 1e-12 };
  for (int trial = 0; trial < 40; ++trial)
  {
    const Case c = RandomCase(rng, trial);
    hov::TransferFunction tf;
    tf.Build(c.Spec);
    hov::GradientOpacityFunction go;
    go.Build(c.GO);
    hov::VolumeShadingSettings vs;
    vs.Shade = true;
    vs.Material = c.Material;
    vs.Lights = c.Lights.data();
    vs.LightCount = static_cast<int>(c.Lights.size());
    hov::Polynomial s, g[3];
    c.F.Polynomials(s, g);
    hov::SegmentRay ray;
    for (int i = 0; i < 3; ++i)
    {
      ray.Origin[i] = c.F.O[i];
      ray.Direction[i] = c.F.D[i];
    }
    for (hov::EmissionModel em : { hov::EmissionModel::WilliamsMax, hov::EmissionModel::WilhelmsVanGelder })
    {
      const bool wvg = em == hov::EmissionModel::WilhelmsVanGelder;
      double selfError = 0.0;
      const hovtest::RefRGBA ref = Reference(c, em, &selfError);
      refSelf.Add(selfError, "trial " + std::to_string(trial));
      for (int k = 0; k < 3; ++k)
      {
        hov::ShadedSegmentSettings settings;
        settings.Emission = em;
        settings.Tolerance = tolerances[k];
        const hov::ShadedSegmentResult r =
          hov::IntegrateShadedPolynomial(tf, s, g, c.Length, vs, c.GO.Nodes.empty() ? nullptr : &go, ray, settings);
        EXPECT_FALSE(r.ExactPath);
        EXPECT_TRUE(r.Converged) << "trial " << trial << " tol " << tolerances[k];
        const double e = hovtest::MaxAbsDiff(r.Color, ref, 1.0);
        const std::string where = "trial " + std::to_string(trial) + (wvg ? " WVG" : " WM") +
          " tol " + Str(tolerances[k]) + " estimate " + Str(r.ErrorEstimate);
        err[k].Add(e, where);
        EXPECT_LE(e, std::max(tolerances[k], 1e-13)) << where;
        // The estimate bounds the error (up to the reference's own rounding).
        ratio.Add(e / (r.ErrorEstimate + 1e-14), where);
        EXPECT_LE(r.ErrorEstimate, tolerances[k] * 1.0000001) << where;
        panels[k] += r.Panels;
      }
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    hovtest::ReportMeasured("ShadedSegment.QuadraticVsReference tol " + Str(tolerances[k]), err[k]);
    std::cout << "[measured] ShadedSegment panels at tol " << tolerances[k] << ": " << panels[k] << "\n";
    EXPECT_LE(err[k].Value, std::max(tolerances[k], 1e-13)) << err[k].Where;
  }
  hovtest::ReportMeasured("ShadedSegment.ReferenceSelfCheck (8 vs 16 panels)", refSelf);
  EXPECT_LE(refSelf.Value, 1e-15) << refSelf.Where;
  hovtest::ReportMeasured("ShadedSegment.ErrorOverEstimate", ratio);
  EXPECT_LE(ratio.Value, 1.0) << ratio.Where;
  // Tighter tolerance: more panels.
  EXPECT_LE(panels[0], panels[1]);
  EXPECT_LE(panels[1], panels[2]);
}

TEST(ShadedSegment, ConstantGradientTakesTheClosedForm)
{
  std::mt19937_64 rng(1922);
  for (int trial = 0; trial < 50; ++trial)
  {
    Case c = RandomCase(rng, trial);
    for (auto& row : c.F.Q)
    {
      for (double& q : row)
      {
        q = 0.0;
      }
    }
    hov::TransferFunction tf;
    tf.Build(c.Spec);
    hov::GradientOpacityFunction go;
    go.Build(c.GO);
    hov::VolumeShadingSettings vs;
    vs.Shade = true;
    vs.Material = c.Material;
    vs.Lights = c.Lights.data();
    vs.LightCount = static_cast<int>(c.Lights.size());
    hov::Polynomial s, g[3];
    c.F.Polynomials(s, g);
    hov::SegmentRay ray;
    for (int i = 0; i < 3; ++i)
    {
      ray.Direction[i] = c.F.D[i];
    }
    hov::ShadedSegmentSettings settings;
    const hov::ShadedSegmentResult r = hov::IntegrateShadedPolynomial(tf, s, g, c.Length, vs, &go, ray, settings);
    ASSERT_TRUE(r.ExactPath);
    const double gc[3] = { g[0].C[0], g[1].C[0], g[2].C[0] };
    const double v[3] = { -c.F.D[0], -c.F.D[1], -c.F.D[2] };
    const hov::RGBA e = hov::IntegrateLinearScalarShaded(tf, s.C[0], s.C[0] + s.C[1] * c.Length, c.Length,
      hov::ComputeShadingTransform(vs, gc, ray.Origin, v), go.EvaluateGradient(gc), hov::IntegrationSettings());
    EXPECT_EQ(r.Color.R, e.R);
    EXPECT_EQ(r.Color.A, e.A);
    // And the closed form agrees with the independent reference.
    const hovtest::RefRGBA ref = Reference(c, hov::EmissionModel::WilliamsMax);
    EXPECT_LE(hovtest::MaxAbsDiff(r.Color, ref, 1.0), Tolerances.ShadedReferenceAbs) << trial;
  }
}

TEST(ShadedSegment, DegenerateInput)
{
  hov::TransferFunctionSpec spec;
  spec.Color = { { 0.0, 1.0, 0.5, 0.2 } };
  spec.Opacity = { { 0.0, 0.5 } };
  hov::TransferFunction tf;
  tf.Build(spec);
  hov::VolumeShadingSettings vs;
  const hov::ShadingLight light = Directional(0, 0, -1);
  vs.Shade = true;
  vs.Lights = &light;
  vs.LightCount = 1;
  hov::Polynomial s = hov::Polynomial::FromCoefficients({ 0.5, 0.1, 0.3 });
  hov::Polynomial g[3] = { hov::Polynomial::FromCoefficients({ 0.1, 1.0 }),
    hov::Polynomial::FromCoefficients({ 0.0 }), hov::Polynomial::FromCoefficients({ 1.0 }) };
  const hov::SegmentRay ray;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double L : { 0.0, -1.0, nan, std::numeric_limits<double>::infinity() })
  {
    const hov::ShadedSegmentResult r = hov::IntegrateShadedPolynomial(tf, s, g, L, vs, nullptr, ray, {});
    EXPECT_EQ(r.Color.A, 0.0) << L;
    EXPECT_TRUE(hovtest::AllFinite(r.Color));
  }
  hov::Polynomial bad = s;
  bad.C[1] = nan;
  const hov::ShadedSegmentResult r = hov::IntegrateShadedPolynomial(tf, bad, g, 1.0, vs, nullptr, ray, {});
  EXPECT_EQ(r.Color.A, 0.0);
  EXPECT_FALSE(r.Converged);
  // The gradient vanishing at one point of the segment (n undefined there): finite, converged.
  hov::Polynomial g0[3] = { hov::Polynomial::FromCoefficients({ -0.5, 1.0 }),
    hov::Polynomial::FromCoefficients({ 0.0 }), hov::Polynomial::FromCoefficients({ 0.0 }) };
  const hov::ShadedSegmentResult z = hov::IntegrateShadedPolynomial(tf, s, g0, 1.0, vs, nullptr, ray, {});
  EXPECT_TRUE(hovtest::AllFinite(z.Color));
  EXPECT_GT(z.Color.A, 0.0);
}
