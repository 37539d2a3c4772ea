#include "hovShading.h"

#include <algorithm> // std::min, std::max
#include <cmath>     // sqrt, pow, expm1, log1p, fabs, isfinite, cos

namespace hov
{
namespace
{
// Gradients with a squared length below this (or above the next) cannot be
// normalised by g / sqrt(g.g) without underflow/overflow: they are rescaled by
// their largest component first; only an exactly zero or non-finite gradient
// takes the fallback.
constexpr double TinySquare = 1e-280;
constexpr double HugeSquare = 1e280;
// MinCosine is clamped to [MinCosineFloor, 1]: the path factor stays <= 1e6.
constexpr double MinCosineFloor = 1e-6;
constexpr double DegreesToRadians = 3.14159265358979323846 / 180.0;

inline double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// out = v / |v|; false if v is zero or not finite.
bool Normalize(const double v[3], double out[3])
{
  double s[3] = { v[0], v[1], v[2] };
  double len2 = Dot(s, s);
  if (!std::isfinite(len2) || len2 < TinySquare || len2 > HugeSquare)
  {
    const double m = std::max(std::fabs(v[0]), std::max(std::fabs(v[1]), std::fabs(v[2])));
    if (!(m > 0.0) || !std::isfinite(m))
    {
      return false;
    }
    for (int i = 0; i < 3; ++i)
    {
      s[i] = v[i] / m;
    }
    len2 = Dot(s, s);
  }
  const double inv = 1.0 / std::sqrt(len2);
  for (int i = 0; i < 3; ++i)
  {
    out[i] = s[i] * inv;
  }
  return true;
}

/**
 * Unit vector @p l toward the light from @p point and the light's factor
 * (intensity times attenuation and spot factor). False if the light does not
 * reach the point (outside its cone, zero direction, bad attenuation).
 */
bool LightAt(const ShadingLight& light, const double point[3], const double normal[3], double l[3],
  double& factor)
{
  factor = light.Intensity;
  if (!light.Positional)
  {
    double d[3];
    if (!Normalize(light.Direction, d))
    {
      return false;
    }
    l[0] = -d[0];
    l[1] = -d[1];
    l[2] = -d[2];
    return std::isfinite(factor);
  }
  const double toLight[3] = { light.Position[0] - point[0], light.Position[1] - point[1],
    light.Position[2] - point[2] };
  const double dist = std::sqrt(Dot(toLight, toLight));
  if (!Normalize(toLight, l))
  {
    // The light sits on the point: it shines along the normal.
    l[0] = normal[0];
    l[1] = normal[1];
    l[2] = normal[2];
  }
  const double denom =
    light.Attenuation[0] + dist * (light.Attenuation[1] + dist * light.Attenuation[2]);
  if (!(denom > 0.0) || !std::isfinite(denom))
  {
    return false;
  }
  factor /= denom;
  if (light.ConeAngle < 90.0)
  {
    double axis[3];
    if (!Normalize(light.Direction, axis))
    {
      return false;
    }
    const double c = -Dot(l, axis); // cos between the axis and light -> point
    if (c < std::cos(light.ConeAngle * DegreesToRadians))
    {
      return false;
    }
    factor *= std::pow(c, light.Exponent);
  }
  return std::isfinite(factor);
}
}

bool SurfaceNormal(const double gradient[3], const double toViewer[3], double normal[3])
{
  if (!Normalize(gradient, normal))
  {
    normal[0] = toViewer[0];
    normal[1] = toViewer[1];
    normal[2] = toViewer[2];
    return false;
  }
  if (Dot(normal, toViewer) < 0.0)
  {
    normal[0] = -normal[0];
    normal[1] = -normal[1];
    normal[2] = -normal[2];
  }
  return true;
}

double EdgeOnOpacity(double alpha, double cosIncidence, double minCosine)
{
  if (!(alpha > 0.0)) // also NaN
  {
    return 0.0;
  }
  if (alpha >= 1.0)
  {
    return 1.0;
  }
  const double cMin = std::isfinite(minCosine) ? std::min(std::max(minCosine, MinCosineFloor), 1.0) : 1.0;
  const double c = std::isfinite(cosIncidence) ? std::min(std::max(std::fabs(cosIncidence), cMin), 1.0) : 1.0;
  if (c == 1.0)
  {
    return alpha; // exactly the base opacity at normal incidence
  }
  return -std::expm1(std::log1p(-alpha) / c);
}

bool ComputeLightVectors(const ShadingLight& light, const double point[3], const double normal[3],
  const double toViewer[3], LightVectors& out)
{
  if (!LightAt(light, point, normal, out.L, out.Factor))
  {
    return false;
  }
  const double half[3] = { out.L[0] + toViewer[0], out.L[1] + toViewer[1],
    out.L[2] + toViewer[2] };
  out.HasHalf = Normalize(half, out.H); // false: the light exactly behind the eye ray
  return true;
}

void AddPhongLight(const LightVectors& light, const double normal[3], const double color[3],
  const ShadingMaterial& material, double diffuse[3], double specular[3])
{
  double nDotL = Dot(normal, light.L);
  double nDotH = light.HasHalf ? Dot(normal, light.H) : 0.0;
  if (material.TwoSidedLighting)
  {
    nDotL = std::fabs(nDotL);
    nDotH = std::fabs(nDotH);
  }
  const double df = light.Factor * std::max(nDotL, 0.0);
  const double sf = nDotH > 0.0 ? light.Factor * std::pow(nDotH, material.SpecularPower) : 0.0;
  for (int c = 0; c < 3; ++c)
  {
    diffuse[c] += df * color[c];
    specular[c] += sf * color[c];
  }
}

void PhongLightSums(const double point[3], const double normal[3], const double toViewer[3],
  const ShadingLight* lights, int lightCount, const ShadingMaterial& material, double diffuse[3],
  double specular[3])
{
  for (int c = 0; c < 3; ++c)
  {
    diffuse[c] = 0.0;
    specular[c] = 0.0;
  }
  for (int i = 0; lights && i < lightCount; ++i)
  {
    LightVectors v;
    if (ComputeLightVectors(lights[i], point, normal, toViewer, v))
    {
      AddPhongLight(v, normal, lights[i].Color, material, diffuse, specular);
    }
  }
}

void ComposePhong(const double baseColor[3], const ShadingMaterial& material,
  const double diffuse[3], const double specular[3], double out[3])
{
  for (int c = 0; c < 3; ++c)
  {
    double v = material.Ambient * baseColor[c] + material.Diffuse * diffuse[c] * baseColor[c] +
      material.Specular * specular[c];
    if (material.ClampColor)
    {
      v = std::isnan(v) ? 0.0 : std::min(std::max(v, 0.0), 1.0);
    }
    out[c] = v;
  }
}

void ShadePhong(const double baseColor[3], const double point[3], const double normal[3],
  const double toViewer[3], const ShadingLight* lights, int lightCount,
  const ShadingMaterial& material, double out[3])
{
  double diffuse[3], specular[3];
  PhongLightSums(point, normal, toViewer, lights, lightCount, material, diffuse, specular);
  ComposePhong(baseColor, material, diffuse, specular, out);
}
}
