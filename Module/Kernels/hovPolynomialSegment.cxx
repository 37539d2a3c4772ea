#include "hovPolynomialSegment.h"

#include "hovBernstein.h"       // BernsteinFromMonomial: the monotonicity test
#include "hovBreakpointWalk.h"  // the intervals a monotone run crosses
#include "hovPieceQuadrature.h" // IntegrateSmoothPiece (the quadrature of one piece)
#include "hovRayIntegrator.h"    // IntegrateLinearScalar (degree <= 1)
#include "hovShadedSegment.h"    // the sampled route past many smooth nodes
#include "hovTransferFunction.h" // the table

#include <algorithm> // std::min, std::max, std::sort
#include <cmath>     // exp, expm1, fabs, isfinite, abs
#include <vector>    // table nodes

namespace hov
{
namespace
{
// Fields of higher degree have a depth of degree > MaxDegree.
constexpr int MaxFieldDegree = Polynomial::MaxDegree - 1;

using detail::PieceOutput;

/// The sampled route (file doc): pieces left when smooth crossings are
/// stepped over, panels bisected from them as the estimate asks.
constexpr int SampledPieces = 32;
/// Its budget of panel evaluations (accepted or bisected) is the exact walk's
/// pieces / this: an evaluation (17 samples, four DCTs) costs as much as
/// 10-17 exact pieces, so a try that fails adds about a quarter of the walk.
constexpr long long SampledBudgetDivisor = 64;

/// Relative distance to a table node below which a field value is taken to be
/// at the node: the rounding of a field that reaches a node value (a maximum
/// at a node with opacity 1, a constant cell) must not cross into the next
/// interval, which in GPU-compatible semantics may be an opaque medium.
constexpr double NodeSnap = 8.0 * 2.220446049250313e-16;

/// @p v, or the table node within NodeSnap (relative) of it.
double SnapToNode(const TransferFunction& tf, double v)
{
  const std::vector<double>& x = tf.GetNodes();
  const auto it = std::lower_bound(x.begin(), x.end(), v);
  for (auto c : { it, it == x.begin() ? it : it - 1 })
  {
    if (c != x.end() && std::abs(*c - v) <= NodeSnap * std::max(std::abs(*c), 1e-300))
    {
      return *c;
    }
  }
  return v;
}

/// True if a table node lies within @p bound (absolute) or NodeSnap (relative) of @p v.
bool NearNode(const TransferFunction& tf, double v, double bound)
{
  const std::vector<double>& x = tf.GetNodes();
  const auto it = std::lower_bound(x.begin(), x.end(), v);
  for (auto c : { it, it == x.begin() ? it : it - 1 })
  {
    if (c != x.end() &&
      std::abs(*c - v) <= bound + NodeSnap * std::max(std::abs(*c), std::abs(v)))
    {
      return true;
    }
  }
  return false;
}

/// A bound on the rounding of Horner's rule for @p s at @p t, generous (FMA
/// contraction, neighbouring samples): 4 (n + 1) eps sum |c_i t^i|, over
/// four times the classical gamma_2n sum |c_i t^i|.
double HornerBound(const Polynomial& s, double t)
{
  double sum = 0.0, power = 1.0;
  for (int i = 0; i <= s.Degree; ++i)
  {
    sum += std::abs(s.C[i]) * power;
    power *= std::abs(t);
  }
  return 4.0 * (s.Degree + 1) * 2.220446049250313e-16 * sum;
}

/**
 * Piece [tA, tA + h] of the segment in table interval @p k, where s goes
 * monotonically from @p sA to @p sB. @p transmitFront is the transmittance of
 * the segment in front of it; @p budgetPerLength the colour error allowed per
 * unit length.
 */
PieceOutput IntegratePiece(const TransferFunction& tf, int k, const Polynomial& s, double tA,
  double h, double sA, double sB, double transmitFront, double budgetPerLength, bool emission,
  int& panelsLeft)
{
  SegmentEnd fA, fB;
  tf.Evaluate(k, sA, emission, fA);
  tf.Evaluate(k, sB, emission, fB);
  const EmissionModel model = emission ? EmissionModel::WilhelmsVanGelder : EmissionModel::WilliamsMax;
  const bool sameEnds = fA.Tau == fB.Tau && fA.Color[0] == fB.Color[0] &&
    fA.Color[1] == fB.Color[1] && fA.Color[2] == fB.Color[2];
  if (sameEnds || !std::isfinite(fA.Tau) || !std::isfinite(fB.Tau))
  {
    PieceOutput out;
    out.Color = IntegrateSegment(h, fA, fB, model, SegmentMethod::Exact);
    return out;
  }
  Polynomial u;
  if (sB != sA)
  {
    u = ComposeAffine(s, tA, h);
    u.C[0] = 0.0; // u(0) = 0 exactly: s(tA) = sA up to the root's rounding
    const double inv = 1.0 / (sB - sA);
    for (int i = 1; i <= u.Degree; ++i)
    {
      u.C[i] *= inv;
    }
  }
  else
  {
    u = Polynomial::FromCoefficients({ 0.0, 1.0 }); // s constant: any monotone u
  }
  return detail::IntegrateSmoothPiece(
    fA, fB, u, u, h, transmitFront, budgetPerLength, emission, panelsLeft);
}

/// True if s' has no zero on [0, @p length]: the Bernstein coefficients of
/// s'(length y), y in [0, 1] (they enclose s' there), all of one sign by more
/// than their rounding. False says nothing (FindRoots decides).
bool ProvablyMonotone(const Polynomial& s, double length)
{
  const Polynomial d = ComposeAffine(Derivative(s), 0.0, length);
  const BernsteinPolynomial b = BernsteinFromMonomial(d);
  double lo = b.B[0], hi = b.B[0], scale = 0.0;
  for (int j = 1; j <= b.Degree; ++j)
  {
    lo = std::min(lo, b.B[j]);
    hi = std::max(hi, b.B[j]);
  }
  for (int k = 0; k <= d.Degree; ++k)
  {
    scale += std::abs(d.C[k]);
  }
  const double margin = 16.0 * (d.Degree + 2) * 2.220446049250313e-16 * scale;
  return std::isfinite(scale) && (lo > margin || hi < -margin);
}

/**
 * The pieces the exact walk would take over the runs from @p sRun[0] through
 * @p sRun[@p runs] if it is worth trying the sampled route first, else 0:
 * more than MaxPanels / 2 of them, and so many at smooth nodes
 * (TransferFunction::IsSmoothNode(), as in a table refined to a tight
 * GPU-compatible tolerance) that the others fit in the sampled route's pieces.
 */
long long PiecesWorthSampling(const TransferFunction& tf, const double* sRun, int runs, int maxPanels)
{
  const long long maxPieces = std::max(std::max(maxPanels, 1) / 2, 1);
  if (static_cast<long long>(runs) * (tf.GetNumberOfNodes() + 1) <= maxPieces)
  {
    return 0; // too few nodes for that many (the usual table: no walk)
  }
  long long all = runs, smooth = 0; // the extrema cut too
  for (int r = 0; r < runs; ++r)
  {
    for (BreakpointWalk w = BreakpointWalk::Of(tf, sRun[r], sRun[r + 1]); w.CrossesNode(); w.Next())
    {
      ++all;
      smooth += tf.IsSmoothNode(w.NodeIndex());
    }
  }
  // Worth it: more pieces than MaxPanels / 2, a budget of at least two
  // evaluations per sampled piece, and at most half of those pieces bounded
  // by nodes that are not smooth (or by extrema of s).
  const bool many = all > maxPieces && all / SampledBudgetDivisor >= 2 * SampledPieces;
  return many && all - smooth <= SampledPieces / 2 ? all : 0;
}

/**
 * The sampled route (file doc): IntegrateShadedPolynomial without shading
 * or gradient opacity, which steps over evenly spaced smooth crossings,
 * within @p panels panels.
 */
PolynomialSegmentResult IntegrateSampled(const TransferFunction& tf, const Polynomial& s,
  double length, const PolynomialSegmentSettings& settings, int panels)
{
  ShadedSegmentSettings sampled;
  sampled.Emission = settings.Emission;
  sampled.Tolerance = settings.Tolerance;
  sampled.MaxPanels = panels;
  sampled.MaxPieces = SampledPieces;
  sampled.StopWhenUnconverged = true; // then the exact walk
  const Polynomial noGradient[3] = {};
  const ShadedSegmentResult r = IntegrateShadedPolynomial(
    tf, s, noGradient, length, VolumeShadingSettings(), nullptr, SegmentRay(), sampled);
  PolynomialSegmentResult result;
  result.Color = r.Color;
  result.ErrorEstimate = r.ErrorEstimate;
  result.Panels = r.Panels;
  result.Pieces = r.Panels; // at least one panel per piece
  result.Converged = r.Converged;
  result.Sampled = true;
  return result;
}

/// Integrates the monotone runs of s front to back into Accum and Result.
struct RunWalker
{
  const TransferFunction& Table;
  const Polynomial& Field;
  bool Emission;
  double BudgetPerLength;
  int PanelsLeft;
  RGBA Accum;
  PolynomialSegmentResult& Result;

