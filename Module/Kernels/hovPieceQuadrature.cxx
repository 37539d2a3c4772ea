#include "hovPieceQuadrature.h"

#include "hovGaussKronrod15.h" // XGK, WGK, WG

#include <algorithm> // std::min, std::max
#include <cmath>     // exp, expm1, fabs

namespace hov
{
namespace detail
{
namespace
{

// Gauss-Kronrod 3-7 (the cheap first try on each panel, see Integrate): nodes
// +-XK7[i], Kronrod weights WK7[i]; XK7[1] = sqrt(3/5) and XK7[3] = 0 are the
// 3 Gauss nodes, weights 5/9 and 8/9. Exact for polynomials of degree 11.
constexpr double XK7[4] = { 0.960491268708020283423507092629080,
  0.774596669241483377035853079956480, 0.434243749346802558002071502844628, 0.0 };
constexpr double WK7[4] = { 0.104656226026467265193823857192073,
  0.268488089868333440728569280666710, 0.401397414775962222905051818618432,
  0.450916538658474142345110087045571 };
constexpr double WG3[2] = { 0.555555555555555555555555555555556,
  0.888888888888888888888888888888889 };

// Beyond this optical depth inside a piece e^-D < 1.6e-28: the rest of the
// piece is not integrated, its bound goes into the error estimate.
constexpr double DepthCut = 64.0;
// Initial panels end where D reaches 1, 2, 4, ..., 32 (6 levels).
constexpr int DepthLevels = 6;
// Depth rates h tau above this are capped (as DepthCap in hovSegmentIntegral):
// D stays finite, e^-D is 0 long before.
constexpr double DepthRateCap = 1e300;
// Bisection depth limit for one panel (2^-40 of the initial panel).
constexpr int MaxBisectionDepth = 40;
// A panel's Kronrod-Gauss difference within this of the same rule applied to
// the sizes of the terms the integrands are made of (as QUADPACK's 50 eps
// resabs, with |u'| (e^-D + T(1)) for Williams-Max, whose difference cancels
// on optically thin pieces) is rounding: bisecting does not make it smaller.
// Such a panel is accepted even if it misses the colour target: a target
// below rounding (colours far beyond [0, 1], e.g. a table colour of 1e300)
// would otherwise bisect until the panel budget is gone (4096 panels per
// segment: 40-90 ms per pixel in robustness case 4711048797). Converged
// still reports the requested target, and the error estimate what was
// reached. Accepting adds at most about this fraction of the transmittance-
// and factor-weighted term sizes to the estimate, over the whole segment.
constexpr double RoundingFloor = 50.0 * 2.220446049250313e-16;

/// One piece in normalised coordinates y in [0,1]: u (colour), u', D, and the weights.
struct Piece
{
  Polynomial U, DU, Depth;
  double TotalDepth = 0.0;
  double EndTransmittance = 1.0;
  bool Emission = false; ///< Wilhelms-Van Gelder (two integrals) or Williams-Max (one)
};

/// p(y) by Horner's rule (inline: Degree is valid here).
inline double Horner(const Polynomial& p, double y)
{
  double r = p.C[p.Degree];
  for (int i = p.Degree - 1; i >= 0; --i)
  {
    r = r * y + p.C[i];
  }
  return r;
}

/**
 * Integrands at y: WM: f0 = u' (e^-D - T(1)); WVG: f0 = (1-u) e^-D, f1 = u e^-D.
 * @p m: the size of the terms they are made of, which sets their rounding
 * (WM: |u'| (e^-D + T(1)), which on an optically thin piece is far above
 * |f0|; WVG: e^-D = f0 + f1).
 */
inline void Integrands(const Piece& p, double y, double& f0, double& f1, double& m)
{
  const double e = std::exp(-Horner(p.Depth, y));
  if (p.Emission)
  {
    const double u = std::min(std::max(Horner(p.U, y), 0.0), 1.0);
    f0 = (1.0 - u) * e;
    f1 = u * e;
    m = e;
  }
  else
  {
    const double du = Horner(p.DU, y);
    f0 = du * (e - p.EndTransmittance);
    f1 = 0.0;
    m = std::fabs(du) * (e + p.EndTransmittance);
  }
}

struct PanelResult
{
  double Value[2] = { 0.0, 0.0 };
  double Error[2] = { 0.0, 0.0 };
  double Abs = 0.0; ///< the Kronrod rule applied to the integrands' term sizes (Integrands)

