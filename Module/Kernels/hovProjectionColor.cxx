#include "hovProjectionColor.h"

#include "hovOpacityRefinement.h" // OpaqueClamp, GPUExtinction
#include "hovRayIntegrator.h"     // IntegrateLinearScalar (M3 in GPU-compatible semantics)

#include <algorithm> // std::min, std::max
#include <cmath>     // std::expm1, std::sqrt, std::log1p
#include <limits>    // infinity

namespace hov
{
namespace
{
constexpr double TableStep = SegmentColorTable::MaxDepth / (SegmentColorTable::Size - 1);

/// Bilinear interpolation of a Size x Size node table at fractional (x, y).
double Bilinear(const std::vector<double>& t, int i, int j, double fx, double fy)
{
  constexpr int n = SegmentColorTable::Size;
  const int i1 = std::min(i + 1, n - 1), j1 = std::min(j + 1, n - 1);
  const double a = t[i + n * j] * (1.0 - fx) + t[i1 + n * j] * fx;
  const double b = t[i + n * j1] * (1.0 - fx) + t[i1 + n * j1] * fx;
  return a * (1.0 - fy) + b * fy;
}

/// phi(D) = (1 - e^-D)/D (-> 1 as D -> 0): a constant glow g over length L
/// and optical depth D gives the radiance L g phi(D).
double GlowFactor(double depth)
{
  // Below 1e-8 the ratio is 1 - D/2 + ... = 1 to double precision.
  return depth > 1e-8 ? -std::expm1(-depth) / depth : 1.0;
}

/**
 * Method M3 from the segment's exact integral @p c (optical depth @p depth):
 * chromaticity C / A (Williams-Max) or effective glow C / (L phi(D))
 * (Wilhelms-Van Gelder). The thin-segment series keeps C and A relatively
 * accurate, so the ratios are accurate for any positive denominator; at zero
 * @p out keeps its colour (the average, the limit).
 */
void ExactColor(const RGBA& c, EmissionModel emission, double length, double depth,
  ProjectionVertexColor& out)
{
  out.Alpha = c.A;
  const double denominator =
    emission == EmissionModel::WilhelmsVanGelder ? length * GlowFactor(depth) : c.A;
  if (denominator > 0.0 && std::isfinite(denominator))
  {
    out.Color[0] = c.R / denominator;
    out.Color[1] = c.G / denominator;
    out.Color[2] = c.B / denominator;
  }
}
}

SegmentColorTable::SegmentColorTable()
{
  constexpr int n = Size;
  this->BackFraction.assign(n * n, 0.5);
  this->VFront.assign(n * n, 0.5);
  this->VBack.assign(n * n, 0.5);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const SegmentWeights w = ExactSegmentWeights(i * TableStep, j * TableStep, true);
      // At zero depth the weights vanish; their ratio tends to 1/2.
      this->BackFraction[i + n * j] = w.Alpha > 0.0 ? w.WBack / w.Alpha : 0.5;
      this->VFront[i + n * j] = w.VFront;
      this->VBack[i + n * j] = w.VBack;
    }
  }
}

bool SegmentColorTable::Lookup(
  double depthFront, double depthBack, double& backFraction, double& vFront, double& vBack) const
{
  if (!(depthFront >= 0.0 && depthFront <= MaxDepth && depthBack >= 0.0 && depthBack <= MaxDepth))
  {
    return false; // NaN fails too
  }
  const double x = depthFront / TableStep, y = depthBack / TableStep;
  const int i = std::min(static_cast<int>(x), Size - 1), j = std::min(static_cast<int>(y), Size - 1);
  const double fx = x - i, fy = y - j;
  backFraction = Bilinear(this->BackFraction, i, j, fx, fy);
  vFront = Bilinear(this->VFront, i, j, fx, fy);
  vBack = Bilinear(this->VBack, i, j, fx, fy);
  return true;
}

ProjectionVertexColor ComputeProjectionVertex(ProjectionColorMethod method, EmissionModel emission,
  double length, const SegmentEnd& front, const SegmentEnd& back, const SegmentColorTable& table)
{
  ProjectionVertexColor out;
  length = std::max(length, 0.0);
  const double depth = length * 0.5 * (front.Tau + back.Tau);
  const bool wvg = emission == EmissionModel::WilhelmsVanGelder;
  for (int c = 0; c < 3; ++c) // M0, M1, and the fallbacks of M2 and M3
  {
    out.Color[c] = 0.5 * (front.Color[c] + back.Color[c]);
  }
  if (method == ProjectionColorMethod::InterpolatedOpacity)
  {
    out.Alpha = -std::expm1(-depth);
  }
  double beta = 0.5, vFront = 0.0, vBack = 0.0;
  if (method == ProjectionColorMethod::TableColor &&
    table.Lookup(front.Tau * length, back.Tau * length, beta, vFront, vBack))
  {
    // Wilhelms-Van Gelder: the radiance C becomes the effective glow C / (L phi(D)).
    const double glowScale = wvg ? length * GlowFactor(depth) : 0.0;
    if (wvg && glowScale > 0.0)
    {
      for (int c = 0; c < 3; ++c)
      {
        out.Color[c] = length * (vFront * front.Color[c] + vBack * back.Color[c]) / glowScale;
      }
    }
    else if (!wvg)
    {
      for (int c = 0; c < 3; ++c)
      {
        out.Color[c] = (1.0 - beta) * front.Color[c] + beta * back.Color[c];
      }
    }
  }
  else if (method == ProjectionColorMethod::ExactColor)
  {
    ExactColor(IntegrateSegment(length, front, back, emission, SegmentMethod::Exact), emission,
      length, depth, out);
  }
  return out;
}

