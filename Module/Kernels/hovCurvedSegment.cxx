// Segment categorization and the integral over a ray segment in a curved
// Lagrange cell: see hovCurvedSegment.h.
#include "hovCurvedSegment.h"

#include "hovCurvedSampling.h"      // the fixed-sample rules, RepresentCurvedField
#include "hovCurvedSegmentDetail.h"  // the shared parts
#include "hovLagrangeRestriction.h"  // the field along the affine cells' parametric line
#include "hovTransferFunction.h"

#include <algorithm> // std::lower_bound, std::upper_bound, std::min, std::max
#include <cmath>     // std::abs, std::sqrt

namespace hov
{
namespace
{
using detail::ValueAt;

double MaxColor(const SegmentEnd& v)
{
  return std::max(std::max(std::abs(v.Color[0]), std::abs(v.Color[1])), std::abs(v.Color[2]));
}

/// Remainder tolerance (relative to the field scale) of the first, coarse
/// categorization enclosure. The enclosure stays rigorous; coarser only means
/// a PS verdict may be conservative, which costs our breakpoint location a
/// Bernstein exclusion test per extra node (the field representation, not
/// the enclosure, is integrated). Taylor-model remainders are O(h^2), so
/// 1e-3 instead of 1e-6 needs ~30x fewer pieces on curved segments.
constexpr double CoarseEnclosureTolerance = 1e-3;

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
      detail::MayBeEmpty(tf, enc.Lo, enc.Hi, settings.Quadrature.Emission)))
  {
    enc = EncloseFieldOnSegment(
      cell, bounds, origin, direction, t0, t1, pcGuess, settings.Enclosure, &model);
    result.Class = CategorizeSegment(tf, enc.Lo, enc.Hi, settings.Quadrature.Emission);
  }
  return enc;
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
  if (detail::IntegrateConstantCell(cell, tf, direction, t0, t1, settings, result))
  {
    return result;
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
  const double length = (t1 - t0) *
    std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  const double fieldTarget =
    detail::FieldTarget(tf, enc.Lo, enc.Hi, bounds.FieldScale, length, settings);
  std::vector<FieldPiece> pieces;
  // The first Taylor model is on the whole segment; if it meets the field target
  // the geometry is affine (enough): the same test as RepresentFieldOnSegment's.
  if (model.size() == 1 && !model[0].Loose && model[0].Remainder <= fieldTarget)
  {
    FieldPiece p;
    p.T0 = t0;
    p.T1 = t1;
    p.G = model[0].Q;
    p.Error = model[0].Remainder;
    p.Exact = true;
    pieces.push_back(p);
  }
  else if (!detail::RepresentCurvedField(cell, bounds.FieldScale, fieldTarget, origin, direction,
             t0, t1, pcGuess, settings.MaxPieces, pieces))
  {
    result.Converged = false;
    return result;
  }
  detail::ClampOrderOneEnds(cell, pieces);
  if (settings.Method != CurvedQuadrature::LocatedBreakpoints)
  {
    for (const FieldPiece& p : pieces)
    {
      result.FieldError = std::max(result.FieldError, p.Error);
    }
    result.FieldPieces = static_cast<int>(pieces.size());
    result.ExactField = !pieces.empty() && pieces[0].Exact;
    const double speed = length / (t1 - t0);
    detail::IntegrateSampledSegment(tf, pieces,
      result.Class.Category == SegmentCategory::Smooth, t0, t1, speed, settings, result);
    return result;
  }
  detail::IntegrateRepresentedField(
    cell, tf, origin, direction, t0, t1, pieces, enc.Lo, enc.Hi, fieldTarget, settings, result);
  return result;
}

