// Segment categorization and the integral over a ray segment in a curved
// Lagrange cell: see hovCurvedSegment.h.
#include "hovCurvedSegment.h"

#include "hovCurvedSampling.h" // the fixed-sample rules
#include "hovTransferFunction.h"

#include <algorithm> // std::lower_bound, std::upper_bound, std::sort
#include <cmath>     // std::abs, std::isfinite, std::sqrt

namespace hov
{
namespace
{
/// Remainder tolerance (relative to the field scale) of the first, coarse
/// categorization enclosure. The enclosure stays rigorous; coarser only means
/// a PS verdict may be conservative, which costs our breakpoint location a
/// Bernstein exclusion test per extra node (the field representation, not
/// the enclosure, is integrated). Taylor-model remainders are O(h^2), so
/// 1e-3 instead of 1e-6 needs ~30x fewer pieces on curved segments.
constexpr double CoarseEnclosureTolerance = 1e-3;

/// Table values at s (Find + Evaluate).
SegmentEnd ValueAt(const TransferFunction& tf, double s, bool emission)
{
  SegmentEnd v;
  tf.Evaluate(tf.FindIntervalUpward(s), s, emission, v);
  return v;
}

double MaxColor(const SegmentEnd& v)
{
  return std::max(std::max(std::abs(v.Color[0]), std::abs(v.Color[1])), std::abs(v.Color[2]));
}

/// True if the table's extinction (and, WVG, emission) is 0 somewhere on
/// [lo, hi]: at lo, hi or a node (one-sided values), since it is linear between nodes.
bool MayBeEmpty(const TransferFunction& tf, double lo, double hi, EmissionModel emission)
{
  const bool wvg = emission == EmissionModel::WilhelmsVanGelder;
  auto zero = [&](const SegmentEnd& v) { return v.Tau == 0.0 && (!wvg || MaxColor(v) == 0.0); };
  if (zero(ValueAt(tf, lo, wvg)) || zero(ValueAt(tf, hi, wvg)))
  {
    return true;
  }
  // Only the nodes in [lo, hi] (binary search: the cost does not grow with
  // the nodes outside the segment's range).
  const std::vector<double>& x = tf.GetNodes();
  const auto last = std::upper_bound(x.begin(), x.end(), hi);
  for (auto it = std::lower_bound(x.begin(), x.end(), lo); it < last; ++it)
  {
    SegmentEnd down;
    tf.Evaluate(tf.FindIntervalDownward(*it), *it, wvg, down);
    if (zero(ValueAt(tf, *it, wvg)) || zero(down))
    {
      return true;
    }
  }
  return false;
}

/// Largest |value|s and slopes d/ds of the table on [lo, hi] (jumps skipped).
struct TableSensitivity
{
  double TauMax = 0.0, ColorMax = 0.0, TauSlope = 0.0, ColorSlope = 0.0;
  /// Infinite extinction somewhere (an opaque medium: opacity 1 in
  /// GPU-compatible semantics); TauMax and TauSlope cover the finite values.
  bool Opaque = false;
};

TableSensitivity Sensitivity(const TransferFunction& tf, double lo, double hi, bool emission)
{
  TableSensitivity s;
  const std::vector<double>& x = tf.GetNodes();
  // lo, the nodes strictly inside (lo, hi) found by binary search, hi: sorted.
  std::vector<double> points{ lo };
  if (lo < hi)
  {
    const auto first = std::upper_bound(x.begin(), x.end(), lo);
    const auto last = std::lower_bound(first, x.end(), hi);
    points.insert(points.end(), first, last);
  }
  points.push_back(hi);
  std::sort(points.begin(), points.end());
  for (size_t i = 0; i < points.size(); ++i)
  {
    const SegmentEnd v = ValueAt(tf, points[i], emission);
    if (std::isfinite(v.Tau))
    {
      s.TauMax = std::max(s.TauMax, std::abs(v.Tau));
    }
    else
    {
      s.Opaque = true;
    }
    s.ColorMax = std::max(s.ColorMax, MaxColor(v));
    if (i + 1 < points.size() && points[i + 1] > points[i])
    {
      // Slope of the linear piece between consecutive points (inside one interval).
      const double a = points[i], b = points[i + 1], m = 0.5 * (a + b);
      SegmentEnd va, vb;
      const int k = tf.FindIntervalUpward(m);
      tf.Evaluate(k, a, emission, va);
      tf.Evaluate(k, b, emission, vb);
      if (std::isfinite(va.Tau) && std::isfinite(vb.Tau))
      {
        s.TauSlope = std::max(s.TauSlope, std::abs(vb.Tau - va.Tau) / (b - a));
      }
      for (int c = 0; c < 3; ++c)
      {
        s.ColorSlope = std::max(s.ColorSlope, std::abs(vb.Color[c] - va.Color[c]) / (b - a));
      }
    }
  }
  return s;
}

/// Integrate one sub-piece G on [a, b] (smooth for the table up to the field
/// error): degree-<=8 approximants (bisected while their bound exceeds the
/// tolerance, at most @p depth times), each by IntegratePolynomialScalar;
/// @p speed = |d| converts ray parameter to length.
void IntegrateSubPiece(const TransferFunction& tf, const BernsteinPolynomial& g, double a, double b,
  double speed, double tolerance, int depth, const CurvedSegmentSettings& settings,
  CurvedSegmentResult& result)
{
  double bound = 0.0;
  const Polynomial q = ApproximateBernstein(g, 8, bound);
  if (bound > tolerance && depth > 0)
  {
    BernsteinPolynomial left, right;
    SubdivideBernstein(g, 0.5, &left, &right);
    const double mid = 0.5 * (a + b);
    IntegrateSubPiece(tf, left, a, mid, speed, tolerance, depth - 1, settings, result);
    IntegrateSubPiece(tf, right, mid, b, speed, tolerance, depth - 1, settings, result);
    return;
  }
  result.FieldError = std::max(result.FieldError, bound);
  // In the world length along the ray, tau = (t - a) |d|, in [0, h].
  const double h = (b - a) * speed;
  Polynomial s = ComposeAffine(q, 0.0, 1.0 / h);
  s.Degree = q.Degree;
  const PolynomialSegmentResult r = IntegratePolynomialScalar(tf, s, h, settings.Quadrature);
  result.ErrorEstimate += (1.0 - result.Color.A) * r.ErrorEstimate;
  result.Converged = result.Converged && r.Converged;
  CompositeBehind(result.Color, r.Color);
  ++result.Pieces;
}
/// Order-1 cells (linear tetrahedra and wedges, trilinear hexahedra) have
/// non-negative shape functions: their field stays within the node values.
/// The pieces' end values (first and last Bernstein coefficients) are clamped
/// to that range, so that rounding (an interval end a hair outside the cell,
/// where the field extrapolates) cannot carry the field past a table node at
/// the range's end: with opacity 1 there (GPU-compatible semantics) that would
/// be an opaque medium.
void ClampOrderOneEnds(const LagrangeCellView& cell, std::vector<FieldPiece>& pieces)
{
  if (!cell.Basis || !cell.Scalars)
  {
    return;
  }
  const int* order = cell.Basis->GetOrder();
  if (order[0] != 1 || order[1] != 1 || order[2] != 1)
  {
    return;
  }
  double lo = cell.Scalars[0], hi = cell.Scalars[0];
  for (int i = 1; i < cell.Basis->GetNodeCount(); ++i)
  {
    lo = std::min(lo, cell.Scalars[i]);
    hi = std::max(hi, cell.Scalars[i]);
  }
  for (FieldPiece& p : pieces)
  {
    double& a = p.G.B[0];
    double& b = p.G.B[p.G.Degree];
    a = std::min(std::max(a, lo), hi);
    b = std::min(std::max(b, lo), hi);
  }
}

/// The categorization enclosure in two stages (see hovCurvedSegment.h); sets
/// result.Class, fills @p model with the Taylor models.
FieldEnclosure TwoStageEnclosure(const LagrangeCellView& cell, const CellDerivativeBounds& bounds,
  const TransferFunction& tf, const double origin[3], const double direction[3], double t0,
  double t1, const double* pcGuess, const CurvedSegmentSettings& settings,
  std::vector<EnclosurePiece>& model, CurvedSegmentResult& result)
{
  // Stage 1: a coarse rigorous enclosure (see CoarseEnclosureTolerance).
  EnclosureSettings coarse = settings.Enclosure;
  coarse.RemainderTolerance = std::max(coarse.RemainderTolerance, CoarseEnclosureTolerance);
  FieldEnclosure enc =
    EncloseFieldOnSegment(cell, bounds, origin, direction, t0, t1, pcGuess, coarse, &model);
  if (!enc.Valid)
  {
    return enc;
  }
  result.Class = CategorizeSegment(tf, enc.Lo, enc.Hi, settings.Quadrature.Emission);
  // Stage 2: the requested tolerance, only where a tighter range can change what is
  // done: a PS verdict that may turn E (a zero of the table in the range), or S (ElVis).
  if (result.Class.Category == SegmentCategory::PiecewiseSmooth &&
    coarse.RemainderTolerance > settings.Enclosure.RemainderTolerance &&
    (settings.Method == CurvedQuadrature::ElVis ||
      MayBeEmpty(tf, enc.Lo, enc.Hi, settings.Quadrature.Emission)))
  {
    enc = EncloseFieldOnSegment(
      cell, bounds, origin, direction, t0, t1, pcGuess, settings.Enclosure, &model);
    result.Class = CategorizeSegment(tf, enc.Lo, enc.Hi, settings.Quadrature.Emission);
  }
  return enc;
}

/// One smooth piece of the field between located breakpoints.
struct SubPiece
{
  BernsteinPolynomial G;
  double A, B;
};

/// The field pieces cut at every located crossing of the table nodes of result.Class.
std::vector<SubPiece> CutAtBreakpoints(const LagrangeCellView& cell, const double origin[3],
  const double direction[3], const TransferFunction& tf, const std::vector<FieldPiece>& pieces,
  CurvedSegmentResult& result)
{
  const std::vector<double>& nodes = tf.GetNodes();
  std::vector<double> cuts;
  std::vector<SubPiece> subs;
  for (const FieldPiece& p : pieces)
  {
    cuts.assign({ p.T0, p.T1 });
    for (int k = 0; k < result.Class.NodeCount; ++k)
    {
      const double level = nodes[result.Class.FirstNode + k];
      if (k > 0 && level == nodes[result.Class.FirstNode + k - 1])
      {
        continue; // a jump: one location
      }
      result.Breakpoints += LocateBreakpoints(cell, origin, direction, p, level, cuts);
    }
    std::sort(cuts.begin(), cuts.end());
    const double h = p.T1 - p.T0;
    for (size_t i = 0; i + 1 < cuts.size(); ++i)
    {
      const double a = std::max(cuts[i], p.T0), b = std::min(cuts[i + 1], p.T1);
      if (b > a)
      {
        subs.push_back({ RestrictBernstein(p.G, (a - p.T0) / h, (b - p.T0) / h), a, b });
      }
    }
  }
  return subs;
}
}

SegmentClassification CategorizeSegment(
  const TransferFunction& tf, double lo, double hi, EmissionModel emission)
{
  SegmentClassification c;
  const std::vector<double>& x = tf.GetNodes();
  if (x.empty() || !(lo <= hi))
  {
    return c; // nothing to render: Empty
  }
  const auto first = std::lower_bound(x.begin(), x.end(), lo);
  const auto last = std::upper_bound(x.begin(), x.end(), hi);
  c.FirstNode = static_cast<int>(first - x.begin());
  c.NodeCount = static_cast<int>(last - first);
  // The table is linear between nodes: its extremes on [lo, hi] are at lo, hi and the nodes.
  const bool wvg = emission == EmissionModel::WilhelmsVanGelder;
  bool anyTau = false, anyColor = false;
  auto visit = [&](double s) {
    const SegmentEnd v = ValueAt(tf, s, wvg);
    anyTau = anyTau || v.Tau != 0.0;
    anyColor = anyColor || MaxColor(v) != 0.0;
  };
  visit(lo);
  visit(hi);
  for (auto it = first; it != last; ++it)
  {
    // Both one-sided values at a node (a jump has two nodes at one X).
    visit(*it);
    SegmentEnd v;
    tf.Evaluate(tf.FindIntervalDownward(*it), *it, wvg, v);
    anyTau = anyTau || v.Tau != 0.0;
    anyColor = anyColor || MaxColor(v) != 0.0;
  }
  const bool empty = !anyTau && (!wvg || !anyColor);
  c.Category = empty          ? SegmentCategory::Empty
    : c.NodeCount > 0         ? SegmentCategory::PiecewiseSmooth
                              : SegmentCategory::Smooth;
  c.OcclusionOnly = anyTau && !anyColor;
  return c;
}

CurvedSegmentResult IntegrateCurvedSegment(const LagrangeCellView& cell,
  const CellDerivativeBounds& bounds, const TransferFunction& tf, const double origin[3],
  const double direction[3], double t0, double t1, const double* pcGuess,
  const CurvedSegmentSettings& settings)
{
  CurvedSegmentResult result;
  if (!(t1 > t0))
  {
    return result; // transparent
  }
  // A cell whose node scalars are all equal carries that constant exactly
  // (partition of unity); interpolating it would round it (1 - 1e-16), which
  // matters where the table is singular: opacity 1 at a node in GPU-compatible
  // semantics is an opaque medium at the node and a finite (clamped)
  // extinction just below it. The segment then has one exact table value.
  if (cell.Scalars && cell.Basis)
  {
    const int n = cell.Basis->GetNodeCount();
    const double c = cell.Scalars[0];
    bool constant = n > 0 && std::isfinite(c);
    for (int i = 1; constant && i < n; ++i)
    {
      constant = cell.Scalars[i] == c;
    }
    if (constant)
    {
      const EmissionModel model = settings.Quadrature.Emission;
      result.Lo = result.Hi = c;
      result.Class = CategorizeSegment(tf, c, c, model);
      result.ExactField = true;
      if (result.Class.Category != SegmentCategory::Empty)
      {
        const SegmentEnd v = ValueAt(tf, c, model == EmissionModel::WilhelmsVanGelder);
        const double length = (t1 - t0) * std::sqrt(direction[0] * direction[0] +
                                            direction[1] * direction[1] + direction[2] * direction[2]);
        result.Color = IntegrateSegment(length, v, v, model, SegmentMethod::Exact);
        result.Pieces = 1;
      }
      return result;
    }
  }
  std::vector<EnclosurePiece> model;
  const FieldEnclosure enc =
    TwoStageEnclosure(cell, bounds, tf, origin, direction, t0, t1, pcGuess, settings, model, result);
  if (!enc.Valid)
  {
    return result; // transparent
  }
  result.Lo = enc.Lo;
  result.Hi = enc.Hi;
  if (result.Class.Category == SegmentCategory::Empty)
  {
    return result; // empty-space skipping: exactly zero
  }
  std::vector<FieldPiece> pieces;
  // The first Taylor model is on the whole segment; if it meets the field tolerance
  // the geometry is affine (enough): the same test as RepresentFieldOnSegment's.
  const double fieldTolerance = settings.FieldTolerance * bounds.FieldScale;
  if (model.size() == 1 && !model[0].Loose && model[0].Remainder <= fieldTolerance)
  {
    FieldPiece p;
    p.T0 = t0;
    p.T1 = t1;
    p.G = model[0].Q;
    p.Error = model[0].Remainder;
    p.Exact = true;
    pieces.push_back(p);
  }
  else if (!detail::RepresentCurvedField(
             cell, bounds, origin, direction, t0, t1, pcGuess, settings, pieces))
  {
    result.Converged = false;
    return result;
  }
  ClampOrderOneEnds(cell, pieces);
  result.FieldPieces = static_cast<int>(pieces.size());
  result.ExactField = !pieces.empty() && pieces[0].Exact;
  const double tolerance = settings.FieldTolerance * bounds.FieldScale;
  const double speed =
    std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for (const FieldPiece& p : pieces)
  {
    result.FieldError = std::max(result.FieldError, p.Error);
  }
  if (settings.Method != CurvedQuadrature::LocatedBreakpoints)
  {
    detail::IntegrateSampledSegment(tf, pieces,
      result.Class.Category == SegmentCategory::Smooth, t0, t1, speed, settings, result);
    return result;
  }
  const std::vector<SubPiece> subs = CutAtBreakpoints(cell, origin, direction, tf, pieces, result);
  const bool emission = settings.Quadrature.Emission == EmissionModel::WilhelmsVanGelder;
  for (const SubPiece& sp : subs)
  {
    if (settings.Samples > 0)
    {
      // Fixed rule: half the segment's nodes shared equally among the pieces, half by
      // length (so every piece's rule refines with Samples: spectral convergence even
      // on the short pieces next to a near-tangent breakpoint), at least one each.
      const double share = 0.5 * settings.Samples / static_cast<double>(subs.size()) +
        0.5 * settings.Samples * (sp.B - sp.A) / (t1 - t0);
      const int m = std::max(1, static_cast<int>(std::lround(share)));
      detail::IntegrateSubPieceFixed(tf, sp.G, sp.A, sp.B, speed, m, emission, result);
    }
    else
    {
      IntegrateSubPiece(tf, sp.G, sp.A, sp.B, speed, tolerance, 8, settings, result);
    }
  }
  // Field-error contribution (see file doc), on the range widened by the error.
  const TableSensitivity s = Sensitivity(tf, enc.Lo - result.FieldError, enc.Hi + result.FieldError,
    settings.Quadrature.Emission == EmissionModel::WilhelmsVanGelder);
  // An opaque medium ends the ray where it starts: a field error e moves that
  // point, and the colour there changes by at most ColorSlope e.
  const double length = (t1 - t0) * speed;
  if (result.FieldError > 0.0)
  {
    result.FieldErrorEstimate =
      (length * (s.ColorSlope * s.TauMax + s.ColorMax * s.TauSlope) + (s.Opaque ? s.ColorSlope : 0.0)) *
      result.FieldError;
    result.ErrorEstimate += result.FieldErrorEstimate;
  }
  return result;
}
}