ProjectionVertexColor ComputeProjectionVertexGPU(ProjectionColorMethod method,
  EmissionModel emission, double length, const SegmentEnd& front, const SegmentEnd& back,
  double sFront, double sBack, const TransferFunction& extinction, double inverseUnit,
  const SegmentColorTable& table)
{
  // The same colours, the exact extinctions of the ends (M2's table reads them).
  SegmentEnd f = front, b = back;
  f.Tau = GPUExtinction(front.Tau, 1.0 - front.Tau, inverseUnit);
  b.Tau = GPUExtinction(back.Tau, 1.0 - back.Tau, inverseUnit);
  const bool exact = method == ProjectionColorMethod::ExactColor;
  // M3 replaces the colour below: start from M1 (its fallback) rather than
  // integrating the linearised segment for nothing.
  ProjectionVertexColor out = ComputeProjectionVertex(
    exact ? ProjectionColorMethod::AverageColor : method, emission, length, f, b, table);
  const double depth =
    std::max(length, 0.0) * GPUAverageExtinction(front.Tau, back.Tau) * inverseUnit;
  if (method == ProjectionColorMethod::InterpolatedOpacity)
  {
    out.Alpha = -std::expm1(-depth);
  }
  else if (exact)
  {
    IntegrationSettings settings;
    settings.Emission = emission;
    ExactColor(IntegrateLinearScalar(extinction, sFront, sBack, length, settings), emission, length,
      depth, out);
  }
  return out;
}

double GPUAverageExtinction(double aFront, double aBack)
{
  const double lo = std::min(aFront, aBack), hi = std::max(aFront, aBack);
  if (!(lo < 1.0))
  {
    return std::numeric_limits<double>::infinity(); // a = 1 all along: opaque medium
  }
  const double big = std::max(1.0 - lo, OpaqueClamp);
  const double small = std::max(1.0 - hi, OpaqueClamp);
  const double x = std::min(std::max(hi - lo, 0.0) / big, 1.0);
  double m;
  if (x < 0.1)
  {
    // sum_{n>=1} x^n / (n (n+1)) to n = 9: the tail is below 1e-12 relative.
    m = 0.0;
    for (int n = 9; n >= 1; --n)
    {
      m = x * (1.0 / (n * (n + 1.0)) + m);
    }
  }
  else
  {
    const double ratio = small / big; // 1 - x, without cancellation
    m = 1.0 + ratio * std::log(ratio) / x;
  }
  const double lnBig = 1.0 - lo > OpaqueClamp ? std::log1p(-std::max(lo, 0.0)) : std::log(OpaqueClamp);
  return m - lnBig;
}

std::vector<float> OpacityTexture::Texels()
{
  constexpr int n = Size;
  constexpr double step = UMax / (n - 1);
  std::vector<float> texels(static_cast<size_t>(n) * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      texels[i + static_cast<size_t>(n) * j] = static_cast<float>(-std::expm1(-(i * step) * (j * step)));
    }
  }
  return texels;
}

double OpacityFromTexture(
  const std::vector<float>& texels, double length, double tau, double lengthScale)
{
  constexpr int n = OpacityTexture::Size;
  if (!(length > 0.0 && tau > 0.0 && lengthScale > 0.0))
  {
    return 0.0;
  }
  // (u, v) = (L / c, tau c) with c = sqrt(L / tau): u = v = sqrt(L tau) (exact: M depends on u v).
  const double u = std::sqrt(length * tau);
  if (!(u < OpacityTexture::UMax))
  {
    return 1.0; // 1 - exp(-UMax^2) = 1 - 2.3e-16
  }
  // Bilinear between the texel centres around (u, u), as the texture unit filters.
  const double f = u / OpacityTexture::UMax * (n - 1);
  const int i = std::min(static_cast<int>(f), n - 2);
  const double t = f - i;
  const size_t k = i + static_cast<size_t>(n) * i;
  const double a = texels[k] * (1.0 - t) + texels[k + 1] * t;
  const double b = texels[k + n] * (1.0 - t) + texels[k + n + 1] * t;
  return a * (1.0 - t) + b * t;
}
}
