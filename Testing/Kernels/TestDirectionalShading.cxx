// The directional-light shortcut of the volume shading (hovVolumeShading.h:
// PrepareDirectionalShading once per ray, then ComputeShadingTransform from
// the prepared lights per sample) must give, bit for bit, the transform the
// general ComputeShadingTransform gives at any point: random lights and
// materials, both ambient terms, one- and two-sided lighting, clamped or not,
// and the edge cases (a zero light direction, a light exactly behind the eye
// ray, non-finite intensities, zero, tiny, huge and NaN gradients, Shade off).
// Positional lights and more than MaxLights lights are refused. Also checks
// that PhongLightSums is its two steps (ComputeLightVectors, AddPhongLight).
#include "hovVolumeShading.h"

#include "hovKernelTestUtilities.h"
#include "hovShadingTestMaterial.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace
{
bool SameBits(const hov::ShadingTransform& a, const hov::ShadingTransform& b)
{
  return std::memcmp(a.Scale, b.Scale, sizeof(a.Scale)) == 0 &&
    std::memcmp(a.Offset, b.Offset, sizeof(a.Offset)) == 0 && a.Clamp == b.Clamp &&
    a.Lit == b.Lit;
}

void UnitRandom(std::mt19937_64& rng, double v[3])
{
  std::normal_distribution<double> nd;
  double l = 0.0;
  while (!(l > 1e-3))
  {
    for (int i = 0; i < 3; ++i)
    {
      v[i] = nd(rng);
    }
    l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }
  for (int i = 0; i < 3; ++i)
  {
    v[i] /= l;
  }
}

TEST(DirectionalShading, PreparedLightsAreBitForBit)
{
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::mt19937_64 rng(4711);
  std::normal_distribution<double> nd;
  int checked = 0, lit = 0, edgeCases = 0, noHalf = 0;
  for (int trial = 0; trial < 4000; ++trial)
  {
    double toViewer[3];
    UnitRandom(rng, toViewer);
    std::vector<hov::ShadingLight> lights(trial % 9); // 0 .. 8 lights
    for (size_t i = 0; i < lights.size(); ++i)
    {
      hov::ShadingLight& l = lights[i];
      for (int k = 0; k < 3; ++k)
      {
        l.Direction[k] = nd(rng);
        l.Color[k] = hovtest::Uniform(rng, 0, 1);
      }
      l.Intensity = hovtest::Uniform(rng, 0.2, 2);
      switch ((trial + static_cast<int>(i)) % 23)
      {
        case 0: // the light travels along the view vector: toward it is -v, half = 0
          // (an axis-aligned view vector, so that normalising it is exact)
          toViewer[0] = toViewer[1] = 0.0;
          toViewer[2] = 1.0;
          for (int k = 0; k < 3; ++k)
          {
            l.Direction[k] = toViewer[k];
          }
          ++edgeCases;
          break;
        case 1:
          l.Direction[0] = l.Direction[1] = l.Direction[2] = 0.0; // no direction: dark
          ++edgeCases;
          break;
        case 2:
          l.Intensity = trial % 2 ? inf : nan;
          ++edgeCases;
          break;
        case 3:
          l.Direction[0] = 1e300; // large: normalised by its largest component
          ++edgeCases;
          break;
        default:
          break;
      }
    }
    hov::VolumeShadingSettings vs;
    vs.Shade = trial % 50 != 0;
    hovtest::RandomShadingMaterial(rng, trial, vs);
    vs.GradientFloor = trial % 11 == 0 ? 0.5 : 0.0;
    vs.Lights = lights.empty() ? nullptr : lights.data();
    vs.LightCount = static_cast<int>(lights.size());
    hov::DirectionalShading prepared;
    ASSERT_TRUE(hov::PrepareDirectionalShading(vs, toViewer, prepared)) << trial;
    for (int i = 0; i < prepared.Count; ++i)
    {
      noHalf += !prepared.Lights[i].HasHalf;
    }
    for (int sample = 0; sample < 8; ++sample)
    {
      double g[3] = { nd(rng), nd(rng), nd(rng) };
      switch (sample)
      {
        case 0:
          g[0] = g[1] = g[2] = 0.0;
          break;
        case 1:
          g[0] *= 1e-300;
          g[1] *= 1e-300;
          g[2] *= 1e-300;
          break;
        case 2:
          g[1] = 1e300;
          break;
        case 3:
          g[2] = nan;
          break;
        default:
          break;
      }
      double point[3] = { nd(rng), nd(rng), nd(rng) };
      const hov::ShadingTransform general = hov::ComputeShadingTransform(vs, g, point, toViewer);
      const hov::ShadingTransform fast = hov::ComputeShadingTransform(prepared, g);
      ASSERT_TRUE(SameBits(general, fast)) << "trial " << trial << " sample " << sample;
      ++checked;
      lit += general.Lit;
    }
  }
  std::cout << "[measured] DirectionalShading: " << checked << " transforms bit for bit (" << lit
            << " lit, " << edgeCases << " edge-case lights, " << noHalf
            << " without a half vector)" << std::endl;
  EXPECT_GT(lit, checked / 2);
  EXPECT_GT(edgeCases, 100);
  EXPECT_GT(noHalf, 10); // the light exactly behind the eye ray was reached
}

TEST(DirectionalShading, RefusesWhatItCannotPrepare)
{
  const double toViewer[3] = { 0.0, 0.0, 1.0 };
  hov::VolumeShadingSettings vs;
  vs.Shade = true;
  std::vector<hov::ShadingLight> lights(2);
  lights[1].Positional = true;
  vs.Lights = lights.data();
  vs.LightCount = 2;
  hov::DirectionalShading prepared;
  EXPECT_FALSE(hov::PrepareDirectionalShading(vs, toViewer, prepared)); // positional
  lights[1].Positional = false;
  EXPECT_TRUE(hov::PrepareDirectionalShading(vs, toViewer, prepared));
  EXPECT_EQ(prepared.Count, 2);
  lights.assign(hov::DirectionalShading::MaxLights + 1, hov::ShadingLight());
  vs.Lights = lights.data();
  vs.LightCount = static_cast<int>(lights.size());
  EXPECT_FALSE(hov::PrepareDirectionalShading(vs, toViewer, prepared)); // too many
  vs.Shade = false; // no shading: the identity, prepared whatever the lights
  EXPECT_TRUE(hov::PrepareDirectionalShading(vs, toViewer, prepared));
  const double g[3] = { 1.0, 2.0, 3.0 };
  EXPECT_TRUE(hov::IsIdentity(hov::ComputeShadingTransform(prepared, g)));
}

TEST(DirectionalShading, PhongLightSumsIsItsTwoSteps)
{
  std::mt19937_64 rng(4712);
  std::normal_distribution<double> nd;
  for (int trial = 0; trial < 2000; ++trial)
  {
    std::vector<hov::ShadingLight> lights(1 + trial % 4);
    for (hov::ShadingLight& l : lights)
    {
      for (int k = 0; k < 3; ++k)
      {
        l.Direction[k] = nd(rng);
        l.Position[k] = hovtest::Uniform(rng, -3, 3);
        l.Color[k] = hovtest::Uniform(rng, 0, 1);
      }
      l.Positional = rng() % 2;
      l.Attenuation[1] = hovtest::Uniform(rng, 0, 0.5);
      l.ConeAngle = rng() % 2 ? hovtest::Uniform(rng, 10, 89) : 180.0;
    }
    hov::ShadingMaterial material;
    material.SpecularPower = hovtest::Uniform(rng, 1, 50);
    material.TwoSidedLighting = trial % 2;
    double normal[3], toViewer[3];
    UnitRandom(rng, normal);
    UnitRandom(rng, toViewer);
    const double point[3] = { nd(rng), nd(rng), nd(rng) };
    double d1[3], s1[3], d2[3] = { 0.0, 0.0, 0.0 }, s2[3] = { 0.0, 0.0, 0.0 };
    hov::PhongLightSums(point, normal, toViewer, lights.data(), static_cast<int>(lights.size()),
      material, d1, s1);
    for (const hov::ShadingLight& l : lights)
    {
      hov::LightVectors v;
      if (hov::ComputeLightVectors(l, point, normal, toViewer, v))
      {
        hov::AddPhongLight(v, normal, l.Color, material, d2, s2);
      }
    }
    ASSERT_EQ(std::memcmp(d1, d2, sizeof(d1)), 0) << trial;
    ASSERT_EQ(std::memcmp(s1, s2, sizeof(s1)), 0) << trial;
  }
}
}
