// The blend modes of the curved ray caster: CurvedRayCaster::TraceRayBlend
// (see hovCurvedRayCaster.h and hovBlendModes.h).
#include "hovCurvedRayCaster.h"

#include "hovBernstein.h"  // ApproximateBernstein, SubdivideBernstein
#include "hovPolynomial.h" // ComposeAffine

#include <algorithm> // std::max
#include <cmath>     // std::sqrt

namespace hov
{
namespace
{
/// Bisections of a field piece at most while its degree-8 approximation's
/// bound exceeds the field tolerance (the composite path's depth).
constexpr int MaxBlendBisections = 8;

/// Field piece G on ray parameters [a, b] (speed |d|) into @p state, with the
/// piece's own error @p error (see TraceRayBlend).
void AccumulatePiece(RayBlendState& state, const BlendSettings& blend,
  const TransferFunction& table, const BernsteinPolynomial& g, double a, double b, double speed,
  double error, double tolerance, int depth)
{
  double bound = 0.0;
  const Polynomial q = ApproximateBernstein(g, 8, bound);
  if (bound > tolerance && depth > 0)
  {
    BernsteinPolynomial left, right;
    SubdivideBernstein(g, 0.5, &left, &right);
    const double mid = 0.5 * (a + b);
    AccumulatePiece(state, blend, table, left, a, mid, speed, error, tolerance, depth - 1);
    AccumulatePiece(state, blend, table, right, mid, b, speed, error, tolerance, depth - 1);
    return;
  }
  // In the world length along the ray, tau = (t - a) |d|, in [0, h].
  const double h = (b - a) * speed;
  if (!(h > 0.0))
  {
    return;
  }
  Polynomial s = ComposeAffine(q, 0.0, 1.0 / h);
  s.Degree = q.Degree;
  AccumulatePolynomialSegment(state, blend, table, a * speed, h, s, error + bound);
}

/// The constant value of @p cell if all its node scalars are equal.
bool ConstantCell(const LagrangeCellView& cell, double& value)
{
  if (!cell.Scalars || !cell.Basis)
  {
    return false;
  }
  const int n = cell.Basis->GetNodeCount();
  value = cell.Scalars[0];
  for (int i = 1; i < n; ++i)
  {
    if (cell.Scalars[i] != value)
    {
      return false;
    }
  }
  return n > 0;
}
}

void CurvedRayCaster::TraceRayBlend(const double origin[3], const double direction[3],
  double tMin, double tMax, const TransferFunction& table, const BlendSettings& blend,
  const CurvedSegmentSettings& settings, RayBlendState& state, CurvedRayStats* stats) const
{
  CurvedRayStats st;
  std::vector<Segment> segments;
  this->CollectSegments(origin, direction, tMin, tMax, segments, st);
  const double speed =
    std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  std::vector<FieldPiece> pieces;
  for (const Segment& seg : segments)
  {
    const Cell& cell = this->Cells[seg.Cell];
    const LagrangeCellView view = this->View(cell);
    ++st.Segments;
    double value = 0.0;
    if (ConstantCell(view, value))
    {
      // Exact: no restriction at all (cell scalars).
      AccumulateLinearSegment(
        state, blend, table, seg.T0 * speed, (seg.T1 - seg.T0) * speed, value, value);
      continue;
    }
    const CellDerivativeBounds& bounds = this->CellBounds(cell);
    if (!RepresentFieldOnSegment(
          view, bounds, origin, direction, seg.T0, seg.T1, seg.PC0, settings, pieces))
    {
      st.Converged = false; // what was represented is used
    }
    const double tolerance = settings.FieldTolerance * bounds.FieldScale;
    for (const FieldPiece& p : pieces)
    {
      AccumulatePiece(state, blend, table, p.G, p.T0, p.T1, speed, p.Error, tolerance,
        MaxBlendBisections);
    }
  }
  st.TolerancePasses = 1;
  if (stats)
  {
    *stats = st;
  }
}
}
