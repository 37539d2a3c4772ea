/**
 * @file hovShadingTestMaterial.h
 * @brief The shading kernel tests' random material: ambient, diffuse,
 * specular and power, one- or two-sided lighting, clamping, the ambient term
 * and the ambient light, varied with the trial number (each option in its own
 * period, so that every combination occurs). The lights, Shade and the
 * gradient floor are each test's own.
 */
#ifndef hovShadingTestMaterial_h
#define hovShadingTestMaterial_h

#include "hovVolumeShading.h"

#include "hovKernelTestReference.h" // Uniform

#include <random>

namespace hovtest
{
/// Sets @p vs's material, ambient term and ambient light for trial @p trial.
inline void RandomShadingMaterial(std::mt19937_64& rng, int trial, hov::VolumeShadingSettings& vs)
{
  vs.Material.Ambient = Uniform(rng, 0, 0.5);
  vs.Material.Diffuse = Uniform(rng, 0, 1);
  vs.Material.Specular = Uniform(rng, 0, 1);
  vs.Material.SpecularPower = trial % 4 == 0 ? 10.0 : Uniform(rng, 1, 100);
  vs.Material.TwoSidedLighting = trial % 2;
  vs.Material.ClampColor = trial % 3 != 0;
  vs.Ambient = trial % 5 == 0 ? hov::AmbientTerm::LightAmbient : hov::AmbientTerm::MaterialColor;
  for (double& a : vs.AmbientLight)
  {
    a = Uniform(rng, 0, 0.3);
  }
}
}

#endif
