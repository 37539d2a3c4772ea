// Rigorous enclosure of a Lagrange field along a ray segment: see hovEnclosure.h.
#include "hovEnclosure.h"

#include "hovLagrangeRestriction.h" // the field along a parametric line

#include <algorithm> // std::min, std::max, heap operations
#include <cmath>     // std::abs
#include <limits>    // infinity

namespace hov
{
namespace
{
/// Relative inflation of the O(1) bound arithmetic of a piece.
constexpr double ArithmeticInflation = 1e-12;

/// The data shared by the pieces of one segment.
struct SegmentContext
{
  const LagrangeCellView* Cell;
  const CellDerivativeBounds* Bounds;
  const double* O;
  const double* D;
};

/// |A| v for a 3x3 row-major A.
void AbsMul(const double A[9], const double v[3], double out[3])
{
  for (int i = 0; i < 3; ++i)
  {
    out[i] = std::abs(A[3 * i]) * v[0] + std::abs(A[3 * i + 1]) * v[1] + std::abs(A[3 * i + 2]) * v[2];
  }
}

/// Componentwise bound k >= |r(t) - rm| on the piece (file doc, step 2),
/// from the continuity argument; false if the quadratic bound has no small
/// branch (the piece is too long for the curvature).
bool DisplacementBound(const CellDerivativeBounds& bounds, const double Y[9], const double E0[9],
  const double rho[3], const double v[3], const double absD[3], double h, double k[3])
{
  const auto& M = bounds.Geometry;
  double normY = 0.0, normE0 = 0.0, mBar = 0.0;
  double yDrho[3];
  const double dRho[3] = { absD[0] * h + std::abs(rho[0]), absD[1] * h + std::abs(rho[1]),
    absD[2] * h + std::abs(rho[2]) };
  AbsMul(Y, dRho, yDrho);
  double A = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    double rowY = 0.0, rowE = 0.0, rowM = 0.0;
    for (int b = 0; b < 3; ++b)
    {
      rowY += std::abs(Y[3 * a + b]);
      rowE += std::abs(E0[3 * a + b]);
      for (int c = 0; c < 3; ++c)
      {
        rowM += M[a][b][c];
      }
    }
    normY = std::max(normY, rowY);
    normE0 = std::max(normE0, rowE);
    mBar = std::max(mBar, rowM);
    A = std::max(A, yDrho[a]);
  }
  // (1 - |E0|) s <= A + B s^2 with s(tm) = 0 and s continuous: s <= the small root.
  const double B = 0.5 * normY * mBar, oneMinus = 1.0 - normE0;
  const double disc = oneMinus * oneMinus - 4.0 * A * B;
  if (!(oneMinus > 0.0) || !(disc > 0.0))
  {
    return false;
  }
  const double s = (2.0 * A / (oneMinus + std::sqrt(disc))) * (1.0 + ArithmeticInflation);
  for (int a = 0; a < 3; ++a)
  {
    k[a] = s;
  }
  // Componentwise refinement: k <- |v| h + |Y| (|rho| + q(k)) + |E0| k (monotone: stays a bound).
  for (int iter = 0; iter < 3; ++iter)
  {
    double rq[3], yrq[3], e0k[3];
    for (int a = 0; a < 3; ++a)
    {
      double q = 0.0;
      for (int b = 0; b < 3; ++b)
        for (int c = 0; c < 3; ++c)
          q += 0.5 * M[a][b][c] * k[b] * k[c];
      rq[a] = std::abs(rho[a]) + q;
    }
    AbsMul(Y, rq, yrq);
    AbsMul(E0, k, e0k);
    for (int a = 0; a < 3; ++a)
    {
      k[a] = std::min(k[a], (std::abs(v[a]) * h + yrq[a] + e0k[a]) * (1.0 + ArithmeticInflation));
    }
  }
  return true;
}

/// One Taylor model on [ta, tb] (file doc); @p rm is the warm start in and the
/// midpoint's coordinates out. False if Newton or the displacement bound fails.
bool VerifyPiece(const SegmentContext& ctx, double ta, double tb, double rm[3],
  EnclosurePiece& piece, double& modelRemainder, int& newtonFailures)
{
  const LagrangeCellView& cell = *ctx.Cell;
  const double tm = 0.5 * (ta + tb), h = 0.5 * (tb - ta);
  const double x[3] = { ctx.O[0] + tm * ctx.D[0], ctx.O[1] + tm * ctx.D[1], ctx.O[2] + tm * ctx.D[2] };
  if (!InvertLagrangeGeometry(cell, x, rm).Converged())
  {
    ++newtonFailures;
    return false;
  }
  double xm[3], J[9], Y[9], E0[9], rho[3], v[3];
  EvaluateLagrangePosition(cell, rm, xm, J);
  for (int j = 0; j < 3; ++j)
  {
    const double e[3] = { j == 0 ? 1.0 : 0.0, j == 1 ? 1.0 : 0.0, j == 2 ? 1.0 : 0.0 };
    double col[3];
    if (!Solve3x3(J, e, col, 1e-14))
    {
      return false;
    }
    Y[j] = col[0];
    Y[3 + j] = col[1];
    Y[6 + j] = col[2];
    rho[j] = xm[j] - x[j];
  }
  for (int a = 0; a < 3; ++a)
  {
    v[a] = Y[3 * a] * ctx.D[0] + Y[3 * a + 1] * ctx.D[1] + Y[3 * a + 2] * ctx.D[2];
    for (int b = 0; b < 3; ++b)
    {
      E0[3 * a + b] = (a == b ? 1.0 : 0.0) -
        (Y[3 * a] * J[b] + Y[3 * a + 1] * J[3 + b] + Y[3 * a + 2] * J[6 + b]);
    }
  }
  const double absD[3] = { std::abs(ctx.D[0]), std::abs(ctx.D[1]), std::abs(ctx.D[2]) };
  double k[3];
  if (!DisplacementBound(*ctx.Bounds, Y, E0, rho, v, absD, h, k))
  {
    return false;
  }
  // Linear model remainder (step 3): e = -Y (rho + q) + E0 (r - rm).
  const auto& M = ctx.Bounds->Geometry;
  const auto& H = ctx.Bounds->Field;
  double rhoQ[3], epsR[3], e0k[3];
  for (int a = 0; a < 3; ++a)
  {
    double q = 0.0;
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c)
        q += 0.5 * M[a][b][c] * k[b] * k[c];
    rhoQ[a] = std::abs(rho[a]) + q;
  }
  AbsMul(Y, rhoQ, epsR);
  AbsMul(E0, k, e0k);
  for (int a = 0; a < 3; ++a)
  {
    epsR[a] += e0k[a];
    if (!(epsR[a] < ctx.Bounds->Margin))
    {
      return false; // the mean value point could leave the bounded box
    }
  }
  double grad[3];
  EvaluateLagrangeScalar(cell, rm, grad);
  double remainder = 0.0;
  for (int b = 0; b < 3; ++b)
  {
    // |xi - rm| <= k + eps_r for the mean value point xi.
    const double G = std::abs(grad[b]) + H[b][0] * (k[0] + epsR[0]) + H[b][1] * (k[1] + epsR[1]) +
      H[b][2] * (k[2] + epsR[2]);
    remainder += G * epsR[b];
  }
  const double start[3] = { rm[0] - v[0] * h, rm[1] - v[1] * h, rm[2] - v[2] * h };
  const double step[3] = { 2.0 * v[0] * h, 2.0 * v[1] * h, 2.0 * v[2] * h };
  double rounding = 0.0;
  if (!LagrangeFieldAlongLine(*cell.Basis, cell.Scalars, start, step, piece.Q, &rounding))
  {
    return false;
  }
  piece.T0 = ta;
  piece.T1 = tb;
  modelRemainder = remainder * (1.0 + ArithmeticInflation);
  piece.Remainder = modelRemainder + rounding;
  piece.Loose = false;
  return true;
}
}

