#include "hovProjectionColor.h"

#include <algorithm> // std::min, std::max
#include <cmath>     // std::exp, std::expm1, std::log, std::floor

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
  const double tauAvg = 0.5 * (front.Tau + back.Tau);
  const double depth = length * tauAvg;
  out.Alpha = -std::expm1(-depth);
  const bool wvg = emission == EmissionModel::WilhelmsVanGelder;
  // Wilhelms-Van Gelder: the radiance C becomes the effective glow C / (L phi(D)).
  const double glowScale = length * GlowFactor(depth);
  for (int c = 0; c < 3; ++c) // M0, M1, and the fallbacks of M2 and M3
  {
    out.Color[c] = 0.5 * (front.Color[c] + back.Color[c]);
  }
  double beta = 0.5, vFront = 0.0, vBack = 0.0;
  if (method == ProjectionColorMethod::TableColor &&
    table.Lookup(front.Tau * length, back.Tau * length, beta, vFront, vBack))
  {
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
    const RGBA c = IntegrateSegment(length, front, back, emission, SegmentMethod::Exact);
    // The thin-segment series keeps C and A relatively accurate, so the
    // ratios are accurate for any positive denominator; at zero the limit is
    // the average.
    const double denominator = wvg ? glowScale : c.A;
    if (denominator > 0.0)
    {
      out.Color[0] = c.R / denominator;
      out.Color[1] = c.G / denominator;
      out.Color[2] = c.B / denominator;
    }
  }
  return out;
}

std::vector<float> OpacityTexture::Texels()
{
  constexpr int n = Size;
  constexpr double step = (LogMax - LogMin) / (n - 1);
  std::vector<float> texels(static_cast<size_t>(n) * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double d = std::exp(LogMin + i * step + LogMin + j * step);
      texels[i + static_cast<size_t>(n) * j] = static_cast<float>(-std::expm1(-d));
    }
  }
  return texels;
}

double OpacityFromTexture(
  const std::vector<float>& texels, double length, double tau, double lengthScale)
{
  constexpr int n = OpacityTexture::Size;
  constexpr double lo = OpacityTexture::LogMin, hi = OpacityTexture::LogMax;
  constexpr double step = (hi - lo) / (n - 1);
  if (!(length > 0.0 && tau > 0.0 && lengthScale > 0.0))
  {
    return 0.0;
  }
  // X + Y = ln(L / scale) + ln(tau scale) = ln(L tau): the scale cancels.
  const double depth = length * tau;
  const double sum = std::log(depth);
  if (sum <= 2.0 * lo)
  {
    return depth; // 1 - e^-d = d to 1e-14 relative here (also 0 on underflow)
  }
  if (sum >= 2.0 * hi)
  {
    return 1.0;
  }
  // M depends on X + Y only: take Y on the texel row nearest sum/2 and
  // X = sum - Y (then X is in [lo, hi]); interpolate linearly along the row.
  const int j = std::min(std::max(static_cast<int>(std::floor((0.5 * sum - lo) / step + 0.5)), 0), n - 1);
  const double fx = std::min(std::max((sum - (lo + j * step) - lo) / step, 0.0), double(n - 1));
  const int i = std::min(static_cast<int>(fx), n - 2);
  const double t = fx - i;
  const size_t k = i + static_cast<size_t>(n) * j;
  return texels[k] * (1.0 - t) + texels[k + 1] * t;
}
}
