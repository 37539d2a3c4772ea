// The control-net tests of the curved face search: see hovCurvedFaceNets.h.
#include "hovCurvedFaceNets.h"

#include <algorithm> // std::min, std::max
#include <cmath>     // std::abs, std::sqrt

namespace hov
{
namespace detail
{
Interval Mul(const Interval& a, const Interval& b)
{
  const double p[4] = { a.Lo * b.Lo, a.Lo * b.Hi, a.Hi * b.Lo, a.Hi * b.Hi };
  return { std::min(std::min(p[0], p[1]), std::min(p[2], p[3])),
    std::max(std::max(p[0], p[1]), std::max(p[2], p[3])) };
}

/// Split a (du+1) x (dv+1) net (row a along u, nv = dv + 1 per row) at the
/// middle of u (@p alongU) or v into @p left and @p right (one de Casteljau
/// subdivision at 1/2 per line: averages only).
void SplitStrided(const double* net, double* left, double* right, int du, int dv, int nv, bool alongU)
{
  const int lines = alongU ? nv : du + 1, degree = alongU ? du : dv;
  const int stride = alongU ? nv : 1, step = alongU ? 1 : nv;
  double w[MaxFaceDegree + 1];
  for (int l = 0; l < lines; ++l)
  {
    const int base = l * step;
    for (int i = 0; i <= degree; ++i)
    {
      w[i] = net[base + i * stride];
    }
    // Stage r: left gets w[0], right gets w[degree - r] (before the averaging).
    for (int r = 0; r <= degree; ++r)
    {
      left[base + r * stride] = w[0];
      right[base + (degree - r) * stride] = w[degree - r];
      for (int i = 0; i < degree - r; ++i)
      {
        w[i] = 0.5 * (w[i] + w[i + 1]);
      }
    }
  }
}

/**
 * The Newton start in a sub-patch, (a, b) in [0, 1]^2 of it: the zero of the
 * bilinear interpolant of h at its corners (the corner control points are h's
 * values there), by a few Newton steps on that interpolant from the centre;
 * the centre if they do not converge inside. Only the start: the crossing is
 * still Newton's on the face's net, under the same stopping rules, evaluated
 * on the exact map once accepted (FaceProblem::Newton, Crossing).
 */
void BilinearStart(const double* const net[2], int du, int nv, int n, double& a, double& b)
{
  double A[2], B[2], C[2], D[2];
  for (int c = 0; c < 2; ++c)
  {
    const double h00 = net[c][0], h01 = net[c][nv - 1], h10 = net[c][du * nv],
                 h11 = net[c][n - 1];
    A[c] = h00;
    B[c] = h10 - h00;
    C[c] = h01 - h00;
    D[c] = h11 - h10 - h01 + h00;
  }
  double x = 0.5, y = 0.5;
  for (int iter = 0; iter < 8; ++iter)
  {
    const double f0 = A[0] + B[0] * x + C[0] * y + D[0] * x * y;
    const double f1 = A[1] + B[1] * x + C[1] * y + D[1] * x * y;
    const double j00 = B[0] + D[0] * y, j01 = C[0] + D[0] * x;
    const double j10 = B[1] + D[1] * y, j11 = C[1] + D[1] * x;
    const double det = j00 * j11 - j01 * j10;
    if (!(std::abs(det) > 0.0))
    {
      return;
    }
    const double dx = -(j11 * f0 - j01 * f1) / det, dy = -(-j10 * f0 + j00 * f1) / det;
    x += dx;
    y += dy;
    if (!(x >= -0.25 && x <= 1.25 && y >= -0.25 && y <= 1.25))
    {
      return; // not inside: the centre
    }
    if (std::max(std::abs(dx), std::abs(dy)) <= 1e-6)
    {
      break;
    }
  }
  a = std::min(1.0, std::max(0.0, x));
  b = std::min(1.0, std::max(0.0, y));
}

/// True if every v[k], k < n, is > @p margin, or every one is < -@p margin.
bool OneSide(const double* v, int n, double margin)
{
  if (v[0] > margin)
  {
    for (int k = 1; k < n; ++k)
    {
      if (!(v[k] > margin))
      {
        return false;
      }
    }
    return true;
  }
  if (v[0] < -margin)
  {
    for (int k = 1; k < n; ++k)
    {
      if (!(v[k] < -margin))
      {
        return false;
      }
    }
    return true;
  }
  return false;
}

namespace
{
/// All points beyond @p margin along (wx, wy) (not normalised) once oriented
/// so that the first corner lies on its positive side.
bool SeparatedAlong(const double* const net[2], int n, double wx, double wy, double cx, double cy,
  double margin)
{
  if (wx * cx + wy * cy < 0.0)
  {
    wx = -wx;
    wy = -wy;
  }
  const double limit = margin * std::sqrt(wx * wx + wy * wy); // w = 0: nothing passes
  for (int k = 0; k < n; ++k)
  {
    if (!(wx * net[0][k] + wy * net[1][k] > limit))
    {
      return false;
    }
  }
  return true;
}
}

bool SeparatedByCorners(const double* const net[2], int n, const int* corners, int count, double margin)
{
  double mx = 0.0, my = 0.0;
  for (int e = 0; e < count; ++e)
  {
    const int a = corners[e], b = corners[(e + 1) % count];
    const double ax = net[0][a], ay = net[1][a];
    mx += ax;
    my += ay;
    // The edge's normal, oriented away from the origin at its first corner.
    if (SeparatedAlong(net, n, net[1][b] - ay, ax - net[0][b], ax, ay, margin))
    {
      return true;
    }
  }
  return SeparatedAlong(net, n, mx, my, mx, my, margin);
}

/// The range of @p v[0 .. n - 1].
Interval RangeOf(const double* v, int n)
{
  double lo = v[0], hi = v[0];
  for (int k = 1; k < n; ++k)
  {
    lo = std::min(lo, v[k]);
    hi = std::max(hi, v[k]);
  }
  return { lo, hi };
}

/**
 * The extreme vectors of the cone of the 2D vectors (x[k], y[k]), k < n: the
 * most clockwise (@p lo) and most counter-clockwise (@p hi) about their sum.
 * False if some vector is not strictly within 90 degrees of the sum (the
 * angles relative to it are then not ordered by cross / dot).
 */
bool ConeOf(const double* x, const double* y, int n, double lo[2], double hi[2])
{
  double sx = 0.0, sy = 0.0;
  for (int k = 0; k < n; ++k)
  {
    sx += x[k];
    sy += y[k];
  }
  double tLo = 0.0, tHi = 0.0;
  for (int k = 0; k < n; ++k)
  {
    const double dot = sx * x[k] + sy * y[k];
    if (!(dot > 0.0))
    {
      return false;
    }
    const double t = (sx * y[k] - sy * x[k]) / dot; // tan of the angle from the sum
    if (k == 0 || t < tLo)
    {
      tLo = t;
      lo[0] = x[k];
      lo[1] = y[k];
    }
    if (k == 0 || t > tHi)
    {
      tHi = t;
      hi[0] = x[k];
      hi[1] = y[k];
    }
  }
  return true;
}

/**
 * True if det(u, v) has one strict sign for every u in the cone of the
 * vectors (ux, uy) and v in the cone of (vx, vy): det is bilinear in the
 * cones' coefficients, so the four pairs of extreme vectors decide (each
 * beyond 1e-12 of |u| |v|: rounding).
 */
bool ConesSeparated(
  const double* ux, const double* uy, int nu, const double* vx, const double* vy, int nv)
{
  double u[2][2], v[2][2];
  if (!ConeOf(ux, uy, nu, u[0], u[1]) || !ConeOf(vx, vy, nv, v[0], v[1]))
  {
    return false;
  }
  int positive = 0, negative = 0;
  for (const auto& a : u)
  {
    for (const auto& b : v)
    {
      const double det = a[0] * b[1] - a[1] * b[0];
      const double tol = 1e-12 * std::sqrt((a[0] * a[0] + a[1] * a[1]) * (b[0] * b[0] + b[1] * b[1]));
      positive += det > tol ? 1 : 0;
      negative += det < -tol ? 1 : 0;
    }
  }
  return positive == 4 || negative == 4;
}
}
}