FieldEnclosure EncloseFieldOnSegment(const LagrangeCellView& cell,
  const CellDerivativeBounds& bounds, const double origin[3], const double direction[3],
  double t0, double t1, const double* pcGuess, const EnclosureSettings& settings,
  std::vector<EnclosurePiece>* pieces)
{
  FieldEnclosure result;
  if (pieces)
  {
    pieces->clear();
  }
  if (!cell.Basis || !cell.Basis->IsInitialized() || !cell.Scalars || !bounds.Valid ||
    !(t0 <= t1) || !std::isfinite(t0) || !std::isfinite(t1))
  {
    return result;
  }
  const SegmentContext ctx{ &cell, &bounds, origin, direction };
  const double tolerance = settings.RemainderTolerance * bounds.FieldScale;
  double rm[3];
  cell.Basis->ParametricCenter(rm);
  if (pcGuess)
  {
    std::copy(pcGuess, pcGuess + 3, rm);
  }
  // Refine the piece with the largest model remainder (failed pieces first)
  // until every one meets the tolerance or MaxPieces is reached.
  struct Item
  {
    EnclosurePiece Piece;
    double Model; ///< model remainder; +inf if the bound failed
    double RM[3]; ///< midpoint coordinates (warm start of the children)
  };
  auto make = [&](double ta, double tb, const double* guess) {
    Item item;
    std::copy(guess, guess + 3, item.RM);
    double model = 0.0;
    const bool ok = VerifyPiece(ctx, ta, tb, item.RM, item.Piece, model, result.NewtonFailures);
    item.Piece.T0 = ta;
    item.Piece.T1 = tb;
    item.Piece.Loose = !ok;
    item.Model = ok ? model : std::numeric_limits<double>::infinity();
    if (!ok)
    {
      std::copy(guess, guess + 3, item.RM);
    }
    return item;
  };
  auto less = [](const Item& a, const Item& b) { return a.Model < b.Model; };
  std::vector<Item> heap{ make(t0, t1, rm) };
  const double minWidth = 1e-12 * (std::abs(t0) + std::abs(t1) + 1e-300);
  while (static_cast<int>(heap.size()) < std::max(settings.MaxPieces, 1))
  {
    std::pop_heap(heap.begin(), heap.end(), less);
    const Item worst = heap.back();
    if (!(worst.Model > tolerance) || worst.Piece.T1 - worst.Piece.T0 <= minWidth)
    {
      std::push_heap(heap.begin(), heap.end(), less);
      break;
    }
    heap.pop_back();
    const double mid = 0.5 * (worst.Piece.T0 + worst.Piece.T1);
    heap.push_back(make(worst.Piece.T0, mid, worst.RM));
    std::push_heap(heap.begin(), heap.end(), less);
    heap.push_back(make(mid, worst.Piece.T1, worst.RM));
    std::push_heap(heap.begin(), heap.end(), less);
  }
  std::sort(heap.begin(), heap.end(),
    [](const Item& a, const Item& b) { return a.Piece.T0 < b.Piece.T0; });
  result.Lo = 1e300;
  result.Hi = -1e300;
  for (Item& item : heap)
  {
    double lo = bounds.FieldMin, hi = bounds.FieldMax;
    if (!item.Piece.Loose)
    {
      BernsteinRangeSubdivided(item.Piece.Q, settings.RangeSubdivisions, lo, hi);
      lo -= item.Piece.Remainder;
      hi += item.Piece.Remainder;
      result.MaxRemainder = std::max(result.MaxRemainder, item.Piece.Remainder);
    }
    else
    {
      ++result.LoosePieces;
    }
    result.Lo = std::min(result.Lo, lo);
    result.Hi = std::max(result.Hi, hi);
    if (pieces)
    {
      pieces->push_back(item.Piece);
    }
  }
  const int leaves = static_cast<int>(heap.size());
  result.Pieces = leaves;
  result.Valid = true;
  return result;
}
}
