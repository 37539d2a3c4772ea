#include "hovVolumeShading.h"

#include "hovSegmentIntegral.h"  // IntegrateSegment (exact pieces)
#include "hovTransferFunction.h" // the table walked here

#include <algorithm> // sort, min, max
#include <cmath>     // isfinite, isnan, isinf
#include <limits>    // infinity

namespace hov
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

double ClampUnit(double v)
{
  return std::isnan(v) ? 0.0 : std::min(std::max(v, 0.0), 1.0);
}

/// gamma as used on extinction: NaN or negative -> 0.
double SanitizeGamma(double gamma)
{
  return gamma > 0.0 ? gamma : 0.0;
}

/// gamma tau with 0 x inf = 0 (a gradient opacity of 0 removes even an opaque medium).
double ScaleTau(double tau, double gamma)
{
  return gamma == 0.0 ? 0.0 : gamma * tau;
}

/// One piece [x0, x1] (fractions of the segment) of one table interval: split
/// at the clamp kinks of the shaded colour, each sub-piece integrated exactly.
void IntegratePiece(RGBA& accum, int& count, const SegmentEnd& f, const SegmentEnd& b,
  double x0, double x1, double length, const ShadingTransform& shade, double gamma,
  double emissionFactor, const IntegrationSettings& settings)
{
  // u_c(y) = Scale c(y) + Offset, y in [0, 1] over the piece: linear.
  double u0[3], u1[3];
  for (int c = 0; c < 3; ++c)
  {
    u0[c] = shade.Scale[c] * f.Color[c] + shade.Offset[c];
    u1[c] = shade.Scale[c] * b.Color[c] + shade.Offset[c];
  }
  double cuts[8];
  int n = 0;
  cuts[n++] = 0.0;
  if (shade.Clamp)
  {
    for (int c = 0; c < 3; ++c)
    {
      for (double level : { 0.0, 1.0 })
      {
        if ((u0[c] - level) * (u1[c] - level) < 0.0)
        {
          cuts[n++] = (level - u0[c]) / (u1[c] - u0[c]); // strictly inside (0, 1)
        }
      }
    }
    std::sort(cuts + 1, cuts + n);
  }
  cuts[n++] = 1.0;
  const bool opaque = std::isinf(f.Tau) || std::isinf(b.Tau);
  auto endAt = [&](double y, SegmentEnd& e) {
    e.Tau = opaque ? (gamma == 0.0 ? 0.0 : Infinity)
                   : ScaleTau(f.Tau + (b.Tau - f.Tau) * y, gamma);
    for (int c = 0; c < 3; ++c)
    {
      double v = u0[c] + (u1[c] - u0[c]) * y;
      if (y == 0.0)
      {
        v = u0[c];
      }
      else if (y == 1.0)
      {
        v = u1[c];
      }
      e.Color[c] = (shade.Clamp ? ClampUnit(v) : v) * emissionFactor;
    }
  };
  for (int i = 0; i + 1 < n; ++i)
  {
    const double pieceLength = length * (x1 - x0) * (cuts[i + 1] - cuts[i]);
    if (!(pieceLength > 0.0))
    {
      continue;
    }
    SegmentEnd front, back;
    endAt(cuts[i], front);
    endAt(cuts[i + 1], back);
    CompositeBehind(accum, IntegrateSegment(pieceLength, front, back, settings.Emission, settings.Method));
    ++count;
    if (accum.A >= 1.0)
    {
      return;
    }
  }
}
}

bool IsIdentity(const ShadingTransform& shade)
{
  return !shade.Clamp && shade.Scale[0] == 1.0 && shade.Scale[1] == 1.0 &&
    shade.Scale[2] == 1.0 && shade.Offset[0] == 0.0 && shade.Offset[1] == 0.0 &&
    shade.Offset[2] == 0.0;
}

bool LightsAreDirectional(const VolumeShadingSettings& settings)
{
  for (int i = 0; settings.Lights && i < settings.LightCount; ++i)
  {
    if (settings.Lights[i].Positional)
    {
      return false;
    }
  }
  return true;
}

