// Building the boundary patches of curved Lagrange cells (BuildCurvedFaces,
// FaceParametricPoint): see hovCurvedFaces.h.
#include "hovCurvedFaces.h"

#include "hovBernstein.h" // equispaced Lagrange -> Bernstein

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

/// The face patches of the cell's shape and their degrees (triangles as 3 quads).
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
  // A triangle as 3 non-degenerate quads: corner, edge midpoint, centroid,
  // other edge midpoint (a collapsed quad would be singular at its apex).
  auto tri = [](FaceDef* d, const double (&c)[3][3], int n) {
    for (int k = 0; k < 3; ++k)
    {
      const double* a = c[k];
      const double* b = c[(k + 1) % 3];
      const double* z = c[(k + 2) % 3];
      for (int i = 0; i < 3; ++i)
      {
        d[k].C[0][i] = a[i];
        d[k].C[1][i] = 0.5 * (a[i] + b[i]);
        d[k].C[2][i] = (a[i] + b[i] + z[i]) / 3.0;
        d[k].C[3][i] = 0.5 * (a[i] + z[i]);
      }
      d[k].Triangle = true;
      d[k].DegU = d[k].DegV = n;
    }
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
      tri(f, { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, p);
      tri(f + 3, { { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 } }, p);
      quad(f[6], { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 0, 1 }, { 0, 0, 1 } }, p, q);
      quad(f[7], { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 1, 1 }, { 1, 0, 1 } }, p, q);
      quad(f[8], { { 0, 1, 0 }, { 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 1 } }, p, q);
      return 9;
    }
    default:
    {
      const int n = special ? 4 : o[0];
      tri(f, { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, n);
      tri(f + 3, { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 1 } }, n);
      tri(f + 6, { { 0, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, n);
      tri(f + 9, { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, n);
      return 12;
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
/// CurvedFacePatch::Orientation: the parametric normal (P10 - P00) x (P01 -
/// P00) against the direction from the domain's centre to the (planar, in
/// parametric space) face, times the sign of det J at the patch's centre.
int PatchOrientation(const LagrangeCellView& cell, const CurvedFacePatch& p)
{
  double centre[3], pc[3], du[3], dv[3], x[3], J[9];
  cell.Basis->ParametricCenter(centre);
  FaceParametricPoint(p, 0.5, 0.5, pc, du, dv);
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
  FaceDef defs[12];
  const int count = FaceDefinitions(*cell.Basis, defs);
  for (int f = 0; cell.Trilinear && f < count; ++f)
  {
    defs[f].DegU = defs[f].DegV = 1; // the faces of a trilinear map are bilinear patches
  }
  out.Faces.resize(count);
  out.FaceFirstPatch.assign(1, 0);
  for (int f = 0; f < count; ++f)
  {
    // A triangle's three patches are consecutive (FaceDefinitions).
    if (!defs[f].Triangle || f + 1 == count || out.FaceFirstPatch.back() + 3 == f + 1)
    {
      out.FaceFirstPatch.push_back(f + 1);
    }
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
    const int nu = d.DegU + 1, nv = d.DegV + 1;
    // Samples at the equispaced grid, then Lagrange -> Bernstein along u, then v.
    std::vector<double> x(3 * nu * nv), y(3 * nu * nv, 0.0);
    for (int i = 0; i < nu; ++i)
    {
      for (int j = 0; j < nv; ++j)
      {
        double pc[3];
        FaceParametricPoint(p, static_cast<double>(i) / d.DegU, static_cast<double>(j) / d.DegV, pc);
        EvaluateLagrangePosition(cell, pc, &x[3 * (nv * i + j)]);
      }
    }
    for (int i = 0; i < nu; ++i)
    {
      const BernsteinPolynomial l = EquispacedLagrangeBernstein(d.DegU, i);
      for (int a = 0; a < nu; ++a)
        for (int j = 0; j < nv; ++j)
          for (int c = 0; c < 3; ++c)
            y[3 * (nv * a + j) + c] += l.B[a] * x[3 * (nv * i + j) + c];
    }
    p.Net.assign(3 * nu * nv, 0.0);
    for (int j = 0; j < nv; ++j)
    {
      const BernsteinPolynomial l = EquispacedLagrangeBernstein(d.DegV, j);
      for (int a = 0; a < nu; ++a)
        for (int b = 0; b < nv; ++b)
          for (int c = 0; c < 3; ++c)
            p.Net[3 * (nv * a + b) + c] += l.B[b] * y[3 * (nv * a + j) + c];
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
