#include "hovCellRestriction.h"

#include "hovChebyshevFit.h" // the non-affine path

#include <algorithm> // std::max, std::min
#include <cmath>     // fabs, cos, isfinite
#include <limits>    // epsilon

namespace hov
{
namespace
{
constexpr double Eps = std::numeric_limits<double>::epsilon();
using detail::ChebN;
/// Newton's parametric tolerance (1e-14) times gradients of a few times the
/// range: the sample error floor, relative to the scalar range.
constexpr double NewtonFloor = 1e-13;
/// Bisection depth limit (the piece count limit usually acts first).
constexpr int MaxDepth = 24;


void MatVec(const double m[9], const double v[3], double r[3])
{
  for (int i = 0; i < 3; ++i)
  {
    r[i] = m[3 * i] * v[0] + m[3 * i + 1] * v[1] + m[3 * i + 2] * v[2];
  }
}

/// Exact path: one piece by expansion of the shape functions along the line.
bool RestrictAffine(CellShape shape, const double* points, const double* scalars,
  const double o[3], const double d[3], double t0, double t1, RestrictedPiece& piece)
{
  double pcCenter[3], xc[3], jac[9], inv[9];
  CellParametricCenter(shape, pcCenter);
  EvaluateGeometry(shape, points, pcCenter, xc, jac);
  if (!InvertMatrix3(jac, inv))
  {
    return false;
  }
  // Base at corner 0 (its pcoords are exact): pc(T0) = pc0 + A (o + T0 d - x0).
  double pc0[3], rel[3], pcStart[3], step[3];
  CellNodeParametricCoords(shape, 0, pc0);
  for (int k = 0; k < 3; ++k)
  {
    rel[k] = (o[k] - points[k]) + t0 * d[k];
  }
  MatVec(inv, rel, pcStart);
  MatVec(inv, d, step);
  for (int k = 0; k < 3; ++k)
  {
    pcStart[k] += pc0[k];
  }
  Polynomial w[MaxCellNodes];
  CellShapeFunctionsAlongLine(shape, pcStart, step, w);
  piece.S = Polynomial();
  piece.S.Degree = Polynomial::MaxDegree;
  double sumAbs = 0.0;
  for (int i = 0, n = CellNodeCount(shape); i < n; ++i)
  {
    for (int k = 0; k <= w[i].Degree; ++k)
    {
      piece.S.C[k] += scalars[i] * w[i].C[k];
    }
    sumAbs += std::fabs(scalars[i]);
  }
  piece.S.Degree = EffectiveDegree(piece.S);
  piece.T0 = t0;
  piece.T1 = t1;
  piece.ErrorBound = 32.0 * Eps * sumAbs;
  return true;
}

struct FitContext
{
  CellShape Shape;
  const double* Points;
  const double* Scalars;
  const double* O;
  const double* D;
  double TolAbs;
  double Floor;
  int MaxPieces;
  std::vector<RestrictedPiece>* Out;
  CellRestrictionStatus* Status;
  int* Intervals; ///< of the partition so far, pending halves included (<= MaxPieces)
};

/// The degree-ChebN interpolant's coefficients of s on [a, b].
void SampleChebyshev(const FitContext& ctx, double a, double b, double c[ChebN + 1])
{
  double t[ChebN + 1], f[ChebN + 1];
  detail::ChebyshevPoints(a, b, t);
  double pc[3];
  CellParametricCenter(ctx.Shape, pc);
  for (int j = 0; j <= ChebN; ++j)
  {
    const double x[3] = { ctx.O[0] + t[j] * ctx.D[0], ctx.O[1] + t[j] * ctx.D[1],
      ctx.O[2] + t[j] * ctx.D[2] };
    if (!InvertGeometry(ctx.Shape, ctx.Points, x, pc)) // warm start from the previous sample
    {
      ++ctx.Status->NewtonFailures;
    }
    f[j] = InterpolateCellScalar(ctx.Shape, ctx.Scalars, pc);
  }
  detail::ChebyshevCoefficients(f, c);
}

void Fit(const FitContext& ctx, double a, double b, int depth)
{
  double c[ChebN + 1];
  SampleChebyshev(ctx, a, b, c);
  double bound = 0.0;
  const int m = detail::TruncationDegree(c, ctx.Floor, ctx.TolAbs, bound);
  const bool canSplit = depth < MaxDepth && *ctx.Intervals + 1 <= ctx.MaxPieces &&
    0.5 * (a + b) > a && 0.5 * (a + b) < b;
  if (bound > ctx.TolAbs && canSplit)
  {
    ++*ctx.Intervals;
    const double mid = 0.5 * (a + b);
    Fit(ctx, a, mid, depth + 1);
    Fit(ctx, mid, b, depth + 1);
    return;
  }
  if (bound > ctx.TolAbs)
  {
    ctx.Status->Converged = false;
  }
  RestrictedPiece piece;
  piece.T0 = a;
  piece.T1 = b;
  piece.S = detail::ChebyshevToLocal(c, m, a, b);
  piece.ErrorBound = bound;
  ctx.Out->push_back(piece);
}
}

bool AffineFieldBasis(CellShape shape, double* basis)
{
  if (GeometryShape(shape) == CellShape::Pyramid)
  {
    return false;
  }
  const int n = CellNodeCount(shape);
  // Shape functions at pc = (a, b, c) / 2, a, b, c in {0, 1, 2}.
  double f[AffineFieldTerms][MaxCellNodes];
  for (int m = 0; m < AffineFieldTerms; ++m)
  {
    const double pc[3] = { 0.5 * (m / 9), 0.5 * ((m / 3) % 3), 0.5 * (m % 3) };
    CellShapeFunctions(shape, pc, f[m]);
  }
  // Values at x = 0, 1/2, 1 -> coefficients of 1, x, x^2, one axis at a time.
  const int stride[3] = { 9, 3, 1 };
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int m = 0; m < AffineFieldTerms; ++m)
    {
      if ((m / stride[axis]) % 3 != 0)
      {
        continue; // m is the first of a line along this axis
      }
      double* f0 = f[m];
      double* f1 = f[m + stride[axis]];
      double* f2 = f[m + 2 * stride[axis]];
      for (int i = 0; i < n; ++i)
      {
        const double v0 = f0[i], v1 = f1[i], v2 = f2[i];
        f1[i] = -3.0 * v0 + 4.0 * v1 - v2;
        f2[i] = 2.0 * v0 - 4.0 * v1 + 2.0 * v2;
      }
    }
  }
  for (int i = 0; i < n; ++i)
  {
    for (int m = 0; m < AffineFieldTerms; ++m)
    {
      // Structural zeros (terms absent from the shape) exactly 0.
      basis[AffineFieldTerms * i + m] = std::fabs(f[m][i]) < 1e-12 ? 0.0 : f[m][i];
    }
  }
  return true;
}

