// Building the boundary patches of curved Lagrange cells (BuildCurvedFaces,
// FaceParametricPoint): see hovCurvedFaces.h.
#include "hovCurvedFaces.h"

#include "hovBernstein.h"           // equispaced Lagrange -> Bernstein
#include "hovCurvedTriangleNets.h" // ... on triangles

#include <algorithm> // std::copy, std::min, std::max

namespace hov
{
namespace
{
struct FaceDef
{
  double C[4][3]; // P00, P10, P11, P01
  bool Triangle;
  int DegU, DegV;
};

/// The face patches of the cell's shape and their degrees (one per face).
int FaceDefinitions(const LagrangeBasis& b, FaceDef* f)
{
  const int* o = b.GetOrder();
  const bool special = b.IsSpecial();
  auto quad = [](FaceDef& d, const double (&c)[4][3], int du, int dv) {
    std::copy(&c[0][0], &c[0][0] + 12, &d.C[0][0]);
    d.Triangle = false;
    d.DegU = du;
    d.DegV = dv;
  };
  // A triangle as one triangular patch: P00, P10, P01 its corners and P11 =
  // P10 + P01 - P00, so that the bilinear map is the affine one.
  auto tri = [](FaceDef& d, const double (&c)[3][3], int n) {
    for (int i = 0; i < 3; ++i)
    {
      d.C[0][i] = c[0][i];
      d.C[1][i] = c[1][i];
      d.C[2][i] = c[1][i] + c[2][i] - c[0][i];
      d.C[3][i] = c[2][i];
    }
    d.Triangle = true;
    d.DegU = d.DegV = n;
  };
  switch (b.GetShape())
  {
    case LagrangeShape::Hexahedron:
      for (int axis = 0; axis < 3; ++axis)
      {
        const int a = (axis + 1) % 3, c = (axis + 2) % 3;
        for (int side = 0; side < 2; ++side)
        {
          double q[4][3] = {};
          const double uv[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
          for (int k = 0; k < 4; ++k)
          {
            q[k][axis] = side;
            q[k][a] = uv[k][0];
            q[k][c] = uv[k][1];
          }
          quad(f[2 * axis + side], q, o[a], o[c]);
        }
      }
      return 6;
    case LagrangeShape::Wedge:
    {
      const int p = special ? 3 : o[0], q = o[2];
      tri(f[0], { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, p);
      tri(f[1], { { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 } }, p);
      quad(f[2], { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 0, 1 }, { 0, 0, 1 } }, p, q);
      quad(f[3], { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 1, 1 }, { 1, 0, 1 } }, p, q);
      quad(f[4], { { 0, 1, 0 }, { 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 1 } }, p, q);
      return 5;
    }
    default:
    {
      const int n = special ? 4 : o[0];
      tri(f[0], { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, n);
      tri(f[1], { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 1 } }, n);
      tri(f[2], { { 0, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, n);
      tri(f[3], { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, n);
      return 4;
    }
  }
}

}

void FaceParametricPoint(
  const CurvedFacePatch& f, double u, double v, double pc[3], double* dpcdu, double* dpcdv)
{
  for (int k = 0; k < 3; ++k)
  {
    pc[k] = f.P00[k] * (1 - u) * (1 - v) + f.P10[k] * u * (1 - v) + f.P01[k] * (1 - u) * v +
      f.P11[k] * u * v;
    if (dpcdu)
    {
      dpcdu[k] = (f.P10[k] - f.P00[k]) * (1 - v) + (f.P11[k] - f.P01[k]) * v;
    }
    if (dpcdv)
    {
      dpcdv[k] = (f.P01[k] - f.P00[k]) * (1 - u) + (f.P11[k] - f.P10[k]) * u;
    }
  }
}

namespace
{
/// The tensor net of a quadrilateral patch: x at the equispaced grid, then
/// Lagrange -> Bernstein along u, then v.
bool TensorNet(const LagrangeCellView& cell, CurvedFacePatch& p)
{
  const int nu = p.DegreeU + 1, nv = p.DegreeV + 1;
  std::vector<double> x(3 * nu * nv), y(3 * nu * nv, 0.0);
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      double pc[3];
      FaceParametricPoint(p, static_cast<double>(i) / p.DegreeU, static_cast<double>(j) / p.DegreeV, pc);
      EvaluateLagrangePosition(cell, pc, &x[3 * (nv * i + j)]);
    }
  }
  for (int i = 0; i < nu; ++i)
  {
    const BernsteinPolynomial l = EquispacedLagrangeBernstein(p.DegreeU, i);
    for (int a = 0; a < nu; ++a)
      for (int j = 0; j < nv; ++j)
        for (int c = 0; c < 3; ++c)
          y[3 * (nv * a + j) + c] += l.B[a] * x[3 * (nv * i + j) + c];
  }
  p.Net.assign(3 * nu * nv, 0.0);
  for (int j = 0; j < nv; ++j)
  {
    const BernsteinPolynomial l = EquispacedLagrangeBernstein(p.DegreeV, j);
    for (int a = 0; a < nu; ++a)
      for (int b = 0; b < nv; ++b)
        for (int c = 0; c < 3; ++c)
          p.Net[3 * (nv * a + b) + c] += l.B[b] * y[3 * (nv * a + j) + c];
  }
  return true;
}

/// The triangular net of a triangular patch (total degree n): x at the
/// equispaced points (j / n, k / n), converted by EquispacedTriangleBernstein.
bool TriangleNet(const LagrangeCellView& cell, CurvedFacePatch& p)
{
  const int n = p.DegreeU, size = detail::TriangleNetSize(n);
  std::vector<double> x(3 * size);
  for (int j = 0; j <= n; ++j)
  {
    for (int k = 0; j + k <= n; ++k)
    {
      double pc[3];
      FaceParametricPoint(p, static_cast<double>(j) / n, static_cast<double>(k) / n, pc);
      EvaluateLagrangePosition(cell, pc, &x[3 * detail::TriangleNetIndex(n, j, k)]);
    }
  }
  p.Net.assign(3 * size, 0.0);
  return detail::EquispacedTriangleBernstein(n, x.data(), 3, 3, p.Net.data());
}

/// CurvedFacePatch::Orientation: the parametric normal (P10 - P00) x (P01 -
/// P00) against the direction from the domain's centre to the (planar, in
/// parametric space) face, times the sign of det J at the patch's centre.
int PatchOrientation(const LagrangeCellView& cell, const CurvedFacePatch& p)
{
  double centre[3], pc[3], du[3], dv[3], x[3], J[9];
  cell.Basis->ParametricCenter(centre);
  const double mid = p.Triangle ? 1.0 / 3.0 : 0.5; // the patch's centre
  FaceParametricPoint(p, mid, mid, pc, du, dv);
  const double n[3] = { du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2],
    du[0] * dv[1] - du[1] * dv[0] };
  const double out = n[0] * (pc[0] - centre[0]) + n[1] * (pc[1] - centre[1]) + n[2] * (pc[2] - centre[2]);
  EvaluateLagrangePosition(cell, pc, x, J);
  const double det = J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) +
    J[2] * (J[3] * J[7] - J[4] * J[6]);
  if (!(det != 0.0) || !(out != 0.0))
  {
    return 0;
  }
  return (out > 0.0) == (det > 0.0) ? 1 : -1;
}
}

