// The per-cell set-up of hov::CurvedRayCaster (see hovCurvedRayCaster.h):
// affine detection and the affine cells' exact ray intervals, the field hull
// that categorises segments, and the lazily built derivative bounds. Split
// from hovCurvedRayCaster.cxx (the BVH, the segment collection and TraceRay).
#include "hovCurvedRayCaster.h"

#include "hovCurvedRayCell.h"

#include <algorithm> // std::min, std::max
#include <cmath>     // std::abs, std::isfinite
#include <mutex>     // std::call_once

namespace hov
{
namespace
{
/// A cell is affine if every node lies within this x extent of the affine map
/// through its unit points (far below any visible effect, far above rounding).
constexpr double AffineTolerance = 1e-12;
}

void CurvedRayCaster::DetectAffine(Cell& cell) const
{
  cell.Affine = false;
  const LagrangeBasis& basis = this->Bases[cell.Basis];
  const LagrangeCellView view{ &basis, cell.Points.data(), cell.Scalars.data() };
  // x0 = x(0) and the columns of J from the unit points (vertices of every shape).
  double J[9];
  const double zero[3] = { 0.0, 0.0, 0.0 };
  EvaluateLagrangePosition(view, zero, cell.X0);
  for (int k = 0; k < 3; ++k)
  {
    double e[3] = { 0.0, 0.0, 0.0 }, x[3];
    e[k] = 1.0;
    EvaluateLagrangePosition(view, e, x);
    for (int i = 0; i < 3; ++i)
    {
      J[3 * i + k] = x[i] - cell.X0[i];
    }
  }
  // Every node on the map (to AffineTolerance x extent): the interpolant IS the map.
  const double tol = AffineTolerance * cell.Faces.Extent;
  for (int n = 0; n < basis.GetNodeCount(); ++n)
  {
    double pc[3];
    basis.NodeParametricCoords(n, pc);
    for (int i = 0; i < 3; ++i)
    {
      const double x = cell.X0[i] + J[3 * i] * pc[0] + J[3 * i + 1] * pc[1] + J[3 * i + 2] * pc[2];
      if (!(std::abs(x - cell.Points[3 * n + i]) <= tol))
      {
        return;
      }
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    const double e[3] = { k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0 };
    double col[3];
    if (!Solve3x3(J, e, col, 1e-10))
    {
      return; // (nearly) degenerate: keep the general path
    }
    for (int i = 0; i < 3; ++i)
    {
      cell.InverseJ[3 * i + k] = col[i];
    }
  }
  cell.Affine = true;
}

int CurvedRayCaster::AffineInterval(const Cell& cell, const double o[3], const double d[3],
  double t0, double t1, double& ta, double& tb, double pc[3]) const
{
  // pc(t) = p0 + t v; each face g(pc) = g0 + t g1 >= 0 bounds t on one side.
  double p0[3], v[3];
  for (int i = 0; i < 3; ++i)
  {
    const double* row = cell.InverseJ + 3 * i;
    p0[i] = row[0] * (o[0] - cell.X0[0]) + row[1] * (o[1] - cell.X0[1]) + row[2] * (o[2] - cell.X0[2]);
    v[i] = row[0] * d[0] + row[1] * d[1] + row[2] * d[2];
  }
  ta = t0;
  tb = t1;
  auto clip = [&](double g0, double g1) {
    if (g1 == 0.0)
    {
      if (g0 < 0.0)
      {
        tb = -1e300; // parallel and outside
      }
      return;
    }
    const double t = -g0 / g1;
    if (g1 > 0.0)
    {
      ta = std::max(ta, t);
    }
    else
    {
      tb = std::min(tb, t);
    }
  };
  const LagrangeShape shape = this->Bases[cell.Basis].GetShape();
  for (int k = 0; k < 3; ++k)
  {
    clip(p0[k], v[k]); // pc_k >= 0
    if (shape == LagrangeShape::Hexahedron || (shape == LagrangeShape::Wedge && k == 2))
    {
      clip(1.0 - p0[k], -v[k]); // pc_k <= 1
    }
  }
  if (shape == LagrangeShape::Tetra)
  {
    clip(1.0 - p0[0] - p0[1] - p0[2], -(v[0] + v[1] + v[2]));
  }
  else if (shape == LagrangeShape::Wedge)
  {
    clip(1.0 - p0[0] - p0[1], -(v[0] + v[1]));
  }
  if (!(tb > ta))
  {
    return 0;
  }
  for (int i = 0; i < 3; ++i)
  {
    pc[i] = p0[i] + ta * v[i];
  }
  return 1;
}

void CurvedRayCaster::FieldHull(Cell& cell) const
{
  const LagrangeBasis& basis = this->Bases[cell.Basis];
  const int n = basis.GetNodeCount();
  double lo = cell.Scalars[0], hi = cell.Scalars[0], maxAbs = 0.0;
  for (int i = 0; i < n; ++i)
  {
    lo = std::min(lo, cell.Scalars[i]);
    hi = std::max(hi, cell.Scalars[i]);
    maxAbs = std::max(maxAbs, std::abs(cell.Scalars[i]));
  }
  // The same scale as ComputeCellDerivativeBounds.
  cell.FieldScale = hi > lo ? hi - lo : (maxAbs > 0.0 ? maxAbs : 1.0);
  const LagrangeHull& hull = this->Hulls[cell.Basis];
  if (hull.IsInitialized())
  {
    hull.Hull(cell.Scalars.data(), cell.FieldLo, cell.FieldHi);
    return;
  }
  const CellDerivativeBounds& bounds = this->CellBounds(cell);
  cell.FieldLo = bounds.Valid ? bounds.FieldMin : -1e300;
  cell.FieldHi = bounds.Valid ? bounds.FieldMax : 1e300;
}

const CellDerivativeBounds& CurvedRayCaster::CellBounds(const Cell& cell) const
{
  std::call_once(*cell.BoundsOnce, [&]() {
    const LagrangeCellView view = this->View(cell);
    ComputeCellDerivativeBounds(view, cell.Bounds);
  });
  return cell.Bounds;
}
}
