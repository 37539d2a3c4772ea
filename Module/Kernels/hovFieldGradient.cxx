#include "hovFieldGradient.h"

#include "hovCellRestriction.h" // AffineFieldBasis, RestrictAffineField, IsGeometryAffine

#include <algorithm> // max
#include <cmath>     // fabs, isfinite

namespace hov
{
namespace
{

void MatVec(const double m[9], const double v[3], double r[3])
{
  for (int i = 0; i < 3; ++i)
  {
    r[i] = m[3 * i] * v[0] + m[3 * i + 1] * v[1] + m[3 * i + 2] * v[2];
  }
}

/// Coefficients (index 9i + 3j + k of r^i s^j t^k) of d/dpc_axis of @p c.
void DerivativeCoefficients(const double c[AffineFieldTerms], int axis, double out[AffineFieldTerms])
{
  for (int m = 0; m < AffineFieldTerms; ++m)
  {
    out[m] = 0.0;
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int e[3] = { i, j, k };
        if (e[axis] == 0)
        {
          continue;
        }
        int lowered[3] = { i, j, k };
        --lowered[axis];
        out[9 * lowered[0] + 3 * lowered[1] + lowered[2]] += e[axis] * c[9 * i + 3 * j + k];
      }
    }
  }
}
}

bool TetraGradient(const double* p, const double* s, double g[3])
{
  g[0] = g[1] = g[2] = 0.0;
  double e[3][3], ds[3];
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      e[i][k] = p[3 * (i + 1) + k] - p[k];
    }
    ds[i] = s[i + 1] - s[0];
  }
  auto cross = [](const double* a, const double* b, double* r) {
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
  };
  double c23[3], c31[3], c12[3];
  cross(e[1], e[2], c23);
  cross(e[2], e[0], c31);
  cross(e[0], e[1], c12);
  const double det = e[0][0] * c23[0] + e[0][1] * c23[1] + e[0][2] * c23[2];
  if (!(std::fabs(det) > 0.0) || !std::isfinite(det) || !std::isfinite(ds[0] + ds[1] + ds[2]))
  {
    return false;
  }
  double r[3];
  for (int k = 0; k < 3; ++k)
  {
    r[k] = (ds[0] * c23[k] + ds[1] * c31[k] + ds[2] * c12[k]) / det;
    if (!std::isfinite(r[k]))
    {
      return false;
    }
  }
  g[0] = r[0];
  g[1] = r[1];
  g[2] = r[2];
  return true;
}

namespace
{
/// VTK cell types are below this (the CellShape values).
constexpr int ShapeSlots = 32;

/// AffineFieldBasis of every shape that has one, built once (thread-safe
/// initialisation of a function-local static).
struct BasisTable
{
  double V[ShapeSlots][AffineFieldTerms * MaxCellNodes] = {};
  bool Known[ShapeSlots] = {};
  BasisTable()
  {
    for (int i = 0; i < ShapeSlots; ++i)
    {
      const CellShape shape = static_cast<CellShape>(i);
      this->Known[i] = IsSupportedCellType(i) && AffineFieldBasis(shape, this->V[i]);
    }
  }
};
}

const double* CachedAffineFieldBasis(CellShape shape)
{
  static const BasisTable table;
  const int i = static_cast<int>(shape);
  return i >= 0 && i < ShapeSlots && table.Known[i] ? table.V[i] : nullptr;
}

bool AffineGradientCoefficients(
  CellShape shape, const double* scalars, double coefficients[3][AffineFieldTerms])
{
  const double* basis = CachedAffineFieldBasis(shape);
  if (!basis)
  {
    return false; // pyramids: rational shape functions
  }
  const int nodes = CellNodeCount(shape);
  for (int i = 0; i < nodes; ++i)
  {
    if (!std::isfinite(scalars[i]))
    {
      return false; // the documented refusal: no NaN coefficient reaches the caller
    }
  }
  // The gradient of s - s_0 (the same polynomial's): a constant field then
  // has the zero gradient exactly, not rounding noise in a random direction.
  double shifted[MaxCellNodes];
  for (int i = 0; i < nodes; ++i)
  {
    shifted[i] = scalars[i] - scalars[0];
  }
  double c[AffineFieldTerms];
  AffineFieldCoefficients(basis, nodes, shifted, c);
  for (int axis = 0; axis < 3; ++axis)
  {
    DerivativeCoefficients(c, axis, coefficients[axis]);
  }
  return true;
}