void AffineFieldCoefficients(
  const double* basis, int nodeCount, const double* scalars, double c[AffineFieldTerms])
{
  for (int m = 0; m < AffineFieldTerms; ++m)
  {
    c[m] = 0.0;
  }
  for (int i = 0; i < nodeCount; ++i)
  {
    const double* b = basis + AffineFieldTerms * i;
    for (int m = 0; m < AffineFieldTerms; ++m)
    {
      c[m] += scalars[i] * b[m];
    }
  }
}

namespace
{
/// True if every term of total degree > 2 is zero (tetrahedra, linear wedges).
bool TotalDegreeAtMost2(const double c[AffineFieldTerms])
{
  // The 17 indices 9 i + 3 j + k with i + j + k > 2.
  static constexpr int High[17] = { 5, 7, 8, 11, 13, 14, 15, 16, 17, 19, 20, 21, 22, 23, 24, 25, 26 };
  bool any = false;
  for (int m : High)
  {
    any = any || c[m] != 0.0;
  }
  return !any;
}

/// A field c0 + g.pc + (quadratic form) along pc = a + tau b, as [s, s', s''/2].
Polynomial RestrictQuadraticForm(const double c[AffineFieldTerms], const double a[3], const double b[3])
{
  const double cr = c[9], cs = c[3], ct = c[1];
  const double crr = c[18], css = c[6], ctt = c[2], crs = c[12], crt = c[10], cst = c[4];
  const double r = a[0], s = a[1], t = a[2], br = b[0], bs = b[1], bt = b[2];
  Polynomial p;
  p.C[0] = c[0] + cr * r + cs * s + ct * t +
    (r * (crr * r + crs * s + crt * t) + s * (css * s + cst * t) + ctt * t * t);
  p.C[1] = cr * br + cs * bs + ct * bt +
    (2.0 * (crr * r * br + css * s * bs + ctt * t * bt) + crs * (r * bs + s * br) +
      crt * (r * bt + t * br) + cst * (s * bt + t * bs));
  p.C[2] = br * (crr * br + crs * bs + crt * bt) + bs * (css * bs + cst * bt) + ctt * bt * bt;
  p.Degree = 2;
  p.Degree = EffectiveDegree(p);
  return p;
}
}

