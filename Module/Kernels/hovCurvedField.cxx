// The field along a ray segment as Bernstein pieces, and breakpoint location:
// see hovCurvedSegment.h (RepresentFieldOnSegment, LocateBreakpoints).
#include "hovCurvedSegment.h"

#include "hovCurvedSampling.h" // detail::RepresentCurvedField

#include <algorithm> // std::min, std::max
#include <cmath>     // std::cos, std::abs
#include <limits>    // epsilon

namespace hov
{
namespace
{
constexpr double Eps = std::numeric_limits<double>::epsilon();
constexpr double Pi = 3.14159265358979323846;
/// Chebyshev interpolation degrees of curved pieces: the coarse rule first,
/// the fine one (nested: twice the points) where the coarse estimate misses.
constexpr int CoarseDegree = 8;
constexpr int SampleDegree = 16;
/// Newton tolerance floor of the sampled values, relative to the field scale.
constexpr double NewtonFloor = 1e-13;

/// The field at o + t d; @p pc is the warm start in and the coordinates out.
bool FieldAt(const LagrangeCellView& cell, const double o[3], const double d[3], double t,
  double pc[3], double& value, double* gradient = nullptr)
{
  const double x[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
  if (!InvertLagrangeGeometry(cell, x, pc).Converged())
  {
    return false;
  }
  value = EvaluateLagrangeScalar(cell, pc, gradient);
  return true;
}

/// sum_k c_k T_k(2y - 1) in Bernstein form of degree n (T_k built by the
/// recurrence T_{k+1} = 2 (2y - 1) T_k - T_{k-1} in Bernstein form).
BernsteinPolynomial ChebyshevToBernstein(const double* c, int n)
{
  BernsteinPolynomial sum, prev, cur, twoX;
  sum.Degree = n;
  prev.Degree = 0;
  prev.B[0] = 1.0;
  cur.Degree = 1;
  cur.B[0] = -1.0;
  cur.B[1] = 1.0;
  twoX.Degree = 1;
  twoX.B[0] = -2.0;
  twoX.B[1] = 2.0;
  for (int k = 0; k <= n; ++k)
  {
    const BernsteinPolynomial tk = ElevateBernstein(k == 0 ? prev : cur, n);
    for (int j = 0; j <= n; ++j)
    {
      sum.B[j] += c[k] * tk.B[j];
    }
    if (k >= 1 && k < n)
    {
      BernsteinPolynomial next;
      MultiplyBernstein(cur, twoX, next);
      const BernsteinPolynomial older = ElevateBernstein(prev, k + 1);
      for (int j = 0; j <= k + 1; ++j)
      {
        next.B[j] -= older.B[j];
      }
      prev = cur;
      cur = next;
    }
  }
  return sum;
}

/// Tables of the Chebyshev interpolants of degree 8 and 16 (built once,
/// thread-safe static): cos(pi m / 16) and each T_k(2y - 1) in Bernstein form.
struct ChebyshevTables
{
  double Cos[2 * SampleDegree];                           ///< cos(pi m / 16)
  double Q8[CoarseDegree + 1][CoarseDegree + 1];          ///< T_k at degree 8
  double Q16[SampleDegree + 1][SampleDegree + 1];         ///< T_k at degree 16
  ChebyshevTables()
  {
    for (int m = 0; m < 2 * SampleDegree; ++m)
    {
      this->Cos[m] = std::cos(Pi * m / SampleDegree);
    }
    double e[SampleDegree + 1] = {};
    for (int k = 0; k <= SampleDegree; ++k)
    {
      e[k] = 1.0;
      const BernsteinPolynomial b16 = ChebyshevToBernstein(e, SampleDegree);
      std::copy(b16.B, b16.B + SampleDegree + 1, this->Q16[k]);
      if (k <= CoarseDegree)
      {
        const BernsteinPolynomial b8 = ChebyshevToBernstein(e, CoarseDegree);
        std::copy(b8.B, b8.B + CoarseDegree + 1, this->Q8[k]);
      }
      e[k] = 0.0;
    }
  }
};

const ChebyshevTables& Tables()
{
  static const ChebyshevTables tables;
  return tables;
}

/// Chebyshev interpolant of degree @p n (8 or 16) from the values @p f at the
/// points cos(pi j / n) (f[j * stride], stride 16 / n of the degree-16 array),
/// into @p piece with its error estimate (see hovCurvedSegment.h).
void Interpolant(const double* f, int n, double ta, double tb, double scale, FieldPiece& piece)
{
  const ChebyshevTables& tab = Tables();
  const int stride = SampleDegree / n;
  double c[SampleDegree + 1], sumAbs = 0.0;
  for (int k = 0; k <= n; ++k)
  {
    double s = 0.0;
    for (int j = 0; j <= n; ++j)
    {
      // cos(pi j k / n) = Cos[(stride j k) mod 32].
      s += ((j == 0 || j == n) ? 0.5 : 1.0) * f[j * stride] * tab.Cos[(stride * j * k) % (2 * SampleDegree)];
    }
    c[k] = ((k == 0 || k == n) ? 1.0 : 2.0) * s / n;
    sumAbs += std::abs(c[k]);
  }
  piece.T0 = ta;
  piece.T1 = tb;
  piece.G = BernsteinPolynomial();
  piece.G.Degree = n;
  for (int k = 0; k <= n; ++k)
  {
    const double* q = n == SampleDegree ? tab.Q16[k] : tab.Q8[k];
    for (int j = 0; j <= n; ++j)
    {
      piece.G.B[j] += c[k] * q[j];
    }
  }
  piece.Error = 2.0 * (std::abs(c[n - 1]) + std::abs(c[n])) + 64.0 * Eps * sumAbs +
    NewtonFloor * scale;
  piece.Exact = false;
}

/// Chebyshev interpolant of the field on [ta, tb] with its error estimate (see
/// hovCurvedSegment.h): degree CoarseDegree first, then SampleDegree on the
/// nested points (the even ones are the coarse rule's) if the estimate misses
/// @p tol. Each inversion is warm-started from its neighbours (linear
/// extrapolation / interpolation of their coordinates in t).
bool SamplePiece(const LagrangeCellView& cell, const double o[3], const double d[3], double ta,
  double tb, double pc[3], double scale, double tol, FieldPiece& piece)
{
  const int n = SampleDegree;
  const ChebyshevTables& tab = Tables();
  double f[SampleDegree + 1];      // f[j] at x_j = cos(pi j / n), y = (1 + x)/2
  double pcs[SampleDegree + 1][3]; // the samples' parametric coordinates
  double ts[SampleDegree + 1];
  for (int j = 0; j <= n; ++j)
  {
    ts[j] = ta + 0.5 * (1.0 + tab.Cos[j]) * (tb - ta);
  }
  // Coarse points, ascending t (j = n, n - 2, ..., 0).
  for (int i = 0, prev = -1, older = -1, oldest = -1; i <= n; i += 2)
  {
    const int j = n - i;
    double guess[3] = { pc[0], pc[1], pc[2] };
    if (oldest >= 0)
    {
      // Quadratic extrapolation through the last three points (Lagrange form).
      const double t = ts[j], a = ts[prev], b = ts[older], c = ts[oldest];
      const double la = (t - b) * (t - c) / ((a - b) * (a - c));
      const double lb = (t - a) * (t - c) / ((b - a) * (b - c));
      const double lc = (t - a) * (t - b) / ((c - a) * (c - b));
      for (int k = 0; k < 3; ++k)
      {
        guess[k] = la * pcs[prev][k] + lb * pcs[older][k] + lc * pcs[oldest][k];
      }
    }
    else if (older >= 0)
    {
      const double w = (ts[j] - ts[prev]) / (ts[prev] - ts[older]);
      for (int k = 0; k < 3; ++k)
      {
        guess[k] = pcs[prev][k] + w * (pcs[prev][k] - pcs[older][k]);
      }
    }
    if (!FieldAt(cell, o, d, ts[j], guess, f[j]))
    {
      std::copy(pc, pc + 3, guess); // retry from the plain warm start
      if (!FieldAt(cell, o, d, ts[j], guess, f[j]))
      {
        return false;
      }
    }
    std::copy(guess, guess + 3, pcs[j]);
    std::copy(guess, guess + 3, pc);
    oldest = older;
    older = prev;
    prev = j;
  }
  Interpolant(f, CoarseDegree, ta, tb, scale, piece);
  std::copy(pcs[n], pcs[n] + 3, piece.PC0);
  std::copy(pcs[0], pcs[0] + 3, piece.PC1);
  piece.HasPC = true;
  if (piece.Error <= tol)
  {
    return true;
  }
  // The odd points between them.
  for (int j = n - 1; j >= 1; j -= 2)
  {
    // Guess: the interpolant through the coarse neighbours j +- 1 and, where
    // they exist, j +- 3 (cubic inside, linear at the ends).
    const bool cubic = j + 3 <= n && j - 3 >= 0;
    const int nodes[4] = { j + 1, j - 1, j + 3, j - 3 };
    const int count = cubic ? 4 : 2;
    double guess[3] = { 0.0, 0.0, 0.0 };
    for (int q = 0; q < count; ++q)
    {
      double l = 1.0;
      for (int r = 0; r < count; ++r)
      {
        l *= r == q ? 1.0 : (ts[j] - ts[nodes[r]]) / (ts[nodes[q]] - ts[nodes[r]]);
      }
      for (int k = 0; k < 3; ++k)
      {
        guess[k] += l * pcs[nodes[q]][k];
      }
    }
    if (!FieldAt(cell, o, d, ts[j], guess, f[j]))
    {
      std::copy(pcs[j + 1], pcs[j + 1] + 3, guess);
      if (!FieldAt(cell, o, d, ts[j], guess, f[j]))
      {
        return false;
      }
    }
  }
  Interpolant(f, n, ta, tb, scale, piece);
  return true;
}
}

bool RepresentFieldOnSegment(const LagrangeCellView& cell, const CellDerivativeBounds& bounds,
  const double origin[3], const double direction[3], double t0, double t1, const double* pcGuess,
  const CurvedSegmentSettings& settings, std::vector<FieldPiece>& out)
{
  out.clear();
  const double tol = settings.FieldTolerance * bounds.FieldScale;
  // Affine (or nearly) geometry: one Taylor model with a negligible remainder is the field.
  EnclosureSettings one;
  one.MaxPieces = 1;
  std::vector<EnclosurePiece> model;
  const FieldEnclosure e =
    EncloseFieldOnSegment(cell, bounds, origin, direction, t0, t1, pcGuess, one, &model);
  if (e.Valid && model.size() == 1 && !model[0].Loose && model[0].Remainder <= tol)
  {
    FieldPiece p;
    p.T0 = t0;
    p.T1 = t1;
    p.G = model[0].Q;
    p.Error = model[0].Remainder;
    p.Exact = true;
    out.push_back(p);
    return true;
  }
  return detail::RepresentCurvedField(cell, bounds.FieldScale, tol, origin, direction, t0, t1,
    pcGuess, settings.MaxPieces, out);
}

bool detail::RepresentCurvedField(const LagrangeCellView& cell, double scale, double tol,
  const double origin[3], const double direction[3], double t0, double t1, const double* pcGuess,
  int maxPieces, std::vector<FieldPiece>& out)
{
  out.clear();
  // Curved: Chebyshev pieces, bisected (left first) until the estimate meets the tolerance.
  double pc[3];
  cell.Basis->ParametricCenter(pc);
  if (pcGuess)
  {
    std::copy(pcGuess, pcGuess + 3, pc);
  }
  struct Span
  {
    double A, B;
  };
  std::vector<Span> stack{ { t0, t1 } };
  while (!stack.empty())
  {
    const Span s = stack.back();
    stack.pop_back();
    FieldPiece p;
    if (!SamplePiece(cell, origin, direction, s.A, s.B, pc, scale, tol, p))
    {
      return false;
    }
    const bool canSplit =
      static_cast<int>(out.size() + stack.size()) + 2 <= maxPieces && s.B - s.A > 1e-9 * (t1 - t0);
    if (p.Error > tol && canSplit)
    {
      const double mid = 0.5 * (s.A + s.B);
      stack.push_back({ mid, s.B });
      stack.push_back({ s.A, mid });
      cell.Basis->ParametricCenter(pc);
      if (pcGuess)
      {
        std::copy(pcGuess, pcGuess + 3, pc);
      }
      continue;
    }
    out.push_back(p);
  }
  return true;
}

int LocateBreakpoints(const LagrangeCellView& cell, const double origin[3],
  const double direction[3], const FieldPiece& piece, double level, std::vector<double>& roots)
{
  double lo, hi;
  BernsteinRange(piece.G, lo, hi);
  if (level < lo - piece.Error || level > hi + piece.Error)
  {
    return 0;
  }
  double ys[MaxBernsteinDegree + 1];
  const int n = BernsteinRoots(piece.G, level, ys, MaxBernsteinDegree + 1);
  const double h = piece.T1 - piece.T0;
  for (int i = 0; i < n; ++i)
  {
    double t = piece.T0 + ys[i] * h;
    if (!piece.Exact)
    {
      // Polish on the exact field: Newton on the coupled system x(pc) = o + t d,
      // f(pc) = level in (pc, t), one geometry and one field evaluation per step,
      // from the ray point's exact coordinates (one inversion); kept inside the
      // piece (the approximant's root is within ~Error/|g'|). Each step solves
      //   [J -d; grad^T 0] (dpc, dt) = -(x - o - t d, f - level)
      // by dpc = a + b dt, a = -J^-1 r, b = J^-1 d. Warm start: the coordinates
      // interpolated between the piece's ends.
      double pc[3];
      cell.Basis->ParametricCenter(pc);
      for (int k = 0; k < 3 && piece.HasPC; ++k)
      {
        pc[k] = piece.PC0[k] + ys[i] * (piece.PC1[k] - piece.PC0[k]);
      }
      double g, grad[3];
      bool ok = FieldAt(cell, origin, direction, t, pc, g, grad);
      for (int iter = 0; ok && iter < 4; ++iter)
      {
        double x[3], J[9], r[3], a[3], b[3];
        if (iter > 0)
        {
          g = EvaluateLagrangeScalar(cell, pc, grad);
        }
        EvaluateLagrangePosition(cell, pc, x, J);
        for (int k = 0; k < 3; ++k)
        {
          r[k] = -(x[k] - origin[k] - t * direction[k]);
        }
        if (!Solve3x3(J, r, a, 1e-14) || !Solve3x3(J, direction, b, 1e-14))
        {
          break;
        }
        const double slope = grad[0] * b[0] + grad[1] * b[1] + grad[2] * b[2];
        const double dt = slope != 0.0
          ? -(g - level + grad[0] * a[0] + grad[1] * a[1] + grad[2] * a[2]) / slope
          : 0.0;
        const double next = t + dt;
        if (!(next >= piece.T0 && next <= piece.T1) || std::abs(dt) > 1e-6 * h)
        {
          break; // not in the approximant root's neighbourhood: keep it
        }
        t = next;
        for (int k = 0; k < 3; ++k)
        {
          pc[k] += a[k] + b[k] * dt;
        }
        if (std::abs(dt) <= 4.0 * Eps * (std::abs(t) + h))
        {
          break; // converged (quadratically: the next step would be rounding)
        }
      }
    }
    roots.push_back(t);
  }
  return n;
}
}
