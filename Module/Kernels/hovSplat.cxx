#include "hovSplat.h"

#include <cmath> // abs, floor, expm1, isfinite

namespace hov
{
namespace
{
// Below this optical depth (1 - e^-D)/D is taken from its series
// 1 - D/2 + D^2/6 (error < D^3/24 < 1e-19 relative), avoiding 0/0 at D = 0.
constexpr double SeriesDepth = 1e-6;

// Pixel coordinates beyond this are off every image (VTK windows are < 2^16
// pixels wide) and would overflow an int; they get zero weights.
constexpr double FarPixel = 1e9;

/// (1 - e^-D) / D for 0 <= D < SeriesDepth.
double SlabFactor(double depth)
{
  return 1.0 - depth * (0.5 - depth / 6.0);
}
}

int QuadraticBSplineWeights(double x, double w[3])
{
  if (!std::isfinite(x))
  {
    w[0] = w[1] = w[2] = 0.0;
    return 0;
  }
  if (std::abs(x) > FarPixel)
  {
    // Far off any image: no weight, and c stays a valid int (c +- 2 too).
    w[0] = w[1] = w[2] = 0.0;
    return x > 0.0 ? static_cast<int>(FarPixel) : -static_cast<int>(FarPixel);
  }
  // c = floor(x + 1/2) without rounding x + 1/2 (which sends x just below a
  // half-integer up): x - floor(x) is exact, and so is f - 1.
  double c = std::floor(x);
  double f = x - c;
  if (f >= 0.5)
  {
    c += 1.0;
    f -= 1.0;
  }
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
  if (!std::isfinite(length))
  {
    return out; // V / a overflows: not a sub-pixel cell
  }
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      const double l = w.W[j][i] * length;
      // D = tau l; an infinite tau with l = 0 is no depth (the pixel gets no weight).
      const double depth = l > 0.0 ? cell.Tau * l : 0.0;
      RGBA& p = out.Pixel[j][i];
      p.A = -std::expm1(-depth);
      // WVG: l (1 - e^-D)/D, written as (1 - e^-D)/tau beyond the series
      // range so that an infinite tau gives 0 (no emission escapes).
      const double scale = emission == EmissionModel::WilliamsMax
        ? p.A
        : (depth < SeriesDepth ? l * SlabFactor(depth) : p.A / cell.Tau);
      p.R = scale * cell.Color[0];
      p.G = scale * cell.Color[1];
      p.B = scale * cell.Color[2];
    }
  }
  return out;
}
}