bool BuildCurvedFaces(const LagrangeCellView& cell, CurvedCellFaces& out)
{
  out.Faces.clear();
  out.FaceFirstPatch.clear();
  if (!cell.Basis || !cell.Basis->IsInitialized() || !cell.Points)
  {
    return false;
  }
  out.Extent = LagrangeCellExtent(cell);
  FaceDef defs[6];
  const int count = FaceDefinitions(*cell.Basis, defs);
  for (int f = 0; cell.Trilinear && f < count; ++f)
  {
    defs[f].DegU = defs[f].DegV = 1; // the faces of a trilinear map are bilinear patches
  }
  out.Faces.resize(count);
  out.FaceFirstPatch.resize(count + 1);
  for (int f = 0; f <= count; ++f)
  {
    out.FaceFirstPatch[f] = f; // one patch per face
  }
  for (int k = 0; k < 3; ++k)
  {
    out.Bounds[2 * k] = 1e300;
    out.Bounds[2 * k + 1] = -1e300;
  }
  for (int f = 0; f < count; ++f)
  {
    CurvedFacePatch& p = out.Faces[f];
    const FaceDef& d = defs[f];
    std::copy(d.C[0], d.C[0] + 3, p.P00);
    std::copy(d.C[1], d.C[1] + 3, p.P10);
    std::copy(d.C[2], d.C[2] + 3, p.P11);
    std::copy(d.C[3], d.C[3] + 3, p.P01);
    p.Triangle = d.Triangle;
    p.DegreeU = d.DegU;
    p.DegreeV = d.DegV;
    if (d.Triangle ? !TriangleNet(cell, p) : !TensorNet(cell, p))
    {
      return false;
    }
    const double margin = FaceSearchSettings().NetMargin * out.Extent;
    for (int k = 0; k < 3; ++k)
    {
      p.Box[2 * k] = 1e300;
      p.Box[2 * k + 1] = -1e300;
    }
    for (size_t k = 0; k < p.Net.size(); ++k)
    {
      p.Box[2 * (k % 3)] = std::min(p.Box[2 * (k % 3)], p.Net[k]);
      p.Box[2 * (k % 3) + 1] = std::max(p.Box[2 * (k % 3) + 1], p.Net[k]);
    }
    for (int k = 0; k < 3; ++k)
    {
      p.Box[2 * k] -= margin;
      p.Box[2 * k + 1] += margin;
      out.Bounds[2 * k] = std::min(out.Bounds[2 * k], p.Box[2 * k]);
      out.Bounds[2 * k + 1] = std::max(out.Bounds[2 * k + 1], p.Box[2 * k + 1]);
    }
    p.Orientation = PatchOrientation(cell, p);
  }
  return true;
}

}
