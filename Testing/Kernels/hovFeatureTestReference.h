/**
 * @file hovFeatureTestReference.h
 * @brief Independent long double references for the issue-19 kernels
 * (blend modes, volume shading, gradient opacity): nothing here calls
 * hov::TransferFunction, the segment integrals or the kernels' root finders.
 *
 *  - RefPwl / RefRawTransfer: piecewise-linear functions from the raw nodes
 *    (sorted stably; a jump takes its right value at its node; constant
 *    beyond the ends), evaluated in long double.
 *  - ReferenceMedium: C = int_0^L E(t) e^-D(t) dt, A = 1 - e^-D(L),
 *    D(t) = int_0^t tau, for arbitrary callables: D by adaptive
 *    Gauss-Kronrod (31 points) from the piece's start, C by adaptive
 *    Gauss-Kronrod (61 points) on every piece between the given
 *    breakpoints, both Boost.Math in long double.
 *  - LevelCrossings: every t in [a, b] where f(t) crosses a level, by dense
 *    sampling and bisection in long double.
 *  - ReferenceBlinnPhong: the shading formula of hovVolumeShading.h
 *    transcribed for directional lights in long double.
 */
#ifndef hovFeatureTestReference_h
#define hovFeatureTestReference_h

#include "hovShading.h"
#include "hovTransferFunction.h"

