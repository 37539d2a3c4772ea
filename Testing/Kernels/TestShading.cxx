// Tests of hovShading: edge-on opacity (closed form in long double, limits,
// cap, monotonicity), surface normals (orientation, scaling, fallback) and
// Blinn-Phong lighting against an independent long double transcription of
// the documented formula, closed forms (headlight, unshaded invariant),
// rotation invariance, two-sided lighting, spot cones, attenuation, and a
// no-NaN sweep.

#include "hovShading.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestUtilities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using hovtest::Str;
using hovtest::Worst;

namespace
{
/// EdgeOnOpacity vs 1 - (1 - a)^(1/c) in 50 digits: expm1/log1p and one
/// division, relative error a few ulp. Measured 2.7e-16.
constexpr double EdgeOnRel = 1e-14;
/// ShadePhong vs the long double transcription: a few dozen operations and
/// pow (powers up to 100 amplify the rounding of n.h). Measured 3.8e-15
/// absolute (colours O(1)).
constexpr double PhongAbs = 1e-13;

using Vec = std::array<double, 3>;

Vec RandomUnit(std::mt19937_64& rng)
{
  std::normal_distribution<double> n;
  Vec v{ n(rng), n(rng), n(rng) };
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / l, v[1] / l, v[2] / l };
}

/// The documented formula, transcribed independently in long double.
Vec ReferencePhong(const Vec& base, const Vec& p, const Vec& n, const Vec& v,
  const std::vector<hov::ShadingLight>& lights, const hov::ShadingMaterial& m)
{
  using LD = long double;
  auto dot = [](const LD* a, const LD* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto unit = [&](LD* a) {
    const LD l = std::sqrt(dot(a, a));
    for (int i = 0; i < 3; ++i)
    {
      a[i] /= l;
    }
  };
  const LD N[3] = { n[0], n[1], n[2] }, V[3] = { v[0], v[1], v[2] };
  LD out[3];
  for (int c = 0; c < 3; ++c)
  {
    out[c] = m.Ambient * static_cast<LD>(base[c]);
  }
  for (const hov::ShadingLight& light : lights)
  {
    LD L[3], f = light.Intensity;
    if (light.Positional)
    {
      for (int i = 0; i < 3; ++i)
      {
        L[i] = static_cast<LD>(light.Position[i]) - p[i];
      }
      const LD d = std::sqrt(dot(L, L));
      unit(L);
      f /= light.Attenuation[0] + light.Attenuation[1] * d + light.Attenuation[2] * d * d;
      if (light.ConeAngle < 90)
      {
        LD axis[3] = { light.Direction[0], light.Direction[1], light.Direction[2] };
        unit(axis);
        const LD cosAxis = -dot(L, axis);
        if (cosAxis < std::cos(static_cast<LD>(light.ConeAngle) * 3.14159265358979323846264L / 180))
        {
          continue;
        }
        f *= std::pow(cosAxis, static_cast<LD>(light.Exponent));
      }
    }
    else
    {
      for (int i = 0; i < 3; ++i)
      {
        L[i] = -static_cast<LD>(light.Direction[i]);
      }
      unit(L);
    }
    LD H[3] = { L[0] + V[0], L[1] + V[1], L[2] + V[2] };
    unit(H);
    LD nl = dot(N, L), nh = dot(N, H);
    if (m.TwoSidedLighting)
    {
      nl = std::fabs(nl);
      nh = std::fabs(nh);
    }
    for (int c = 0; c < 3; ++c)
    {
      out[c] += f * (m.Diffuse * std::max(nl, 0.0L) * base[c] * light.Color[c] +
                      (nh > 0 ? m.Specular * std::pow(nh, static_cast<LD>(m.SpecularPower)) : 0.0L) * light.Color[c]);
    }
  }
  return { static_cast<double>(out[0]), static_cast<double>(out[1]), static_cast<double>(out[2]) };
}

Vec Shade(const Vec& base, const Vec& p, const Vec& n, const Vec& v,
  const std::vector<hov::ShadingLight>& lights, const hov::ShadingMaterial& m)
{
  Vec out;
  hov::ShadePhong(base.data(), p.data(), n.data(), v.data(), lights.data(), static_cast<int>(lights.size()), m, out.data());
  return out;
}

double MaxDiff(const Vec& a, const Vec& b)
{
  return std::max(std::fabs(a[0] - b[0]), std::max(std::fabs(a[1] - b[1]), std::fabs(a[2] - b[2])));
}
}