Polynomial RestrictAffineField(
  const double c[AffineFieldTerms], const double start[3], const double step[3])
{
  if (TotalDegreeAtMost2(c))
  {
    return RestrictQuadraticForm(c, start, step);
  }
  const double ar = start[0], br = step[0], as = start[1], bs = step[1], at = start[2],
               bt = step[2];
  double out[7] = {};
  int degree = 0;
  for (int i = 0; i < 3; ++i)
  {
    // R(tau) = sum_j s(tau)^j (c_ij0 + c_ij1 t(tau) + c_ij2 t(tau)^2), degree <= 4.
    double r[5] = {};
    int rDeg = -1;
    for (int j = 0; j < 3; ++j)
    {
      const double* cc = c + 9 * i + 3 * j;
      if (cc[0] == 0.0 && cc[1] == 0.0 && cc[2] == 0.0)
      {
        continue;
      }
      const double q[3] = { cc[0] + at * (cc[1] + cc[2] * at), bt * (cc[1] + 2.0 * cc[2] * at),
        cc[2] * bt * bt };
      const int qDeg = cc[2] != 0.0 ? 2 : (cc[1] != 0.0 ? 1 : 0);
      if (j == 0)
      {
        for (int k = 0; k <= qDeg; ++k)
        {
          r[k] += q[k];
        }
      }
      else if (j == 1)
      {
        for (int k = 0; k <= qDeg; ++k)
        {
          r[k] += as * q[k];
          r[k + 1] += bs * q[k];
        }
      }
      else
      {
        const double p0 = as * as, p1 = 2.0 * as * bs, p2 = bs * bs;
        for (int k = 0; k <= qDeg; ++k)
        {
          r[k] += p0 * q[k];
          r[k + 1] += p1 * q[k];
          r[k + 2] += p2 * q[k];
        }
      }
      rDeg = std::max(rDeg, qDeg + j);
    }
    if (rDeg < 0)
    {
      continue;
    }
    // out += r(tau)^i R(tau).
    if (i == 0)
    {
      for (int k = 0; k <= rDeg; ++k)
      {
        out[k] += r[k];
      }
    }
    else if (i == 1)
    {
      for (int k = 0; k <= rDeg; ++k)
      {
        out[k] += ar * r[k];
        out[k + 1] += br * r[k];
      }
    }
    else
    {
      const double p0 = ar * ar, p1 = 2.0 * ar * br, p2 = br * br;
      for (int k = 0; k <= rDeg; ++k)
      {
        out[k] += p0 * r[k];
        out[k + 1] += p1 * r[k];
        out[k + 2] += p2 * r[k];
      }
    }
    degree = std::max(degree, rDeg + i);
  }
  Polynomial s;
  for (int k = 0; k <= degree; ++k)
  {
    s.C[k] = out[k];
  }
  s.Degree = degree;
  s.Degree = EffectiveDegree(s);
  return s;
}

