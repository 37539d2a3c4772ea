#include "hovCellShapes.h"

#include <algorithm> // std::max
#include <cmath>     // fabs, isfinite

// The geometry half of hovCellShapes.h: the corner map, its inverse and the
// parametric domain tests (the shape functions are in hovCellShapes.cxx).
namespace hov
{
namespace
{
double MaxAbs3(const double v[3])
{
  return std::max(std::fabs(v[0]), std::max(std::fabs(v[1]), std::fabs(v[2])));
}

/// Newton from one start; true if the step fell below the tolerance.
bool NewtonFrom(CellShape shape, const double* points, const double x[3], double pc[3],
  const GeometryInversionSettings& settings)
{
  for (int it = 0; it < settings.MaxIterations; ++it)
  {
    double f[3], j[9];
    EvaluateGeometry(shape, points, pc, f, j);
    for (int k = 0; k < 3; ++k)
    {
      f[k] -= x[k];
    }
    // Solve J step = f by Cramer's rule on the columns of J.
    const double c0[3] = { j[0], j[3], j[6] }, c1[3] = { j[1], j[4], j[7] },
                 c2[3] = { j[2], j[5], j[8] };
    auto det = [](const double* a, const double* b, const double* c) {
      return a[0] * (b[1] * c[2] - b[2] * c[1]) - b[0] * (a[1] * c[2] - a[2] * c[1]) +
        c[0] * (a[1] * b[2] - a[2] * b[1]);
    };
    const double d = det(c0, c1, c2);
    if (!(std::fabs(d) > 0.0) || !std::isfinite(d))
    {
      return false;
    }
    double step[3] = { det(f, c1, c2) / d, det(c0, f, c2) / d, det(c0, c1, f) / d };
    const double len = MaxAbs3(step);
    if (!std::isfinite(len))
    {
      return false;
    }
    const double damp = len > 1.0 ? 1.0 / len : 1.0; // far away: limit the step
    for (int k = 0; k < 3; ++k)
    {
      pc[k] -= damp * step[k];
    }
    if (len <= settings.StepTolerance)
    {
      return true;
    }
  }
  return false;
}
}

double ParametricDistanceOutside(CellShape shape, const double pc[3])
{
  const double r = pc[0], s = pc[1], t = pc[2];
  switch (GeometryShape(shape))
  {
    case CellShape::Tetra:
      return std::max(std::max(-r, -s), std::max(-t, r + s + t - 1.0));
    case CellShape::Wedge:
      return std::max(std::max(std::max(-r, -s), r + s - 1.0), std::max(-t, t - 1.0));
    default: // hexahedron, voxel, pyramid: the unit cube
      return std::max(std::max(std::max(-r, r - 1.0), std::max(-s, s - 1.0)),
        std::max(-t, t - 1.0));
  }
}

void EvaluateGeometry(
  CellShape shape, const double* points, const double pc[3], double x[3], double* jacobian)
{
  const CellShape g = GeometryShape(shape);
  const int n = CellNodeCount(g);
  double w[8], d[24];
  CellShapeFunctions(g, pc, w);
  if (jacobian)
  {
    CellShapeDerivatives(g, pc, d);
    for (int k = 0; k < 9; ++k)
    {
      jacobian[k] = 0.0;
    }
  }
  x[0] = x[1] = x[2] = 0.0;
  for (int i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      x[k] += w[i] * points[3 * i + k];
      if (jacobian)
      {
        for (int j = 0; j < 3; ++j)
        {
          jacobian[3 * k + j] += d[j * n + i] * points[3 * i + k];
        }
      }
    }
  }
}

bool InvertGeometry(CellShape shape, const double* points, const double x[3], double pc[3],
  const GeometryInversionSettings& settings)
{
  if (!std::isfinite(x[0] + x[1] + x[2]))
  {
    return false;
  }
  double guess[3] = { pc[0], pc[1], pc[2] };
  if (std::isfinite(guess[0] + guess[1] + guess[2]) &&
    NewtonFrom(shape, points, x, guess, settings))
  {
    pc[0] = guess[0], pc[1] = guess[1], pc[2] = guess[2];
    return true;
  }
  double best[3];
  CellParametricCenter(shape, best);
  for (int start = -1; start < 8; ++start)
  {
    double q[3];
    if (start < 0)
    {
      CellParametricCenter(shape, q);
    }
    else
    {
      q[0] = (start & 1) ? 0.75 : 0.25;
      q[1] = (start & 2) ? 0.75 : 0.25;
      q[2] = (start & 4) ? 0.75 : 0.25;
      if (GeometryShape(shape) == CellShape::Tetra || GeometryShape(shape) == CellShape::Wedge)
      {
        q[0] *= 0.5, q[1] *= 0.5; // into the triangle r + s <= 1
        q[2] *= GeometryShape(shape) == CellShape::Tetra ? 0.5 : 1.0;
      }
    }
    if (NewtonFrom(shape, points, x, q, settings))
    {
      pc[0] = q[0], pc[1] = q[1], pc[2] = q[2];
      return true;
    }
    if (std::isfinite(q[0] + q[1] + q[2]))
    {
      best[0] = q[0], best[1] = q[1], best[2] = q[2];
    }
  }
  pc[0] = best[0], pc[1] = best[1], pc[2] = best[2];
  return false;
}
}