TEST(Shading, EdgeOnOpacityClosedFormAndLimits)
{
  Worst worst;
  std::mt19937_64 rng(1);
  for (int i = 0; i < 5000; ++i)
  {
    const double a = i % 2 ? hovtest::LogUniform(rng, 1e-12, 0.999) : 1 - hovtest::LogUniform(rng, 1e-12, 1);
    const double c = hovtest::LogUniform(rng, 0.01, 1.0);
    // 50 digits: 1 - a and the power amplify long double rounding by 1/(c a).
    const hovtest::Mp ref = 1 - pow(1 - hovtest::Mp(a), 1 / hovtest::Mp(c));
    const double got = hov::EdgeOnOpacity(a, c);
    const double rel = hovtest::RelErr(got, ref);
    worst.Add(rel, "a=" + Str(a) + " c=" + Str(c));
    ASSERT_LE(rel, EdgeOnRel) << "a=" << a << " c=" << c;
  }
  hovtest::ReportMeasured("Shading.EdgeOnRel", worst);
  for (double a : { 1e-300, 1e-10, 0.25, 0.5, 0.999999 })
  {
    EXPECT_EQ(hov::EdgeOnOpacity(a, 1.0), a);  // normal incidence: the base opacity
    EXPECT_EQ(hov::EdgeOnOpacity(a, -1.0), a); // either side
    EXPECT_EQ(hov::EdgeOnOpacity(a, 0.0), hov::EdgeOnOpacity(a, hov::DefaultEdgeOnMinCosine)); // cap
    EXPECT_EQ(hov::EdgeOnOpacity(a, 1e-9, 0.5), hov::EdgeOnOpacity(a, 0.5, 0.5));
    double prev = a;
    for (double c = 0.9; c > 0.005; c *= 0.8) // more opaque the more oblique
    {
      const double v = hov::EdgeOnOpacity(a, c);
      EXPECT_GE(v, prev);
      EXPECT_LE(v, 1.0);
      prev = v;
    }
  }
  for (double c : { 1.0, 0.5, 0.0, -0.3, static_cast<double>(NAN), static_cast<double>(INFINITY) })
  {
    EXPECT_EQ(hov::EdgeOnOpacity(1.0, c), 1.0);
    EXPECT_EQ(hov::EdgeOnOpacity(0.0, c), 0.0);
    EXPECT_EQ(hov::EdgeOnOpacity(2.0, c), 1.0);
    EXPECT_EQ(hov::EdgeOnOpacity(NAN, c), 0.0);
    const double v = hov::EdgeOnOpacity(0.4, c, NAN);
    EXPECT_TRUE(v >= 0.4 && v <= 1.0);
  }
  // Thin-layer limit: a / c for small a.
  EXPECT_NEAR(hov::EdgeOnOpacity(1e-9, 0.25), 4e-9, 1e-17);
}

TEST(Shading, SurfaceNormalOrientationAndFallback)
{
  const double v[3] = { 0.0, 0.6, 0.8 };
  double n[3];
  const double g1[3] = { 3.0, -4.0, 0.0 };
  ASSERT_TRUE(hov::SurfaceNormal(g1, v, n));
  EXPECT_NEAR(n[0], -0.6, 2.3e-16); // flipped: n . v >= 0
  EXPECT_NEAR(n[1], 0.8, 2.3e-16);
  for (double scale : { 1e-310, 1e-200, 1.0, 1e200, 4e307 })
  {
    const double g[3] = { 1.0 * scale, 2.0 * scale, 2.0 * scale };
    ASSERT_TRUE(hov::SurfaceNormal(g, v, n)) << scale;
    EXPECT_NEAR(n[0], 1.0 / 3, 1e-15) << scale;
    EXPECT_NEAR(n[2], 2.0 / 3, 1e-15) << scale;
  }
  for (const Vec& g : { Vec{ 0, 0, 0 }, Vec{ NAN, 1, 0 }, Vec{ INFINITY, 0, 0 } })
  {
    EXPECT_FALSE(hov::SurfaceNormal(g.data(), v, n));
    EXPECT_EQ(n[1], 0.6);
    EXPECT_EQ(n[2], 0.8);
  }
}

