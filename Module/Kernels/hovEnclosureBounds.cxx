// Second-derivative bounds of Lagrange cells over their widened parametric
// domain (CellDerivativeBounds): see hovEnclosure.h.
#include "hovEnclosure.h"

#include "hovBernstein.h" // equispaced Lagrange -> Bernstein

#include <algorithm> // std::min, std::max
#include <cmath>     // std::abs

namespace hov
{
namespace
{
/// Relative inflation of the derivative bounds: the equispaced-to-Bernstein
/// conversion (3 passes, degree <= 10) amplifies rounding by <= ~4e3 eps each.
constexpr double BoundInflation = 1e-11;
/// Sub-boxes per simplex direction for the bounds of tetrahedra and wedges.
constexpr int SimplexSplits = 2;

/// Degree of the cell's polynomials in each parametric direction (a bound).
void TensorDegrees(const LagrangeBasis& b, int deg[3])
{
  const int* o = b.GetOrder();
  if (b.IsSpecial())
  {
    const bool tet = b.GetShape() == LagrangeShape::Tetra;
    deg[0] = deg[1] = tet ? 4 : 3;
    deg[2] = tet ? 4 : 2;
    return;
  }
  switch (b.GetShape())
  {
    case LagrangeShape::Tetra:
      deg[0] = deg[1] = deg[2] = o[0];
      return;
    case LagrangeShape::Wedge:
      deg[0] = deg[1] = o[0];
      deg[2] = o[2];
      return;
    default:
      deg[0] = o[0];
      deg[1] = o[1];
      deg[2] = o[2];
  }
}

/// Equispaced samples -> Bernstein coefficients along dimension @p dim of a
/// (n0, n1, n2) array with @p comps interleaved components.
void ToBernsteinAlong(std::vector<double>& v, const int n[3], int comps, int dim)
{
  const int m = n[dim] - 1;
  std::vector<BernsteinPolynomial> t(m + 1);
  for (int i = 0; i <= m; ++i)
  {
    t[i] = EquispacedLagrangeBernstein(m, i);
  }
  const int stride[3] = { 1, n[0], n[0] * n[1] };
  std::vector<double> out(v.size(), 0.0);
  for (int i2 = 0; i2 < n[2]; ++i2)
    for (int i1 = 0; i1 < n[1]; ++i1)
      for (int i0 = 0; i0 < n[0]; ++i0)
      {
        const int idx[3] = { i0, i1, i2 };
        const int base = i0 * stride[0] + i1 * stride[1] + i2 * stride[2] - idx[dim] * stride[dim];
        const int a = idx[dim];
        for (int i = 0; i <= m; ++i)
          for (int c = 0; c < comps; ++c)
            out[comps * (base + a * stride[dim]) + c] +=
              t[i].B[a] * v[comps * (base + i * stride[dim]) + c];
      }
  v.swap(out);
}

/// max |second difference| of component @p c of the net along (b, e), times the
/// derivative factor (a bound of the derivative in the box's unit coordinates).
double SecondDerivativeBound(
  const std::vector<double>& net, const int n[3], int comps, int c, int b, int e)
{
  const int deg[3] = { n[0] - 1, n[1] - 1, n[2] - 1 };
  if ((b == e && deg[b] < 2) || deg[b] < 1 || deg[e] < 1)
  {
    return 0.0;
  }
  auto at = [&](int i0, int i1, int i2) { return net[comps * (i0 + n[0] * (i1 + n[1] * i2)) + c]; };
  double worst = 0.0;
  for (int i2 = 0; i2 < n[2]; ++i2)
    for (int i1 = 0; i1 < n[1]; ++i1)
      for (int i0 = 0; i0 < n[0]; ++i0)
      {
        int idx[3] = { i0, i1, i2 };
        int lim[3] = { deg[0], deg[1], deg[2] };
        lim[b] -= 1;
        lim[e] -= 1; // b == e: two steps along b
        if (idx[0] > lim[0] || idx[1] > lim[1] || idx[2] > lim[2])
        {
          continue;
        }
        int p1[3] = { i0, i1, i2 }, p2[3] = { i0, i1, i2 }, p3[3] = { i0, i1, i2 };
        p1[b] += 1;
        p2[e] += 1;
        p3[b] += 1;
        p3[e] += 1;
        const double diff = at(p3[0], p3[1], p3[2]) - at(p1[0], p1[1], p1[2]) -
          at(p2[0], p2[1], p2[2]) + at(i0, i1, i2);
        worst = std::max(worst, std::abs(diff));
      }
  const double factor = (b == e) ? deg[b] * (deg[b] - 1.0) : deg[b] * 1.0 * deg[e];
  return factor * worst;
}

/// Restrict the net to [y0, y1] (box coordinates in [0, 1]) along dimension @p dim.
void RestrictAlong(std::vector<double>& net, const int n[3], int comps, int dim, double y0, double y1)
{
  const int stride[3] = { 1, n[0], n[0] * n[1] };
  const int other[2] = { (dim + 1) % 3, (dim + 2) % 3 };
  for (int i = 0; i < n[other[0]]; ++i)
    for (int j = 0; j < n[other[1]]; ++j)
      for (int c = 0; c < comps; ++c)
      {
        const int base = i * stride[other[0]] + j * stride[other[1]];
        BernsteinPolynomial line;
        line.Degree = n[dim] - 1;
        for (int a = 0; a < n[dim]; ++a)
        {
          line.B[a] = net[comps * (base + a * stride[dim]) + c];
        }
        line = RestrictBernstein(line, y0, y1);
        for (int a = 0; a < n[dim]; ++a)
        {
          net[comps * (base + a * stride[dim]) + c] = line.B[a];
        }
      }
}

/// Fold one sub-box's nets (widths @p w) into the cell's bounds (maxima).
void AccumulateBoxBounds(const std::vector<double>& net, const int n[3], int comps,
  const double w[3], const double rootMaxAbs[4], CellDerivativeBounds& out)
{
  for (int c = 0; c < comps; ++c)
  {
    double maxAbs = 0.0, lo = 1e300, hi = -1e300;
    for (size_t k = c; k < net.size(); k += comps)
    {
      maxAbs = std::max(maxAbs, std::abs(net[k]));
      lo = std::min(lo, net[k]);
      hi = std::max(hi, net[k]);
    }
    const double slack = BoundInflation * std::max(maxAbs, rootMaxAbs[c]);
    for (int b = 0; b < 3; ++b)
    {
      for (int e = b; e < 3; ++e) // symmetric: (e, b) mirrored
      {
        const double bound = SecondDerivativeBound(net, n, comps, c, b, e) / (w[b] * w[e]) *
            (1.0 + BoundInflation) + slack / (w[b] * w[e]);
        double& target = c < 3 ? out.Geometry[c][b][e] : out.Field[b][e];
        target = std::max(target, bound);
        (c < 3 ? out.Geometry[c][e][b] : out.Field[e][b]) = target;
      }
    }
    if (c == 3)
    {
      out.FieldMin = std::min(out.FieldMin, lo - slack);
      out.FieldMax = std::max(out.FieldMax, hi + slack);
    }
  }
}
}

bool ComputeCellDerivativeBounds(
  const LagrangeCellView& cell, CellDerivativeBounds& out, double margin)
{
  out = CellDerivativeBounds();
  out.Margin = margin;
  if (!cell.Basis || !cell.Basis->IsInitialized() || !cell.Points || !(margin >= 0.0))
  {
    return false;
  }
  const LagrangeBasis& basis = *cell.Basis;
  const int nodes = basis.GetNodeCount();
  int deg[3];
  TensorDegrees(basis, deg);
  const int n[3] = { deg[0] + 1, deg[1] + 1, deg[2] + 1 };
  const int comps = cell.Scalars ? 4 : 3;
  // Node values: geometry minus the affine map through the corners (no
  // second derivatives; for an affine cell the remainder is rounding only, so
  // its bounds are ~0 instead of the conversion's amplified rounding of the
  // coordinates), then the field.
  double affine[12];
  IsLagrangeGeometryAffine(cell, 0.0, affine);
  std::vector<double> nodeValues(static_cast<size_t>(comps) * nodes);
  for (int i = 0; i < nodes; ++i)
  {
    double pc[3];
    basis.NodeParametricCoords(i, pc);
    for (int k = 0; k < 3; ++k)
    {
      const double a = affine[k] + affine[3 + k] * pc[0] + affine[6 + k] * pc[1] + affine[9 + k] * pc[2];
      nodeValues[comps * i + k] = cell.Points[3 * i + k] - a;
    }
    if (cell.Scalars)
    {
      nodeValues[comps * i + 3] = cell.Scalars[i];
    }
  }
  // Sub-boxes of [-margin, 1 + margin]^3 (simplex directions split in S parts,
  // those outside the widened domain skipped: the polynomials' extension to
  // the whole cube would inflate the bounds of tetrahedra and wedges).
  const LagrangeShape shape = basis.GetShape();
  const int split[3] = { shape == LagrangeShape::Hexahedron ? 1 : SimplexSplits,
    shape == LagrangeShape::Hexahedron ? 1 : SimplexSplits,
    shape == LagrangeShape::Tetra ? SimplexSplits : 1 };
  const double full = 1.0 + 2.0 * margin;
  for (int c = 0; c < comps; ++c)
  {
    for (int b = 0; b < 3; ++b)
      for (int e = 0; e < 3; ++e)
        (c < 3 ? out.Geometry[c][b][e] : out.Field[b][e]) = 0.0;
  }
  out.FieldMin = 1e300;
  out.FieldMax = -1e300;
  // One net over the whole box (samples, then Lagrange -> Bernstein per
  // direction); the sub-boxes' nets by exact de Casteljau restriction.
  std::vector<double> root(static_cast<size_t>(comps) * n[0] * n[1] * n[2]);
  for (int i2 = 0; i2 < n[2]; ++i2)
    for (int i1 = 0; i1 < n[1]; ++i1)
      for (int i0 = 0; i0 < n[0]; ++i0)
      {
        const double pc[3] = { -margin + full * i0 / deg[0], -margin + full * i1 / deg[1],
          -margin + full * i2 / deg[2] };
        basis.Interpolate(
          pc, nodeValues.data(), comps, &root[comps * (i0 + n[0] * (i1 + n[1] * i2))], nullptr);
      }
  for (int dim = 0; dim < 3; ++dim)
  {
    ToBernsteinAlong(root, n, comps, dim);
  }
  // Rounding slack relative to the whole net (the sub-nets inherit its errors).
  double rootMaxAbs[4] = { 0.0, 0.0, 0.0, 0.0 };
  for (size_t k = 0; k < root.size(); ++k)
  {
    rootMaxAbs[k % comps] = std::max(rootMaxAbs[k % comps], std::abs(root[k]));
  }
  std::vector<double> net;
  for (int b2 = 0; b2 < split[2]; ++b2)
    for (int b1 = 0; b1 < split[1]; ++b1)
      for (int b0 = 0; b0 < split[0]; ++b0)
      {
        const int b[3] = { b0, b1, b2 };
        const double w[3] = { full / split[0], full / split[1], full / split[2] };
        const double lo[3] = { -margin + b0 * w[0], -margin + b1 * w[1], -margin + b2 * w[2] };
        const double cornerSum = shape == LagrangeShape::Tetra ? lo[0] + lo[1] + lo[2]
          : shape == LagrangeShape::Wedge                    ? lo[0] + lo[1]
                                                             : -1.0;
        if (cornerSum > 1.0 + 3.0 * margin)
        {
          continue; // the box misses the domain widened by margin
        }
        net = root;
        for (int dim = 0; dim < 3; ++dim)
        {
          if (split[dim] > 1)
          {
            RestrictAlong(net, n, comps, dim, static_cast<double>(b[dim]) / split[dim],
              static_cast<double>(b[dim] + 1) / split[dim]);
          }
        }
        AccumulateBoxBounds(net, n, comps, w, rootMaxAbs, out);
      }
  if (cell.Scalars)
  {
    double lo = cell.Scalars[0], hi = cell.Scalars[0], maxAbs = 0.0;
    for (int i = 0; i < nodes; ++i)
    {
      lo = std::min(lo, cell.Scalars[i]);
      hi = std::max(hi, cell.Scalars[i]);
      maxAbs = std::max(maxAbs, std::abs(cell.Scalars[i]));
    }
    out.FieldScale = hi > lo ? hi - lo : (maxAbs > 0.0 ? maxAbs : 1.0);
  }
  out.Valid = true;
  return true;
}

}