  /**
   * Run [t0, t1] on which s goes monotonically from @p sStart to @p sEnd:
   * walk the table's intervals (as IntegrateLinearScalar does), each node in
   * between crossed once. Returns false once the accumulation is opaque.
   */
  bool Walk(double t0, double t1, double sStart, double sEnd)
  {
    BreakpointWalk walk = BreakpointWalk::Of(this->Table, sStart, sEnd);
    double tPrev = t0, sPrev = sStart;
    while (true)
    {
      double sNext = sEnd, tNext = t1;
      const bool last = !walk.CrossesNode();
      if (!last)
      {
        sNext = walk.Node();
        tNext = std::min(std::max(SolveMonotone(this->Field, sNext, tPrev, t1), tPrev), t1);
      }
      if (tNext > tPrev)
      {
        const double transmit = 1.0 - this->Accum.A;
        const PieceOutput piece = IntegratePiece(this->Table, walk.Interval(), this->Field, tPrev,
          tNext - tPrev, sPrev, sNext, transmit, this->BudgetPerLength, this->Emission,
          this->PanelsLeft);
        this->Result.ErrorEstimate += transmit * piece.Error;
        this->Result.Panels += piece.Panels;
        this->Result.Converged = this->Result.Converged && piece.Converged;
        ++this->Result.Pieces;
        CompositeBehind(this->Accum, piece.Color);
        if (this->Accum.A >= 1.0)
        {
          return false;
        }
      }
      if (last)
      {
        return true;
      }
      tPrev = tNext;
      sPrev = sNext;
      walk.Next();
    }
  }
};
}

PolynomialSegmentResult IntegratePolynomialScalar(const TransferFunction& tf, const Polynomial& s,
  double length, const PolynomialSegmentSettings& settings)
{
  PolynomialSegmentResult result;
  if (!(length > 0.0) || !std::isfinite(length) || tf.GetNumberOfNodes() == 0)
  {
    return result;
  }
  for (int i = 0; i <= std::min(s.Degree, Polynomial::MaxDegree); ++i)
  {
    if (!std::isfinite(s.C[i]))
    {
      return result;
    }
  }
  const int degree = EffectiveDegree(s);
  if (degree <= 1)
  {
    IntegrationSettings linear;
    linear.Emission = settings.Emission;
    linear.Method = SegmentMethod::Exact;
    result.Color = IntegrateLinearScalar(tf, SnapToNode(tf, s.C[0]),
      SnapToNode(tf, Evaluate(s, length)), length, linear, &result.Pieces);
    return result;
  }
  if (degree > MaxFieldDegree)
  {
    result.Converged = false;
    return result;
  }
  Polynomial field = s;
  field.Degree = degree;
  RunWalker walker{ tf, field, settings.Emission == EmissionModel::WilhelmsVanGelder,
    std::max(settings.Tolerance, 0.0) / length, std::max(settings.MaxPanels, 1), RGBA(), result };

  // Runs where s is monotone: [0, L] cut at the extrema of s.
  double ends[Polynomial::MaxDegree + 2];
  int nEnds = 0;
  ends[nEnds++] = 0.0;
  if (degree == 2)
  {
    // The vertex -c1 / (2 c2): FindRoots on s' gives this same value (its
    // power-of-two scaling is exact) and drops it unless inside (0, L).
    const double vertex = -field.C[1] / (2.0 * field.C[2]);
    if (vertex > 0.0 && vertex < length)
    {
      ends[nEnds++] = vertex;
    }
  }
  else
  {
    double crit[Polynomial::MaxDegree];
    // Most pieces are monotone (the curved path's sub-pieces lie between
    // breakpoints): the Bernstein test proves it for O(n^2) operations.
    const int nCrit =
      ProvablyMonotone(field, length) ? 0 : FindRoots(Derivative(field), 0.0, 0.0, length, crit);
    for (int i = 0; i < nCrit; ++i)
    {
      if (crit[i] > ends[nEnds - 1] && crit[i] < length)
      {
        ends[nEnds++] = crit[i];
      }
    }
  }
  ends[nEnds++] = length;

  double sRun[Polynomial::MaxDegree + 2];
  // The sampled route (file doc) evaluates s by plain Horner and unrounded:
  // not tried if an end of a run lies within that rounding (or the snap) of
  // a node, where the two routes could put s on different sides of it, nor
  // for a tolerance that is not a positive number.
  double sRaw[Polynomial::MaxDegree + 2];
  sRaw[0] = field.C[0];
  sRun[0] = SnapToNode(tf, field.C[0]);
  for (int run = 0; run + 1 < nEnds; ++run)
  {
    sRaw[run + 1] = EvaluateCompensated(field, ends[run + 1]);
    sRun[run + 1] = SnapToNode(tf, sRaw[run + 1]);
  }
  const bool mayTrySampled = settings.Tolerance > 0.0 && std::isfinite(settings.Tolerance) &&
    sRun[0] == sRaw[0]; // at t = 0 both routes read C[0] exactly
  long long pieces = mayTrySampled ? PiecesWorthSampling(tf, sRun, nEnds - 1, settings.MaxPanels) : 0;
  for (int run = 1; pieces > 0 && run < nEnds; ++run)
  {
    if (NearNode(tf, sRaw[run], HornerBound(field, ends[run])))
    {
      pieces = 0;
    }
  }
  if (pieces > 0)
  {
    const int budget = static_cast<int>(
      std::min<long long>(pieces / SampledBudgetDivisor, std::max(settings.MaxPanels, 1)));
    const PolynomialSegmentResult sampled = IntegrateSampled(tf, field, length, settings, budget);
    if (sampled.Converged)
    {
      return sampled;
    }
  }
  for (int run = 0; run + 1 < nEnds; ++run)
  {
    if (!walker.Walk(ends[run], ends[run + 1], sRun[run], sRun[run + 1]))
    {
      break; // opaque: nothing behind is visible
    }
  }
  result.Color = walker.Accum;
  return result;
}

int IsovalueCrossings(const Polynomial& s, double length, const double* isovalues, int count,
  std::vector<IsovalueCrossing>& out)
{
  out.clear();
  if (!(length >= 0.0) || !std::isfinite(length) || !isovalues)
  {
    return 0;
  }
  // Sign of s - iso at t: 0 within the evaluation error.
  auto sign = [&s](double t, double iso) {
    double bound = 0.0;
    const double v = EvaluateCompensated(s, t, iso, &bound);
    return std::fabs(v) <= bound ? 0 : (v > 0.0 ? 1 : -1);
  };
  for (int i = 0; i < count; ++i)
  {
    double r[Polynomial::MaxDegree];
    const int nr = FindRoots(s, isovalues[i], 0.0, length, r);
    for (int j = 0; j < nr; ++j)
    {
      const bool hasBefore = j > 0 || r[j] > 0.0;
      const bool hasAfter = j + 1 < nr || r[j] < length;
      const int before = hasBefore ? sign(0.5 * ((j > 0 ? r[j - 1] : 0.0) + r[j]), isovalues[i]) : 0;
      const int after = hasAfter ? sign(0.5 * (r[j] + (j + 1 < nr ? r[j + 1] : length)), isovalues[i]) : 0;
      IsovalueCrossing c;
      c.T = r[j];
      c.Index = i;
      if (hasBefore && hasAfter)
      {
        c.Direction = before < 0 && after > 0 ? 1 : (before > 0 && after < 0 ? -1 : 0);
      }
      else
      {
        c.Direction = hasAfter ? after : -before;
      }
      out.push_back(c);
    }
  }
  std::sort(out.begin(), out.end(), [](const IsovalueCrossing& a, const IsovalueCrossing& b) {
    return a.T < b.T || (a.T == b.T && a.Index < b.Index);
  });
  return static_cast<int>(out.size());
}
}