TEST(Shading, PhongMatchesReferenceAndClosedForms)
{
  std::mt19937_64 rng(2);
  Worst worst;
  hov::ShadingMaterial m;
  m.ClampColor = false;
  for (int trial = 0; trial < 2000; ++trial)
  {
    m.Ambient = hovtest::Uniform(rng, 0, 1);
    m.Diffuse = hovtest::Uniform(rng, 0, 1);
    m.Specular = hovtest::Uniform(rng, 0, 1);
    m.SpecularPower = hovtest::Uniform(rng, 1, 100);
    m.TwoSidedLighting = trial % 2;
    std::vector<hov::ShadingLight> lights(1 + trial % 3);
    for (hov::ShadingLight& l : lights)
    {
      const Vec d = RandomUnit(rng);
      for (int i = 0; i < 3; ++i)
      {
        l.Direction[i] = 2.5 * d[i];
        l.Position[i] = hovtest::Uniform(rng, -5, 5);
        l.Color[i] = hovtest::Uniform(rng, 0, 1);
      }
      l.Intensity = hovtest::Uniform(rng, 0.2, 2);
      l.Positional = rng() % 2;
      l.Attenuation[0] = hovtest::Uniform(rng, 0.5, 1);
      l.Attenuation[1] = hovtest::Uniform(rng, 0, 0.5);
      l.Attenuation[2] = hovtest::Uniform(rng, 0, 0.1);
      l.ConeAngle = rng() % 2 ? hovtest::Uniform(rng, 10, 89) : 180.0;
      l.Exponent = hovtest::Uniform(rng, 0.5, 4);
    }
    const Vec base{ hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1) };
    const Vec p{ hovtest::Uniform(rng, -1, 1), hovtest::Uniform(rng, -1, 1), hovtest::Uniform(rng, -1, 1) };
    const Vec v = RandomUnit(rng);
    Vec n = RandomUnit(rng);
    const double d = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
    if (d < 0)
    {
      n = { -n[0], -n[1], -n[2] };
    }
    const double err = MaxDiff(Shade(base, p, n, v, lights, m), ReferencePhong(base, p, n, v, lights, m));
    worst.Add(err, "trial " + Str(trial));
    ASSERT_LE(err, PhongAbs) << "trial " << trial;
  }
  hovtest::ReportMeasured("Shading.PhongVsReference", worst);

  // Headlight (light travelling along -v onto a surface facing the viewer):
  // n.l = n.h = 1, C = (ka + kd) c + ks.
  hov::ShadingLight head;
  const Vec v{ 0.0, 0.0, 1.0 }, n{ 0.0, 0.0, 1.0 }, o{ 0, 0, 0 }, base{ 0.5, 0.25, 0.125 };
  for (int i = 0; i < 3; ++i)
  {
    head.Direction[i] = -v[i];
  }
  const Vec c = Shade(base, o, n, v, { head }, m);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(c[i], (m.Ambient + m.Diffuse) * base[i] + m.Specular, 1e-15);
  }
  // Unshaded invariant: ka = 1, kd = ks = 0 is the base colour, whatever the lights.
  hov::ShadingMaterial flat;
  flat.Ambient = 1.0;
  flat.Diffuse = 0.0;
  flat.Specular = 0.0;
  EXPECT_EQ(MaxDiff(Shade(base, o, n, v, { head, head }, flat), base), 0.0);
}