bool VolumeNormal(const double gradient[3], double floor, double normal[3])
{
  normal[0] = normal[1] = normal[2] = 0.0;
  if (std::isnan(gradient[0]) || std::isnan(gradient[1]) || std::isnan(gradient[2]))
  {
    return false;
  }
  // Divide by the largest component first (VectorLength's scaling, whose
  // arithmetic this repeats once for both the length and the normal): no
  // overflow, and no precision lost when |g| itself is subnormal (the unit
  // length is recomputed from the scaled components, not as |g| / m).
  const double m = std::max(std::fabs(gradient[0]), std::max(std::fabs(gradient[1]), std::fabs(gradient[2])));
  if (!(m > 0.0) || !std::isfinite(m))
  {
    return false; // zero or infinite
  }
  const double a = gradient[0] / m, b = gradient[1] / m, c = gradient[2] / m;
  const double unit = std::sqrt(a * a + b * b + c * c);
  const double length = m * unit; // VectorLength(gradient)
  if (!(length > floor) || !(length > 0.0) || !std::isfinite(length))
  {
    return false;
  }
  normal[0] = a / unit;
  normal[1] = b / unit;
  normal[2] = c / unit;
  return true;
}

namespace
{
/// The two compositions' materials: M = ka' + kd D (unit colour, no
/// specular), K = ks S (zero colour, specular only).
void CompositionMaterials(
  const VolumeShadingSettings& settings, ShadingMaterial& diffuse, ShadingMaterial& specular)
{
  diffuse = settings.Material;
  diffuse.Ambient = settings.Ambient == AmbientTerm::MaterialColor ? settings.Material.Ambient : 0.0;
  diffuse.Specular = 0.0;
  diffuse.ClampColor = false;
  specular = settings.Material;
  specular.Ambient = 0.0;
  specular.Diffuse = 0.0;
  specular.ClampColor = false;
}

/// The transform from one lighting pass's sums, composed twice.
void ComposeTransform(const VolumeShadingSettings& settings, const ShadingMaterial& diffuse,
  const ShadingMaterial& specular, const double lightDiffuse[3], const double lightSpecular[3],
  ShadingTransform& out)
{
  const double one[3] = { 1.0, 1.0, 1.0 }, zero[3] = { 0.0, 0.0, 0.0 };
  ComposePhong(one, diffuse, lightDiffuse, lightSpecular, out.Scale);
  ComposePhong(zero, specular, lightDiffuse, lightSpecular, out.Offset);
  if (settings.Ambient == AmbientTerm::LightAmbient)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.Offset[c] += settings.Material.Ambient * settings.AmbientLight[c];
    }
  }
  out.Clamp = settings.Material.ClampColor;
}
}

ShadingTransform ComputeShadingTransform(const VolumeShadingSettings& settings,
  const double gradient[3], const double point[3], const double toViewer[3])
{
  ShadingTransform out;
  if (!settings.Shade)
  {
    return out;
  }
  double normal[3];
  out.Lit = VolumeNormal(gradient, settings.GradientFloor, normal);
  ShadingMaterial diffuse, specular;
  CompositionMaterials(settings, diffuse, specular);
  // One lighting pass (the light vectors, half vectors and powers), composed twice.
  double lightDiffuse[3], lightSpecular[3];
  PhongLightSums(point, normal, toViewer, settings.Lights, settings.LightCount, settings.Material,
    lightDiffuse, lightSpecular);
  ComposeTransform(settings, diffuse, specular, lightDiffuse, lightSpecular, out);
  return out;
}

bool PrepareDirectionalShading(
  const VolumeShadingSettings& settings, const double toViewer[3], DirectionalShading& out)
{
  out.Settings = &settings;
  out.Count = 0;
  if (!settings.Shade)
  {
    return true; // the identity, whatever the lights
  }
  if (settings.Lights && settings.LightCount > DirectionalShading::MaxLights)
  {
    return false;
  }
  CompositionMaterials(settings, out.Diffuse, out.Specular);
  const double anywhere[3] = { 0.0, 0.0, 0.0 }; // directional lights: not read
  for (int i = 0; settings.Lights && i < settings.LightCount; ++i)
  {
    const ShadingLight& light = settings.Lights[i];
    if (light.Positional)
    {
      return false;
    }
    if (ComputeLightVectors(light, anywhere, anywhere, toViewer, out.Lights[out.Count]))
    {
      out.Colors[out.Count++] = light.Color;
    }
  }
  return true;
}