CurvedSegmentResult IntegrateCurvedSegment(const LagrangeCellView& cell, const CurvedCellInfo& info,
  const TransferFunction& tf, const double origin[3], const double direction[3], double t0,
  double t1, const double* pcGuess, const CurvedSegmentSettings& settings,
  const double* pcEndGuess)
{
  CurvedSegmentResult result;
  if (!(t1 > t0))
  {
    return result; // transparent
  }
  if (detail::IntegrateConstantCell(cell, tf, direction, t0, t1, settings, result))
  {
    return result;
  }
  const EmissionModel emission = settings.Quadrature.Emission;
  // The cell's rigorous hull decides what a segment enclosure would only
  // refine: E (nothing visible anywhere in the cell) is exact; where no zero
  // of the table lies in the hull no segment can be E, and the breakpoints are
  // located on the field representation itself (its own range selects the
  // table nodes), so the Taylor-model enclosure is needed only when the hull
  // holds a zero of the table (or for the sampled rules, which need E/PS/S).
  result.Class = CategorizeSegment(tf, info.FieldLo, info.FieldHi, emission);
  result.Lo = info.FieldLo;
  result.Hi = info.FieldHi;
  if (result.Class.Category == SegmentCategory::Empty)
  {
    return result; // empty-space skipping: exactly zero
  }
  if (settings.Method != CurvedQuadrature::LocatedBreakpoints ||
    (result.Class.Category == SegmentCategory::PiecewiseSmooth &&
      detail::MayBeEmpty(tf, info.FieldLo, info.FieldHi, emission)))
  {
    return IntegrateCurvedSegment(
      cell, info.Bounds(), tf, origin, direction, t0, t1, pcGuess, settings);
  }
  const double length = (t1 - t0) *
    std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  const double fieldTarget =
    detail::FieldTarget(tf, info.FieldLo, info.FieldHi, info.FieldScale, length, settings);
  std::vector<FieldPiece> pieces;
  if (info.Affine)
  {
    // pc(t) = InverseJ (o + t d - X0): the field along the segment is exactly
    // the cell's polynomial on that parametric line.
    FieldPiece p;
    double start[3], step[3];
    for (int i = 0; i < 3; ++i)
    {
      const double* row = info.InverseJ + 3 * i;
      const double a[3] = { origin[0] + t0 * direction[0] - info.X0[0],
        origin[1] + t0 * direction[1] - info.X0[1], origin[2] + t0 * direction[2] - info.X0[2] };
      start[i] = row[0] * a[0] + row[1] * a[1] + row[2] * a[2];
      step[i] = (t1 - t0) * (row[0] * direction[0] + row[1] * direction[1] + row[2] * direction[2]);
    }
    double rounding = 0.0;
    if (!LagrangeFieldAlongLine(*cell.Basis, cell.Scalars, start, step, p.G, &rounding))
    {
      result.Converged = false;
      return result;
    }
    p.T0 = t0;
    p.T1 = t1;
    p.Error = rounding;
    p.Exact = true;
    pieces.push_back(p);
  }
  else if (!detail::RepresentCurvedField(cell, info.FieldScale, fieldTarget, origin, direction, t0,
             t1, pcGuess, settings.MaxPieces, pieces, pcEndGuess))
  {
    result.Converged = false;
    return result;
  }
  detail::ClampOrderOneEnds(cell, pieces);
  // The segment's range from its pieces (within the cell's hull), and the
  // table nodes in it.
  double lo = 1e300, hi = -1e300;
  for (const FieldPiece& p : pieces)
  {
    double a, b;
    BernsteinRange(p.G, a, b);
    lo = std::min(lo, a - p.Error);
    hi = std::max(hi, b + p.Error);
  }
  lo = std::max(lo, info.FieldLo);
  hi = std::min(hi, info.FieldHi);
  if (lo <= hi)
  {
    result.Lo = lo;
    result.Hi = hi;
    result.Class = CategorizeSegment(tf, lo, hi, emission);
  }
  detail::IntegrateRepresentedField(
    cell, tf, origin, direction, t0, t1, pieces, result.Lo, result.Hi, fieldTarget, settings, result);
  return result;
}
}