TEST(Shading, InvariancesConesAndTwoSidedLighting)
{
  std::mt19937_64 rng(3);
  hov::ShadingMaterial m;
  m.ClampColor = false;
  const Vec base{ 0.9, 0.6, 0.3 }, o{ 0, 0, 0 };
  Worst rot;
  for (int trial = 0; trial < 200; ++trial)
  {
    // Rotation about a random axis (Rodrigues) applied to everything.
    const Vec k = RandomUnit(rng);
    const double ang = hovtest::Uniform(rng, 0, 6.28), cs = std::cos(ang), sn = std::sin(ang);
    auto R = [&](const Vec& x) {
      const double kx = k[0] * x[0] + k[1] * x[1] + k[2] * x[2];
      const Vec c{ k[1] * x[2] - k[2] * x[1], k[2] * x[0] - k[0] * x[2], k[0] * x[1] - k[1] * x[0] };
      return Vec{ x[0] * cs + c[0] * sn + k[0] * kx * (1 - cs), x[1] * cs + c[1] * sn + k[1] * kx * (1 - cs),
        x[2] * cs + c[2] * sn + k[2] * kx * (1 - cs) };
    };
    const Vec v = RandomUnit(rng), n = RandomUnit(rng), p = RandomUnit(rng);
    hov::ShadingLight a, b;
    const Vec d = RandomUnit(rng), q{ 3, 1, 2 };
    a.Positional = true;
    a.ConeAngle = 60;
    for (int i = 0; i < 3; ++i)
    {
      a.Direction[i] = d[i];
      a.Position[i] = q[i];
    }
    b.Positional = true;
    b.ConeAngle = 60;
    const Vec rd = R(d), rq = R(q);
    for (int i = 0; i < 3; ++i)
    {
      b.Direction[i] = rd[i];
      b.Position[i] = rq[i];
    }
    const double err = MaxDiff(Shade(base, p, n, v, { a }, m), Shade(base, R(p), R(n), R(v), { b }, m));
    rot.Add(err, "trial " + Str(trial));
    EXPECT_LE(err, 1e-13);
  }
  hovtest::ReportMeasured("Shading.RotationInvariance", rot);

  const Vec v{ 0, 0, 1 }, n{ 0, 0, 1 };
  m.Specular = 0.0;
  // A light behind the surface: two-sided lighting sees the mirrored light.
  hov::ShadingLight behind, mirrored;
  const double dir[3] = { 0.3, 0.4, 0.866 }; // travels away from the viewer side
  for (int i = 0; i < 3; ++i)
  {
    behind.Direction[i] = dir[i];
    mirrored.Direction[i] = i == 2 ? -dir[i] : dir[i];
  }
  EXPECT_LE(MaxDiff(Shade(base, o, n, v, { behind }, m), Shade(base, o, n, v, { mirrored }, m)), 1e-15);
  m.TwoSidedLighting = false;
  const Vec amb = Shade(base, o, n, v, { behind }, m);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(amb[i], m.Ambient * base[i], 1e-16); // one-sided: unlit from behind
  }
  // Spot: a point outside the cone gets ambient only; inside, (cos)^e.
  hov::ShadingLight spot;
  spot.Positional = true;
  spot.Position[2] = 2.0;
  spot.Direction[0] = 0.0;
  spot.Direction[2] = -1.0;
  spot.ConeAngle = 20.0;
  spot.Exponent = 3.0;
  const Vec outside{ 1.0, 0.0, 0.0 }, inside{ 0.2, 0.0, 0.0 };
  const Vec cOut = Shade(base, outside, n, v, { spot }, m);
  EXPECT_NEAR(cOut[0], m.Ambient * base[0], 1e-16);
  const double d = std::sqrt(0.04 + 4.0), cosAxis = 2.0 / d;
  const Vec cIn = Shade(base, inside, n, v, { spot }, m);
  EXPECT_NEAR(cIn[0], m.Ambient * base[0] + m.Diffuse * std::pow(cosAxis, 3.0) * cosAxis * base[0], 1e-15);
  // Attenuation 1/(a0 + a1 d + a2 d^2).
  spot.ConeAngle = 180.0;
  spot.Attenuation[0] = 0.5;
  spot.Attenuation[1] = 0.25;
  spot.Attenuation[2] = 0.125;
  const Vec cAtt = Shade(base, inside, n, v, { spot }, m);
  EXPECT_NEAR(cAtt[0], m.Ambient * base[0] + m.Diffuse * cosAxis * base[0] / (0.5 + 0.25 * d + 0.125 * d * d), 1e-15);
}

TEST(Shading, SweepHasNoNaN)
{
  std::mt19937_64 rng(4);
  hov::ShadingMaterial m;
  auto odd = [&]() {
    const int k = static_cast<int>(rng() % 7);
    return k == 0 ? 0.0 : k == 1 ? NAN : k == 2 ? INFINITY : k == 3 ? -1e300 : hovtest::Uniform(rng, -2, 2);
  };
  for (int i = 0; i < 5000; ++i)
  {
    hov::ShadingLight l;
    for (int k = 0; k < 3; ++k)
    {
      l.Direction[k] = odd();
      l.Position[k] = odd();
    }
    l.Positional = i % 2;
    l.ConeAngle = i % 3 ? 30 : 180;
    l.Attenuation[1] = i % 5 ? 0.0 : -10.0;
    const Vec base{ odd(), 0.5, 0.5 }, p{ odd(), odd(), 0 }, v{ 0, 0, 1 };
    Vec n;
    const Vec g{ odd(), odd(), odd() };
    hov::SurfaceNormal(g.data(), v.data(), n.data());
    const Vec c = Shade(base, p, n, v, { l }, m);
    for (double x : c)
    {
      ASSERT_TRUE(std::isfinite(x));
      ASSERT_GE(x, 0.0);
      ASSERT_LE(x, 1.0);
    }
  }
}