  /// True if the error is at the rule's rounding (RoundingFloor).
  bool AtRounding() const
  {
    return std::isfinite(this->Abs) && this->Error[0] + this->Error[1] <= RoundingFloor * this->Abs;
  }
};

/// Gauss-Kronrod 7-15 on [y0, y1].
PanelResult Kronrod(const Piece& p, double y0, double y1)
{
  const double half = 0.5 * (y1 - y0), mid = 0.5 * (y0 + y1);
  double k[2] = { 0.0, 0.0 }, g[2] = { 0.0, 0.0 }, mag = 0.0;
  for (int i = 0; i < 8; ++i)
  {
    double a0, a1, am, b0 = 0.0, b1 = 0.0, bm = 0.0;
    Integrands(p, mid - half * XGK[i], a0, a1, am);
    if (i < 7)
    {
      Integrands(p, mid + half * XGK[i], b0, b1, bm);
    }
    k[0] += WGK[i] * (a0 + b0);
    k[1] += WGK[i] * (a1 + b1);
    mag += WGK[i] * (am + bm);
    if (i % 2 == 1)
    {
      g[0] += WG[i / 2] * (a0 + b0);
      g[1] += WG[i / 2] * (a1 + b1);
    }
  }
  PanelResult r;
  for (int j = 0; j < 2; ++j)
  {
    r.Value[j] = half * k[j];
    r.Error[j] = std::fabs(half * (k[j] - g[j]));
  }
  r.Abs = half * mag;
  return r;
}

/// Gauss-Kronrod 3-7 on [y0, y1].
PanelResult Kronrod7(const Piece& p, double y0, double y1)
{
  const double half = 0.5 * (y1 - y0), mid = 0.5 * (y0 + y1);
  double k[2] = { 0.0, 0.0 }, g[2] = { 0.0, 0.0 }, mag = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    double a0, a1, am, b0 = 0.0, b1 = 0.0, bm = 0.0;
    Integrands(p, mid - half * XK7[i], a0, a1, am);
    if (i < 3)
    {
      Integrands(p, mid + half * XK7[i], b0, b1, bm);
    }
    k[0] += WK7[i] * (a0 + b0);
    k[1] += WK7[i] * (a1 + b1);
    mag += WK7[i] * (am + bm);
    if (i % 2 == 1)
    {
      g[0] += WG3[i / 2] * (a0 + b0);
      g[1] += WG3[i / 2] * (a1 + b1);
    }
  }
  PanelResult r;
  for (int j = 0; j < 2; ++j)
  {
    r.Value[j] = half * k[j];
    r.Error[j] = std::fabs(half * (k[j] - g[j]));
  }
  r.Abs = half * mag;
  return r;
}

/**
 * Adaptive quadrature of the piece's integrals over [0,1]. @p factor converts
 * an integral's error into a colour error; @p budget is the colour error
 * allowed per unit of y; @p panelsLeft is decremented.
 */
void Integrate(const Piece& p, double factor, double budget, int& panelsLeft, double value[2],
  PieceOutput& out)
{
  // Initial panels at depth levels 1, 2, 4, ... (D is non-decreasing).
  double edges[DepthLevels + 3];
  int n = 0;
  edges[n++] = 0.0;
  double level = 1.0;
  for (int i = 0; i < DepthLevels && level < p.TotalDepth; ++i, level *= 2.0)
  {
    const double y = SolveMonotone(p.Depth, level, 0.0, 1.0);
    edges[n] = std::max(edges[n - 1], y);
    ++n;
  }
  double end = 1.0;
  if (p.TotalDepth > DepthCut)
  {
    end = std::max(edges[n - 1], SolveMonotone(p.Depth, DepthCut, 0.0, 1.0));
    // Tail bound: WM |u'|-weighted e^-D integrates to <= e^-64; WVG <= e^-64 (1 - end).
    out.Error += factor * std::exp(-DepthCut) * (p.Emission ? 2.0 * (1.0 - end) : 1.0);
  }
  edges[n++] = end;

  struct Panel
  {
    double Y0, Y1;
    int Depth;
  };
  Panel stack[DepthLevels + 3 + MaxBisectionDepth + 2];
  int top = 0;
  for (int i = n - 1; i >= 1; --i)
  {
    if (edges[i] > edges[i - 1])
    {
      stack[top++] = Panel{ edges[i - 1], edges[i], 0 };
    }
  }
  while (top > 0)
  {
    const Panel panel = stack[--top];
    // The 7-point pair first: on the usual smooth, thin pieces its estimate
    // already meets the budget (half the exponentials of the 15-point pair).
    PanelResult r = Kronrod7(p, panel.Y0, panel.Y1);
    double err = factor * (r.Error[0] + r.Error[1]);
    if (!(err <= budget * (panel.Y1 - panel.Y0)) && !r.AtRounding())
    {
      r = Kronrod(p, panel.Y0, panel.Y1);
      err = factor * (r.Error[0] + r.Error[1]);
    }
    --panelsLeft;
    ++out.Panels;
    const double mid = 0.5 * (panel.Y0 + panel.Y1);
    const bool canSplit = panel.Depth < MaxBisectionDepth && panelsLeft > 1 && mid > panel.Y0 &&
      mid < panel.Y1;
    if (err <= budget * (panel.Y1 - panel.Y0) || r.AtRounding() || !canSplit)
    {
      out.Converged = out.Converged && (err <= budget * (panel.Y1 - panel.Y0));
      value[0] += r.Value[0];
      value[1] += r.Value[1];
      out.Error += err;
      continue;
    }
    stack[top++] = Panel{ mid, panel.Y1, panel.Depth + 1 };
    stack[top++] = Panel{ panel.Y0, mid, panel.Depth + 1 };
  }
}
}

PieceOutput IntegrateSmoothPiece(const SegmentEnd& fA, const SegmentEnd& fB,
  const Polynomial& uDepth, const Polynomial& uColor, double h, double transmitFront,
  double budgetPerLength, bool emission, int& panelsLeft)
{
  PieceOutput out;
  Piece p;
  p.Emission = emission;
  p.U = uColor;
  p.DU = Derivative(p.U);
  Polynomial integralU;
  Antiderivative(uDepth, integralU); // degree <= 9: checked by the callers
  const double dA = std::min(fA.Tau * h, DepthRateCap), dB = std::min(fB.Tau * h, DepthRateCap);
  p.Depth = integralU;
  for (int i = 0; i <= p.Depth.Degree; ++i)
  {
    p.Depth.C[i] *= dB - dA;
  }
  p.Depth.C[1] += dA;
  p.Depth.Degree = std::max(p.Depth.Degree, 1);
  p.TotalDepth = std::max(Evaluate(p.Depth, 1.0), 0.0);
  p.EndTransmittance = std::exp(-p.TotalDepth);
  const double alpha = -std::expm1(-p.TotalDepth);
  out.Color.A = alpha;

  double factor = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    factor = std::max(factor,
      emission ? h * std::max(std::fabs(fA.Color[c]), std::fabs(fB.Color[c]))
               : std::fabs(fB.Color[c] - fA.Color[c]));
  }
  double w[2] = { 0.0, 0.0 };
  if (factor > 0.0)
  {
    const double budget = transmitFront > 0.0 ? budgetPerLength * h / transmitFront : INFINITY;
    Integrate(p, factor, budget, panelsLeft, w, out);
  }
  double* rgb[3] = { &out.Color.R, &out.Color.G, &out.Color.B };
  for (int c = 0; c < 3; ++c)
  {
    *rgb[c] = emission ? h * (fA.Color[c] * w[0] + fB.Color[c] * w[1])
                       : fA.Color[c] * alpha + (fB.Color[c] - fA.Color[c]) * w[0];
  }
  return out;
}
}
}