#include "hovKernelTestReference.h" // RefRGBA

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace hovtest
{
using LD = long double;

/// Piecewise-linear function through raw nodes (file doc).
struct RefPwl
{
  std::vector<LD> X, V;

  LD operator()(LD s) const
  {
    if (X.empty())
    {
      return 0.0L;
    }
    if (s < X.front())
    {
      return V.front();
    }
    if (s >= X.back())
    {
      return V.back();
    }
    const size_t i = static_cast<size_t>(std::upper_bound(X.begin(), X.end(), s) - X.begin()) - 1;
    if (X[i + 1] == X[i])
    {
      return V[i + 1];
    }
    return V[i] + (V[i + 1] - V[i]) * ((s - X[i]) / (X[i + 1] - X[i]));
  }
};

/// Colour and raw opacity of a spec (assumed sorted, valid).
struct RefRawTransfer
{
  RefPwl R, G, B, A;
  LD Unit = 1.0L;
  hov::OpacitySemantics Semantics = hov::OpacitySemantics::VTKUnstructured;

  explicit RefRawTransfer(const hov::TransferFunctionSpec& spec)
  {
    for (const auto& n : spec.Color)
    {
      R.X.push_back(n.X);
      G.X.push_back(n.X);
      B.X.push_back(n.X);
      R.V.push_back(n.R);
      G.V.push_back(n.G);
      B.V.push_back(n.B);
    }
    for (const auto& n : spec.Opacity)
    {
      A.X.push_back(n.X);
      A.V.push_back(n.Opacity);
    }
    Unit = spec.UnitDistance;
    Semantics = spec.Semantics;
  }

  void Color(LD s, LD c[3]) const
  {
    c[0] = R(s);
    c[1] = G(s);
    c[2] = B(s);
  }

  /// Extinction per unit length in the spec's semantics (true -ln(1-a)/u for GPU).
  LD Tau(LD s) const
  {
    const LD a = A(s);
    switch (Semantics)
    {
      case hov::OpacitySemantics::GPUCompatible:
        return -std::log1p(-a) / Unit;
      case hov::OpacitySemantics::VTKUnstructured:
        return a / Unit;
      default:
        return a;
    }
  }
};

/// Sorted t in [a, b] where f crosses @p level (sign change), by sampling and bisection.
inline std::vector<LD> LevelCrossings(
  const std::function<LD(LD)>& f, LD level, LD a, LD b, int samples = 4000)
{
  std::vector<LD> out;
  LD t0 = a, f0 = f(a) - level;
  for (int i = 1; i <= samples; ++i)
  {
    const LD t1 = a + (b - a) * i / samples;
    const LD f1 = f(t1) - level;
    if ((f0 < 0) != (f1 < 0) && f0 != 0)
    {
      LD lo = t0, hi = t1, flo = f0;
      for (int k = 0; k < 200 && hi - lo > 0; ++k)
      {
        const LD m = 0.5L * (lo + hi);
        if (m <= lo || m >= hi)
        {
          break;
        }
        const LD fm = f(m) - level;
        if ((fm < 0) == (flo < 0))
        {
          lo = m;
          flo = fm;
        }
        else
        {
          hi = m;
        }
      }
      out.push_back(0.5L * (lo + hi));
    }
    t0 = t1;
    f0 = f1;
  }
  return out;
}

/// A medium along [0, Length]: extinction Tau(t), emission Emission(t, channel).
struct RefMedium
{
  std::function<LD(LD)> Tau;
  std::function<LD(LD, int)> Emission;
  std::vector<LD> Breaks; ///< interior kinks/jumps, any order
  LD Length = 1.0L;
};

inline RefRGBA ReferenceMedium(const RefMedium& m, LD tol = 1e-16L)
{
  // Outer: adaptive 61-point Gauss-Kronrod (the integrand is smooth between
  // the breakpoints: one level usually reaches long double rounding; tanh-sinh
  // asked for ~1e-17 refined to its last level and took minutes per case).
  // Inner: 31-point Gauss-Kronrod from the piece's start (exact for the
  // piecewise-linear extinctions of the tests, adaptive otherwise).
  using GKOuter = boost::math::quadrature::gauss_kronrod<LD, 61>;
  using GK = boost::math::quadrature::gauss_kronrod<LD, 31>;
  std::vector<LD> cuts{ 0.0L, m.Length };
  for (LD b : m.Breaks)
  {
    if (b > 0 && b < m.Length)
    {
      cuts.push_back(b);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  RefRGBA out;
  LD depth = 0.0L;
  for (size_t p = 0; p + 1 < cuts.size(); ++p)
  {
    const LD p0 = cuts[p], p1 = cuts[p + 1];
    auto depthTo = [&](LD t) {
      return t <= p0 ? 0.0L : GK::integrate(m.Tau, p0, t, 2, tol);
    };
    for (int ch = 0; ch < 3; ++ch)
    {
      auto f = [&](LD t) { return m.Emission(t, ch) * std::exp(-(depth + depthTo(t))); };
      const LD v = GKOuter::integrate(f, p0, p1, 3, tol);
      (ch == 0 ? out.R : (ch == 1 ? out.G : out.B)) += v;
    }
    depth += depthTo(p1);
  }
  out.A = -std::expm1(-depth);
  return out;
}

/// The same integral by composite 30-point Gauss-Legendre (Boost.Math nodes),
/// non-adaptive: every piece between breakpoints cut into @p panels equal
/// panels; D at each node = D at the panel's start + a 30-point rule over
/// [start, node]. For integrands analytic between the breakpoints (shaded,
/// gradient-opacity-modulated media) this converges geometrically in
/// @p panels; callers compare two panel counts to bound its own error.
inline RefRGBA ReferenceMediumComposite(const RefMedium& m, int panels)
{
  using GL = boost::math::quadrature::gauss<LD, 30>;
  std::vector<LD> cuts{ 0.0L, m.Length };
  for (LD b : m.Breaks)
  {
    if (b > 0 && b < m.Length)
    {
      cuts.push_back(b);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  RefRGBA out;
  LD depth = 0.0L;
  for (size_t p = 0; p + 1 < cuts.size(); ++p)
  {
    for (int k = 0; k < panels; ++k)
    {
      const LD a = cuts[p] + (cuts[p + 1] - cuts[p]) * k / panels;
      const LD b = k + 1 == panels ? cuts[p + 1] : cuts[p] + (cuts[p + 1] - cuts[p]) * (k + 1) / panels;
      auto depthTo = [&](LD t) { return t <= a ? 0.0L : GL::integrate(m.Tau, a, t); };
      for (int ch = 0; ch < 3; ++ch)
      {
        auto f = [&](LD t) { return m.Emission(t, ch) * std::exp(-(depth + depthTo(t))); };
        (ch == 0 ? out.R : (ch == 1 ? out.G : out.B)) += GL::integrate(f, a, b);
      }
      depth += depthTo(b);
    }
  }
  out.A = -std::expm1(-depth);
  return out;
}

/// Directional Blinn-Phong (hovVolumeShading.h's formula) in long double:
/// returns M and K per channel (c_sh = clamp(M c + K)).
inline void ReferenceBlinnPhong(const LD n[3], const LD v[3],
  const std::vector<hov::ShadingLight>& lights, const hov::ShadingMaterial& m, bool lightAmbient,
  const LD ambientLight[3], LD M[3], LD K[3])
{
  auto dot = [](const LD* a, const LD* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  for (int c = 0; c < 3; ++c)
  {
    M[c] = lightAmbient ? 0.0L : static_cast<LD>(m.Ambient);
    K[c] = lightAmbient ? m.Ambient * ambientLight[c] : 0.0L;
  }
  for (const auto& light : lights)
  {
    LD l[3] = { -light.Direction[0], -light.Direction[1], -light.Direction[2] };
    const LD ll = std::sqrt(dot(l, l));
    for (LD& x : l)
    {
      x /= ll;
    }
    LD h[3] = { l[0] + v[0], l[1] + v[1], l[2] + v[2] };
    const LD hl = std::sqrt(dot(h, h));
    LD nh = 0.0L;
    if (hl > 0)
    {
      for (LD& x : h)
      {
        x /= hl;
      }
      nh = dot(n, h);
    }
    LD nl = dot(n, l);
    if (m.TwoSidedLighting)
    {
      nl = std::fabs(nl);
      nh = std::fabs(nh);
    }
    const LD df = light.Intensity * std::max(nl, 0.0L);
    const LD sf = nh > 0 ? light.Intensity * std::pow(nh, static_cast<LD>(m.SpecularPower)) : 0.0L;
    for (int c = 0; c < 3; ++c)
    {
      M[c] += m.Diffuse * df * light.Color[c];
      K[c] += m.Specular * sf * light.Color[c];
    }
  }
}
}

#endif
