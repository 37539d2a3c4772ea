/**
 * @file hovShadedSegmentTestCase.h
 * @brief The random cases of the hovShadedSegment tests and their
 * independent long double reference (raw-node transfer and gradient-opacity
 * functions, Blinn-Phong transcribed per point with directional or
 * positional lights, breakpoints located by bisection, Boost Gauss-Kronrod:
 * hovFeatureTestReference.h). Used by TestShadedSegment.cxx and
 * TestShadedSegmentLights.cxx.
 */
#ifndef hovShadedSegmentTestCase_h
#define hovShadedSegmentTestCase_h

#include "hovGradientOpacity.h"
#include "hovShadedSegment.h" // SegmentRay
#include "hovShading.h"
#include "hovVolumeShading.h"
#include "hovTransferFunction.h"

#include "hovFeatureTestReference.h"
#include "hovKernelTestUtilities.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace hovtest
{
inline hov::ShadingLight Directional(double x, double y, double z, double intensity = 1.0)
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

/// The kernel's inputs of a case: the tables, the shading settings (Shade on,
/// the case's lights), the field and gradient polynomials and the ray.
struct CaseInputs
{
  hov::TransferFunction TF;
  hov::GradientOpacityFunction GO;
  hov::VolumeShadingSettings Shading;
  hov::Polynomial S, G[3];
  hov::SegmentRay Ray;

  explicit CaseInputs(const Case& c)
  {
    this->TF.Build(c.Spec);
    this->GO.Build(c.GO);
    this->Shading.Shade = true;
    this->Shading.Material = c.Material;
    this->Shading.Lights = c.Lights.data();
    this->Shading.LightCount = static_cast<int>(c.Lights.size());
    c.F.Polynomials(this->S, this->G);
    for (int i = 0; i < 3; ++i)
    {
      this->Ray.Origin[i] = c.F.O[i];
      this->Ray.Direction[i] = c.F.D[i];
    }
  }
};

inline Case RandomCase(std::mt19937_64& rng, int trial)
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
inline RefRGBA Reference(const Case& c, hov::EmissionModel em, double* selfError = nullptr)
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
    const LD p[3] = { c.F.O[0] + t * c.F.D[0], c.F.O[1] + t * c.F.D[1], c.F.O[2] + t * c.F.D[2] };
    LD M[3], K[3], col[3];
    hovtest::ReferenceBlinnPhong(n, v, c.Lights, c.Material, false, zero, M, K, p);
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
  // max(0, .) one-sided), i.e. where g(t).l(t) and g(t).h(t) change sign (l
  // varies along the ray for positional lights).
  for (const auto& light : c.Lights)
  {
    for (int half = 0; half < 2; ++half)
    {
      auto dot = [&](LD t) {
        const LD p[3] = { c.F.O[0] + t * c.F.D[0], c.F.O[1] + t * c.F.D[1], c.F.O[2] + t * c.F.D[2] };
        LD l[3], f, g[3];
        hovtest::ReferenceLightAt(light, p, l, f);
        if (half)
        {
          for (int i = 0; i < 3; ++i)
          {
            l[i] += v[i]; // the half vector's direction (its length does not change the sign)
          }
        }
        c.F.G(t, g);
        return g[0] * l[0] + g[1] * l[1] + g[2] * l[2];
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

#endif
