#include "hovSplat.h"

#include <cmath> // floor, expm1, isfinite

namespace hov
{
namespace
{
// Below this optical depth (1 - e^-D)/D is taken from its series
// 1 - D/2 + D^2/6 (error < D^3/24 < 1e-19 relative), avoiding 0/0 at D = 0.
constexpr double SeriesDepth = 1e-6;

/// (1 - e^-D) / D for D >= 0, 0 for D = +inf.
double SlabFactor(double depth)
{
  if (depth < SeriesDepth)
  {
    return 1.0 - depth * (0.5 - depth / 6.0);
  }
  return std::isfinite(depth) ? -std::expm1(-depth) / depth : 0.0;
}
}

int QuadraticBSplineWeights(double x, double w[3])
{
  if (!std::isfinite(x))
  {
    w[0] = w[1] = w[2] = 0.0;
    return 0;
  }
  const double c = std::floor(x + 0.5);
  const double f = x - c; // in [-1/2, 1/2]
  const double a = 0.5 - f, b = 0.5 + f;
  w[0] = 0.5 * a * a;
  w[1] = 0.75 - f * f;
  w[2] = 0.5 * b * b;
  return static_cast<int>(c);
}

SplatWeights BiquadraticSplatWeights(double x, double y)
{
  SplatWeights s;
  double wx[3], wy[3];
  s.X0 = QuadraticBSplineWeights(x, wx) - 1;
  s.Y0 = QuadraticBSplineWeights(y, wy) - 1;
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      s.W[j][i] = wx[i] * wy[j];
    }
  }
  return s;
}

double OrthographicPixelArea(double pixelWidthWorld, double pixelHeightWorld)
{
  return pixelWidthWorld * pixelHeightWorld;
}

double PerspectivePixelArea(double depth, double w1, double h1, double cosAngle)
{
  return (depth * w1) * (depth * h1) * cosAngle;
}

SplatFootprint SplatCellContribution(
  const SplatCell& cell, double pixelArea, double x, double y, EmissionModel emission)
{
  SplatFootprint out;
  const bool valid = cell.Volume >= 0.0 && std::isfinite(cell.Volume) && cell.Tau >= 0.0 &&
    !std::isnan(cell.Tau) && pixelArea > 0.0 && std::isfinite(pixelArea) && std::isfinite(x) &&
    std::isfinite(y);
  if (!valid)
  {
    return out;
  }
  const SplatWeights w = BiquadraticSplatWeights(x, y);
  out.X0 = w.X0;
  out.Y0 = w.Y0;
  const double length = cell.Volume / pixelArea; // integrated path length, pixel units
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      const double l = w.W[j][i] * length;
      // D = tau l; an infinite tau with l = 0 is no depth (the pixel gets no weight).
      const double depth = l > 0.0 ? cell.Tau * l : 0.0;
      RGBA& p = out.Pixel[j][i];
      p.A = -std::expm1(-depth);
      const double scale =
        emission == EmissionModel::WilliamsMax ? p.A : l * SlabFactor(depth);
      p.R = scale * cell.Color[0];
      p.G = scale * cell.Color[1];
      p.B = scale * cell.Color[2];
    }
  }
  return out;
}
}