ShadingTransform ComputeShadingTransform(const DirectionalShading& prepared, const double gradient[3])
{
  ShadingTransform out;
  const VolumeShadingSettings& settings = *prepared.Settings;
  if (!settings.Shade)
  {
    return out;
  }
  double normal[3];
  out.Lit = VolumeNormal(gradient, settings.GradientFloor, normal);
  double lightDiffuse[3] = { 0.0, 0.0, 0.0 }, lightSpecular[3] = { 0.0, 0.0, 0.0 };
  for (int i = 0; i < prepared.Count; ++i)
  {
    AddPhongLight(prepared.Lights[i], normal, prepared.Colors[i], settings.Material, lightDiffuse,
      lightSpecular);
  }
  ComposeTransform(settings, prepared.Diffuse, prepared.Specular, lightDiffuse, lightSpecular, out);
  return out;
}

void ApplyShading(const ShadingTransform& shade, double color[3])
{
  for (int c = 0; c < 3; ++c)
  {
    const double v = shade.Scale[c] * color[c] + shade.Offset[c];
    color[c] = shade.Clamp ? ClampUnit(v) : v;
  }
}

RGBA IntegrateLinearScalarShaded(const TransferFunction& tf, double sFront, double sBack,
  double length, const ShadingTransform& shade, double gamma, const IntegrationSettings& settings,
  int* pieces)
{
  gamma = SanitizeGamma(gamma);
  if (IsIdentity(shade) && gamma == 1.0)
  {
    return IntegrateLinearScalar(tf, sFront, sBack, length, settings, pieces);
  }
  RGBA accum;
  int count = 0;
  if (pieces)
  {
    *pieces = 0;
  }
  if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(sFront) ||
    !std::isfinite(sBack) || tf.GetNumberOfNodes() == 0)
  {
    return accum;
  }
  const double emissionFactor =
    settings.Emission == EmissionModel::WilhelmsVanGelder ? tf.GetEmissionFactor() : 1.0;
  const std::vector<double>& nodes = tf.GetNodes();
  const int n = static_cast<int>(nodes.size());
  const double ds = sBack - sFront;
  const bool up = ds > 0.0;
  int k = up ? tf.FindIntervalUpward(sFront) : tf.FindIntervalDownward(sFront);
  // As IntegrateLinearScalar: fractions on halved values if ds overflows.
  const double scale = std::isfinite(ds) ? 1.0 : 0.5;
  const double invDs = ds != 0.0 ? 1.0 / (scale * sBack - scale * sFront) : 0.0;
  double xPrev = 0.0, sPrev = sFront;
  while (true)
  {
    double sNext = sBack, xNext = 1.0;
    bool last = true;
    if (up && k + 1 < n && nodes[k + 1] < sBack)
    {
      sNext = nodes[k + 1];
      last = false;
    }
    else if (!up && ds != 0.0 && k >= 0 && nodes[k] > sBack)
    {
      sNext = nodes[k];
      last = false;
    }
    if (!last)
    {
      xNext = (scale * sNext - scale * sFront) * invDs;
    }
    if (xNext > xPrev)
    {
      SegmentEnd f, b;
      tf.Evaluate(k, sPrev, false, f);
      tf.Evaluate(k, sNext, false, b);
      IntegratePiece(accum, count, f, b, xPrev, xNext, length, shade, gamma, emissionFactor, settings);
      if (accum.A >= 1.0)
      {
        break;
      }
    }
    if (last)
    {
      break;
    }
    xPrev = xNext;
    sPrev = sNext;
    k += up ? 1 : -1;
  }
  if (pieces)
  {
    *pieces = count;
  }
  return accum;
}
}
