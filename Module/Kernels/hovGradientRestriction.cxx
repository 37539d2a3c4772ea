#include "hovGradientRestriction.h"

#include "hovChebyshevFit.h"  // the Chebyshev steps
#include "hovFieldGradient.h" // CellFieldAndGradient

#include <algorithm> // std::max
#include <cmath>     // fabs, isfinite

namespace hov
{
namespace
{
using detail::ChebN;
/// Newton's parametric tolerance (1e-14) times a few: the samples' error
/// floor relative to the gradient's scale (as the scalar's NewtonFloor).
constexpr double NewtonFloor = 1e-13;
/// Bisection depth limit (the piece count limit usually acts first).
constexpr int MaxDepth = 24;

struct Context
{
  CellShape Shape;
  const double* Points;
  const double* Scalars;
  const double* O;
  const double* D;
  double TolAbs = 0.0;
  double Floor = 0.0;
  int MaxPieces = 1;
  std::vector<GradientPiece>* Out;
  CellRestrictionStatus* Status;
  int Intervals = 1; ///< of the partition so far, pending halves included (<= MaxPieces)
};

/// The three components' Chebyshev coefficients on [a, b].
void Sample(Context& ctx, double a, double b, double c[3][ChebN + 1])
{
  double t[ChebN + 1], f[3][ChebN + 1];
  detail::ChebyshevPoints(a, b, t);
  double pc[3];
  CellParametricCenter(ctx.Shape, pc);
  for (int j = 0; j <= ChebN; ++j)
  {
    const double x[3] = { ctx.O[0] + t[j] * ctx.D[0], ctx.O[1] + t[j] * ctx.D[1],
      ctx.O[2] + t[j] * ctx.D[2] };
    double value, g[3];
    if (!CellFieldAndGradient(ctx.Shape, ctx.Points, ctx.Scalars, x, pc, value, g))
    {
      ++ctx.Status->NewtonFailures; // warm start from the previous point either way
    }
    for (int i = 0; i < 3; ++i)
    {
      f[i][j] = g[i];
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    detail::ChebyshevCoefficients(f[i], c[i]);
  }
}

void Fit(Context& ctx, double a, double b, int depth, double (*given)[ChebN + 1])
{
  double own[3][ChebN + 1];
  double(*c)[ChebN + 1] = given;
  if (!c)
  {
    Sample(ctx, a, b, own);
    c = own;
  }
  int m[3];
  double bound = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    double bi = 0.0;
    m[i] = detail::TruncationDegree(c[i], ctx.Floor, ctx.TolAbs, bi);
    bound = std::max(bound, bi);
  }
  const double mid = 0.5 * (a + b);
  const bool canSplit =
    depth < MaxDepth && ctx.Intervals + 1 <= ctx.MaxPieces && mid > a && mid < b;
  if (!(bound <= ctx.TolAbs) && canSplit)
  {
    ++ctx.Intervals;
    Fit(ctx, a, mid, depth + 1, nullptr);
    Fit(ctx, mid, b, depth + 1, nullptr);
    return;
  }
  if (!(bound <= ctx.TolAbs))
  {
    ctx.Status->Converged = false;
  }
  GradientPiece piece;
  piece.T0 = a;
  piece.T1 = b;
  for (int i = 0; i < 3; ++i)
  {
    piece.G[i] = detail::ChebyshevToLocal(c[i], m[i], a, b);
  }
  piece.ErrorBound = bound;
  ctx.Out->push_back(piece);
}
}

int RestrictCellGradient(CellShape shape, const double* points, const double* scalars,
  const double origin[3], const double direction[3], double t0, double t1,
  const CellRestrictionSettings& settings, std::vector<GradientPiece>& out,
  CellRestrictionStatus* status)
{
  out.clear();
  CellRestrictionStatus local;
  CellRestrictionStatus& st = status ? *status : local;
  st = CellRestrictionStatus();
  bool finite = std::isfinite(t0) && std::isfinite(t1) && t0 <= t1;
  for (int k = 0; k < 3; ++k)
  {
    finite = finite && std::isfinite(origin[k]) && std::isfinite(direction[k]);
  }
  for (int i = 0, n = CellNodeCount(shape); finite && i < n; ++i)
  {
    finite = std::isfinite(scalars[i]) && std::isfinite(points[3 * i]) &&
      std::isfinite(points[3 * i + 1]) && std::isfinite(points[3 * i + 2]);
  }
  if (!finite)
  {
    st.Converged = false;
    return 0;
  }
  Context ctx{ shape, points, scalars, origin, direction, 0.0, 0.0,
    std::max(settings.MaxPieces, 1), &out, &st };
  if (t1 == t0)
  {
    // Zero length: the constant gradient at t0.
    const double x[3] = { origin[0] + t0 * direction[0], origin[1] + t0 * direction[1],
      origin[2] + t0 * direction[2] };
    double pc[3], value, g[3];
    CellParametricCenter(shape, pc);
    if (!CellFieldAndGradient(shape, points, scalars, x, pc, value, g))
    {
      ++st.NewtonFailures;
    }
    GradientPiece piece;
    piece.T0 = piece.T1 = t0;
    for (int i = 0; i < 3; ++i)
    {
      piece.G[i].C[0] = g[i];
    }
    out.push_back(piece);
    return 1;
  }
  // The first interval's samples give the scale (and are its fit).
  double c[3][ChebN + 1];
  Sample(ctx, t0, t1, c);
  double scale = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    // The interpolant's values are bounded by sum |c_k|, which bounds the
    // samples from above and is as cheap.
    double sum = 0.0;
    for (int k = 0; k <= ChebN; ++k)
    {
      sum += std::fabs(c[i][k]);
    }
    scale = std::max(scale, sum);
  }
  ctx.TolAbs = settings.RelativeTolerance * scale;
  ctx.Floor = NewtonFloor * scale;
  Fit(ctx, t0, t1, 0, c);
  return static_cast<int>(out.size());
}
}