bool IsGeometryAffine(CellShape shape, const double* points, double relativeTolerance)
{
  if (GeometryShape(shape) == CellShape::Pyramid)
  {
    return false;
  }
  if (GeometryShape(shape) == CellShape::Tetra)
  {
    return true;
  }
  double pcCenter[3], xc[3], jac[9];
  CellParametricCenter(shape, pcCenter);
  EvaluateGeometry(shape, points, pcCenter, xc, jac);
  double extent = 0.0, deviation = 0.0;
  for (int i = 0, n = CellCornerCount(shape); i < n; ++i)
  {
    double pc[3], dpc[3], lin[3];
    CellNodeParametricCoords(shape, i, pc);
    for (int k = 0; k < 3; ++k)
    {
      dpc[k] = pc[k] - pcCenter[k];
    }
    MatVec(jac, dpc, lin);
    for (int k = 0; k < 3; ++k)
    {
      extent = std::max(extent, std::fabs(points[3 * i + k] - points[k]));
      deviation = std::max(deviation, std::fabs(points[3 * i + k] - (xc[k] + lin[k])));
    }
  }
  return deviation <= relativeTolerance * extent;
}

int RestrictCellScalar(CellShape shape, const double* points, const double* scalars,
  const double origin[3], const double direction[3], double t0, double t1,
  const CellRestrictionSettings& settings, std::vector<RestrictedPiece>& out,
  CellRestrictionStatus* status)
{
  out.clear();
  CellRestrictionStatus localStatus;
  CellRestrictionStatus& st = status ? *status : localStatus;
  st = CellRestrictionStatus();
  if (!(t0 <= t1) || !std::isfinite(t0) || !std::isfinite(t1))
  {
    st.Converged = false;
    return 0;
  }
  if (t1 == t0)
  {
    // Zero length: the constant s(t0) (no interval to fit on).
    const double x[3] = { origin[0] + t0 * direction[0], origin[1] + t0 * direction[1],
      origin[2] + t0 * direction[2] };
    double pc[3];
    CellParametricCenter(shape, pc);
    if (!InvertGeometry(shape, points, x, pc))
    {
      ++st.NewtonFailures;
    }
    RestrictedPiece piece;
    piece.T0 = piece.T1 = t0;
    piece.S.C[0] = InterpolateCellScalar(shape, scalars, pc);
    out.push_back(piece);
    return 1;
  }
  if (IsGeometryAffine(shape, points))
  {
    RestrictedPiece piece;
    if (RestrictAffine(shape, points, scalars, origin, direction, t0, t1, piece))
    {
      st.Affine = true;
      out.push_back(piece);
      return 1;
    }
  }
  double lo = scalars[0], hi = scalars[0], maxAbs = 0.0;
  for (int i = 0, n = CellNodeCount(shape); i < n; ++i)
  {
    lo = std::min(lo, scalars[i]);
    hi = std::max(hi, scalars[i]);
    maxAbs = std::max(maxAbs, std::fabs(scalars[i]));
  }
  double scale = hi - lo > 0.0 ? hi - lo : (maxAbs > 0.0 ? maxAbs : 1.0);
  int intervals = 1;
  FitContext ctx{ shape, points, scalars, origin, direction,
    settings.RelativeTolerance * scale, NewtonFloor * scale, std::max(settings.MaxPieces, 1),
    &out, &st, &intervals };
  Fit(ctx, t0, t1, 0);
  return static_cast<int>(out.size());
}

bool InvertMatrix3(const double j[9], double inv[9])
{
  const double c00 = j[4] * j[8] - j[5] * j[7], c01 = j[5] * j[6] - j[3] * j[8],
               c02 = j[3] * j[7] - j[4] * j[6];
  const double det = j[0] * c00 + j[1] * c01 + j[2] * c02;
  if (!(std::fabs(det) > 0.0) || !std::isfinite(det))
  {
    return false;
  }
  const double r = 1.0 / det;
  inv[0] = c00 * r;
  inv[1] = (j[2] * j[7] - j[1] * j[8]) * r;
  inv[2] = (j[1] * j[5] - j[2] * j[4]) * r;
  inv[3] = c01 * r;
  inv[4] = (j[0] * j[8] - j[2] * j[6]) * r;
  inv[5] = (j[2] * j[3] - j[0] * j[5]) * r;
  inv[6] = c02 * r;
  inv[7] = (j[1] * j[6] - j[0] * j[7]) * r;
  inv[8] = (j[0] * j[4] - j[1] * j[3]) * r;
  return std::isfinite(inv[0] + inv[1] + inv[2] + inv[3] + inv[4] + inv[5] + inv[6] + inv[7] +
    inv[8]);
}
}