void AffineGradientAlongLine(const double coefficients[3][AffineFieldTerms],
  const double inverseJacobian[9], const double start[3], const double step[3],
  Polynomial gradient[3])
{
  Polynomial dpc[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    dpc[axis] = RestrictAffineField(coefficients[axis], start, step);
  }
  // grad_a = sum_b (J^-1)_{b a} ds/dpc_b.
  const double* inv = inverseJacobian;
  for (int a = 0; a < 3; ++a)
  {
    Polynomial g;
    g.Degree = 0;
    for (int b = 0; b < 3; ++b)
    {
      g.Degree = std::max(g.Degree, dpc[b].Degree);
      for (int k = 0; k <= dpc[b].Degree; ++k)
      {
        g.C[k] += inv[3 * b + a] * dpc[b].C[k];
      }
    }
    g.Degree = EffectiveDegree(g);
    gradient[a] = g;
  }
}

bool AffineGradientAlongRay(CellShape shape, const double* points, const double* scalars,
  const double origin[3], const double direction[3], double t0, Polynomial gradient[3])
{
  if (!IsGeometryAffine(shape, points))
  {
    return false;
  }
  double coefficients[3][AffineFieldTerms];
  if (!AffineGradientCoefficients(shape, scalars, coefficients))
  {
    return false; // pyramids, non-finite scalars
  }
  double pcCenter[3], xc[3], jac[9], inv[9];
  CellParametricCenter(shape, pcCenter);
  EvaluateGeometry(shape, points, pcCenter, xc, jac);
  if (!hov::InvertMatrix3(jac, inv))
  {
    return false;
  }
  // As RestrictCellScalar's affine path: pc(t0) = pc0 + J^-1 (o + t0 d - x0).
  double pc0[3], rel[3], pcStart[3], step[3];
  CellNodeParametricCoords(shape, 0, pc0);
  for (int k = 0; k < 3; ++k)
  {
    rel[k] = (origin[k] - points[k]) + t0 * direction[k];
  }
  MatVec(inv, rel, pcStart);
  MatVec(inv, direction, step);
  for (int k = 0; k < 3; ++k)
  {
    pcStart[k] += pc0[k];
    if (!std::isfinite(pcStart[k]) || !std::isfinite(step[k]))
    {
      return false;
    }
  }
  AffineGradientAlongLine(coefficients, inv, pcStart, step, gradient);
  return true;
}

bool CellFieldAndGradient(CellShape shape, const double* points, const double* scalars,
  const double x[3], double pc[3], double& value, double gradient[3])
{
  const bool converged = InvertGeometry(shape, points, x, pc);
  const int n = CellNodeCount(shape);
  double w[MaxCellNodes], derivs[3 * MaxCellNodes];
  CellShapeFunctions(shape, pc, w);
  CellShapeDerivatives(shape, pc, derivs);
  // The derivatives of s - s_0 (the same polynomial's): a constant field then
  // has the zero gradient exactly, not the rounding of sum_i dN_i/dpc s_i
  // (~1e-16 in a random direction), whose normal is noise; the shaded
  // segment's adaptive quadrature never converges on noise (256 panels per
  // segment).
  double dpc[3] = { 0.0, 0.0, 0.0 };
  value = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const double si = scalars[i] - scalars[0];
    value += w[i] * si;
    for (int b = 0; b < 3; ++b)
    {
      dpc[b] += derivs[b * n + i] * si;
    }
  }
  value += scalars[0];
  double xc[3], jac[9], inv[9];
  EvaluateGeometry(shape, points, pc, xc, jac);
  gradient[0] = gradient[1] = gradient[2] = 0.0;
  if (!hov::InvertMatrix3(jac, inv))
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    gradient[a] = inv[a] * dpc[0] + inv[3 + a] * dpc[1] + inv[6 + a] * dpc[2];
  }
  if (!std::isfinite(value) || !std::isfinite(gradient[0]) || !std::isfinite(gradient[1]) ||
    !std::isfinite(gradient[2]))
  {
    value = 0.0; // non-finite scalars: refused, nothing non-finite returned
    gradient[0] = gradient[1] = gradient[2] = 0.0;
    return false;
  }
  return converged;
}
}
