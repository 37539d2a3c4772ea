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

/// The field at o + t d; @p pc is the warm start in and the coordinates out;
/// @p rate, if given, receives dpc/dt = J^-1 d (false in @p hasRate if J is
/// singular there).
bool FieldAt(const LagrangeCellView& cell, const double o[3], const double d[3], double t,
  double pc[3], double& value, double* gradient = nullptr, double* rate = nullptr,
  bool* hasRate = nullptr)
{
  const double x[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
  const LagrangeInversionResult inv = InvertLagrangeGeometry(cell, x, pc);
  if (!inv.Converged())
  {
    return false;
  }
  value = EvaluateLagrangeScalar(cell, pc, gradient);
  if (rate)
  {
    *hasRate = Solve3x3(inv.Jacobian, d, rate, 1e-14);
  }
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

/// One computed sample of SamplePiece: coordinates and their rate dpc/dt.
struct Sample
{
  double PC[3];
  double Rate[3];
  bool HasRate = false;
};

/// Newton start at @p t between computed samples @p a (at ta) and @p b (at
/// tb): the cubic Hermite interpolant of their coordinates and rates (the
/// linear one where a rate is missing).
void HermiteGuess(const Sample& a, double ta, const Sample& b, double tb, double t, double pc[3])
{
  const double h = tb - ta, u = (t - ta) / h;
  const bool cubic = a.HasRate && b.HasRate;
  const double h00 = cubic ? (2.0 * u - 3.0) * u * u + 1.0 : 1.0 - u;
  const double h01 = 1.0 - h00;
  const double h10 = cubic ? ((u - 2.0) * u + 1.0) * u * h : 0.0;
  const double h11 = cubic ? (u - 1.0) * u * u * h : 0.0;
  for (int k = 0; k < 3; ++k)
  {
    pc[k] = h00 * a.PC[k] + h01 * b.PC[k] + h10 * a.Rate[k] + h11 * b.Rate[k];
  }
}

/// Chebyshev interpolant of the field on [ta, tb] with its error estimate (see
/// hovCurvedSegment.h): degree CoarseDegree first, then SampleDegree on the
/// nested points (the even ones are the coarse rule's) if the estimate misses
/// @p tol. The ends are inverted first (from @p pcA / @p pcB, the latter
/// extrapolated from the first end's rate if null), then every other point
/// in bisection order from the Hermite interpolant of its computed
/// neighbours (HermiteGuess), retried from the left neighbour's coordinates.
bool SamplePiece(const LagrangeCellView& cell, const double o[3], const double d[3], double ta,
  double tb, const double pcA[3], const double* pcB, double scale, double tol, FieldPiece& piece)
{
  const int n = SampleDegree;
  const ChebyshevTables& tab = Tables();
  double f[SampleDegree + 1]; // f[j] at x_j = cos(pi j / n), y = (1 + x)/2
  Sample smp[SampleDegree + 1];
  double ts[SampleDegree + 1];
  for (int j = 0; j <= n; ++j)
  {
    ts[j] = ta + 0.5 * (1.0 + tab.Cos[j]) * (tb - ta);
  }
  ts[n] = ta;
  ts[0] = tb;
  const auto compute = [&](int j, const double guess[3], const double* retry) {
    double p[3] = { guess[0], guess[1], guess[2] };
    if (!FieldAt(cell, o, d, ts[j], p, f[j], nullptr, smp[j].Rate, &smp[j].HasRate))
    {
      if (!retry)
      {
        return false;
      }
      std::copy(retry, retry + 3, p);
      if (!FieldAt(cell, o, d, ts[j], p, f[j], nullptr, smp[j].Rate, &smp[j].HasRate))
      {
        return false;
      }
    }
    std::copy(p, p + 3, smp[j].PC);
    return true;
  };
  // The ends.
  if (!compute(n, pcA, nullptr))
  {
    return false;
  }
  double guess[3];
  for (int k = 0; k < 3; ++k)
  {
    guess[k] = pcB ? pcB[k]
                   : smp[n].PC[k] + (smp[n].HasRate ? (tb - ta) * smp[n].Rate[k] : 0.0);
  }
  if (!compute(0, guess, smp[n].PC))
  {
    return false;
  }
  // Coarse interior points in bisection order: {point, left, right}.
  static constexpr int coarse[7][3] = { { 8, 16, 0 }, { 12, 16, 8 }, { 4, 8, 0 }, { 14, 16, 12 },
    { 10, 12, 8 }, { 6, 8, 4 }, { 2, 4, 0 } };
  for (const auto& c : coarse)
  {
    HermiteGuess(smp[c[1]], ts[c[1]], smp[c[2]], ts[c[2]], ts[c[0]], guess);
    if (!compute(c[0], guess, smp[c[1]].PC))
    {
      return false;
    }
  }
  const auto store = [&](int degree) {
    const int stride = SampleDegree / degree;
    piece.SampleDegree = degree;
    for (int j = 0; j <= degree; ++j)
    {
      std::copy(smp[j * stride].PC, smp[j * stride].PC + 3, piece.SamplePC[j]);
    }
  };
  Interpolant(f, CoarseDegree, ta, tb, scale, piece);
  std::copy(smp[n].PC, smp[n].PC + 3, piece.PC0);
  std::copy(smp[0].PC, smp[0].PC + 3, piece.PC1);
  piece.HasPC = true;
  if (piece.Error <= tol)
  {
    store(CoarseDegree);
    return true;
  }
  // The odd points between them.
  for (int j = n - 1; j >= 1; j -= 2)
  {
    HermiteGuess(smp[j + 1], ts[j + 1], smp[j - 1], ts[j - 1], ts[j], guess);
    if (!compute(j, guess, smp[j + 1].PC))
    {
      return false;
    }
  }
  Interpolant(f, n, ta, tb, scale, piece);
  store(SampleDegree);
  return true;
}
}

bool PieceCoordinates(const FieldPiece& piece, double t, double pc[3])
{
  const int n = piece.SampleDegree;
  if (n <= 0 || n > SampleDegree || !(piece.T1 > piece.T0))
  {
    return false;
  }
  // Barycentric interpolation at the points x_j = cos(pi j / n): weights
  // (-1)^j, halved at both ends.
  const ChebyshevTables& tab = Tables();
  const int stride = SampleDegree / n;
  const double x = 2.0 * (t - piece.T0) / (piece.T1 - piece.T0) - 1.0;
  double num[3] = { 0.0, 0.0, 0.0 }, den = 0.0;
  for (int j = 0; j <= n; ++j)
  {
    const double diff = x - tab.Cos[j * stride];
    if (diff == 0.0)
    {
      std::copy(piece.SamplePC[j], piece.SamplePC[j] + 3, pc);
      return true;
    }
    const double w = ((j & 1) ? -1.0 : 1.0) * ((j == 0 || j == n) ? 0.5 : 1.0) / diff;
    den += w;
    for (int k = 0; k < 3; ++k)
    {
      num[k] += w * piece.SamplePC[j][k];
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    pc[k] = num[k] / den;
  }
  return true;
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
  int maxPieces, std::vector<FieldPiece>& out, const double* pcEndGuess)
{
  out.clear();
  // Curved: Chebyshev pieces, bisected (left first) until the estimate meets
  // the tolerance; a half's ends start from the parent's samples.
  struct Span
  {
    double A, B;
    double PCA[3], PCB[3];
    bool HasB;
  };
  Span first{ t0, t1, {}, {}, pcEndGuess != nullptr };
  cell.Basis->ParametricCenter(first.PCA);
  if (pcGuess)
  {
    std::copy(pcGuess, pcGuess + 3, first.PCA);
  }
  if (pcEndGuess)
  {
    std::copy(pcEndGuess, pcEndGuess + 3, first.PCB);
  }
  std::vector<Span> stack{ first };
  while (!stack.empty())
  {
    const Span s = stack.back();
    stack.pop_back();
    FieldPiece p;
    if (!SamplePiece(
          cell, origin, direction, s.A, s.B, s.PCA, s.HasB ? s.PCB : nullptr, scale, tol, p))
    {
      return false;
    }
    const bool canSplit =
      static_cast<int>(out.size() + stack.size()) + 2 <= maxPieces && s.B - s.A > 1e-9 * (t1 - t0);
    if (p.Error > tol && canSplit)
    {
      const double mid = 0.5 * (s.A + s.B);
      Span right{ mid, s.B, {}, {}, true }, left{ s.A, mid, {}, {}, true };
      PieceCoordinates(p, mid, right.PCA);
      std::copy(right.PCA, right.PCA + 3, left.PCB);
      std::copy(p.PC0, p.PC0 + 3, left.PCA);
      std::copy(p.PC1, p.PC1 + 3, right.PCB);
      stack.push_back(right);
      stack.push_back(left);
      continue;
    }
    out.push_back(p);
  }
  return true;
}

namespace
{
/**
 * The coupled Newton of LocateBreakpoints from (@p pc, @p t): true when it
 * converged (|dt| at rounding). With @p invert the ray point's coordinates
 * are first inverted exactly; then @p t keeps every accepted step, as it did
 * before the samples' start (a step leaving the piece or longer than 1e-6 of
 * it is not taken). Without, @p t is changed only on convergence.
 */
bool PolishBreakpoint(const LagrangeCellView& cell, const double origin[3],
  const double direction[3], const FieldPiece& piece, double level, bool invert, double pc[3],
  double& t)
{
  const double h = piece.T1 - piece.T0;
  double g = 0.0, grad[3] = { 0.0, 0.0, 0.0 };
  if (invert)
  {
    if (!FieldAt(cell, origin, direction, t, pc, g, grad))
    {
      return false;
    }
  }
  else
  {
    g = EvaluateLagrangeScalar(cell, pc, grad);
  }
  double tt = t;
  const int iterations = invert ? 4 : 6;
  for (int iter = 0; iter < iterations; ++iter)
  {
    double x[3], J[9], r[3], a[3], b[3];
    if (iter > 0)
    {
      g = EvaluateLagrangeScalar(cell, pc, grad);
    }
    EvaluateLagrangePosition(cell, pc, x, J);
    for (int k = 0; k < 3; ++k)
    {
      r[k] = -(x[k] - origin[k] - tt * direction[k]);
    }
    if (!Solve3x3(J, r, a, 1e-14) || !Solve3x3(J, direction, b, 1e-14))
    {
      return false;
    }
    const double slope = grad[0] * b[0] + grad[1] * b[1] + grad[2] * b[2];
    const double dt = slope != 0.0
      ? -(g - level + grad[0] * a[0] + grad[1] * a[1] + grad[2] * a[2]) / slope
      : 0.0;
    const double next = tt + dt;
    if (!(next >= piece.T0 && next <= piece.T1) || std::abs(dt) > 1e-6 * h)
    {
      return false; // not in the approximant root's neighbourhood
    }
    tt = next;
    for (int k = 0; k < 3; ++k)
    {
      pc[k] += a[k] + b[k] * dt;
    }
    if (invert)
    {
      t = tt;
    }
    if (std::abs(dt) <= 4.0 * Eps * (std::abs(tt) + h))
    {
      t = tt;
      return true; // converged (quadratically: the next step would be rounding)
    }
  }
  return false;
}
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
      // kept inside the piece (the approximant's root is within ~Error/|g'|).
      // Each step solves
      //   [J -d; grad^T 0] (dpc, dt) = -(x - o - t d, f - level)
      // by dpc = a + b dt, a = -J^-1 r, b = J^-1 d. Start: the piece's sampled
      // coordinates interpolated at the root; if that does not converge, the
      // ray point's exact coordinates (one inversion from the coordinates
      // interpolated linearly between the piece's ends).
      double pc[3];
      double tp = t;
      const bool fromSamples = PieceCoordinates(piece, t, pc) &&
        PolishBreakpoint(cell, origin, direction, piece, level, false, pc, tp);
      if (!fromSamples)
      {
        tp = t;
        cell.Basis->ParametricCenter(pc);
        for (int k = 0; k < 3 && piece.HasPC; ++k)
        {
          pc[k] = piece.PC0[k] + ys[i] * (piece.PC1[k] - piece.PC0[k]);
        }
        PolishBreakpoint(cell, origin, direction, piece, level, true, pc, tp);
      }
      t = tp;
    }
    roots.push_back(t);
  }
  return n;
}
}
