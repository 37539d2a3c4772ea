// The parts of IntegrateCurvedSegment: see hovCurvedSegmentDetail.h.
#include "hovCurvedSegmentDetail.h"

#include "hovCurvedSampling.h"   // IntegrateSubPieceFixed
#include "hovTransferFunction.h" // table values and nodes

#include <algorithm> // std::lower_bound, std::upper_bound, std::sort
#include <cmath>     // std::abs, std::isfinite, std::sqrt, std::lround

namespace hov
{
namespace detail
{
namespace
{
double MaxColor(const SegmentEnd& v)
{
  return std::max(std::max(std::abs(v.Color[0]), std::abs(v.Color[1])), std::abs(v.Color[2]));
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

SegmentEnd ValueAt(const TransferFunction& tf, double s, bool emission)
{
  SegmentEnd v;
  tf.Evaluate(tf.FindIntervalUpward(s), s, emission, v);
  return v;
}

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

double FieldTarget(const TransferFunction& tf, double lo, double hi, double scale, double length,
  const CurvedSegmentSettings& settings)
{
  const double floor = settings.FieldTolerance * scale;
  const double share = settings.FieldErrorShare * settings.Quadrature.Tolerance;
  // Only the adaptive rule budgets its error (the fixed-sample rules serve
  // convergence studies: their field stays at FieldTolerance).
  if (!(share > 0.0) || !(lo <= hi) || settings.Method != CurvedQuadrature::LocatedBreakpoints ||
    settings.Samples > 0)
  {
    return floor;
  }
  // Never looser than share x scale: a table jump (two nodes at one s) located
  // off by e/|g'| changes the pixel by about jump x e / scale (not in the
  // sensitivity, which skips jumps).
  const double cap = share * scale;
  const TableSensitivity s = Sensitivity(
    tf, lo, hi, settings.Quadrature.Emission == EmissionModel::WilhelmsVanGelder);
  const double budgetLength = settings.FieldBudgetLength > 0.0 ? settings.FieldBudgetLength : length;
  const double perField = budgetLength * (s.ColorSlope * s.TauMax + s.ColorMax * s.TauSlope) +
    (s.Opaque ? s.ColorSlope : 0.0);
  const double target = perField > 0.0 ? std::min(share / perField, cap) : cap;
  return std::max(floor, target);
}

bool IntegrateConstantCell(const LagrangeCellView& cell, const TransferFunction& tf,
  const double direction[3], double t0, double t1, const CurvedSegmentSettings& settings,
  CurvedSegmentResult& result)
{
  // A cell whose node scalars are all equal carries that constant exactly
  // (partition of unity); interpolating it would round it (1 - 1e-16), which
  // matters where the table is singular: opacity 1 at a node in GPU-compatible
  // semantics is an opaque medium at the node and a finite (clamped)
  // extinction just below it. The segment then has one exact table value.
  if (!cell.Scalars || !cell.Basis)
  {
    return false;
  }
  const int n = cell.Basis->GetNodeCount();
  const double c = cell.Scalars[0];
  bool constant = n > 0 && std::isfinite(c);
  for (int i = 1; constant && i < n; ++i)
  {
    constant = cell.Scalars[i] == c;
  }
  if (!constant)
  {
    return false;
  }
  const EmissionModel model = settings.Quadrature.Emission;
  result.Lo = result.Hi = c;
  result.Class = CategorizeSegment(tf, c, c, model);
  result.ExactField = true;
  if (result.Class.Category != SegmentCategory::Empty)
  {
    const SegmentEnd v = ValueAt(tf, c, model == EmissionModel::WilhelmsVanGelder);
    const double length = (t1 - t0) *
      std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
    result.Color = IntegrateSegment(length, v, v, model, SegmentMethod::Exact);
    result.Pieces = 1;
  }
  return true;
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

void IntegrateRepresentedField(const LagrangeCellView& cell, const TransferFunction& tf,
  const double origin[3], const double direction[3], double t0, double t1,
  const std::vector<FieldPiece>& pieces, double lo, double hi, double fieldTarget,
  const CurvedSegmentSettings& settings, CurvedSegmentResult& result)
{
  result.FieldPieces = static_cast<int>(pieces.size());
  result.ExactField = !pieces.empty() && pieces[0].Exact;
  const double speed =
    std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for (const FieldPiece& p : pieces)
  {
    result.FieldError = std::max(result.FieldError, p.Error);
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
      IntegrateSubPieceFixed(tf, sp.G, sp.A, sp.B, speed, m, emission, result);
    }
    else
    {
      IntegrateSubPiece(tf, sp.G, sp.A, sp.B, speed, fieldTarget, 8, settings, result);
    }
  }
  // Field-error contribution (see file doc), on the range widened by the error.
  const TableSensitivity s =
    Sensitivity(tf, lo - result.FieldError, hi + result.FieldError, emission);
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
}
}
}
