// Closed-form 15-node tetrahedron and 21-node wedge: see hovLagrangeSpecial.h.
#include "hovLagrangeSpecial.h"

namespace hov
{
namespace detail
{
namespace
{
/// Forward-mode dual number with the three parametric partials.
struct Dual
{
  double V = 0.0;
  double D[3] = { 0.0, 0.0, 0.0 };
  Dual() = default;
  Dual(double v) // NOLINT: implicit from constants, as in the formulas
    : V(v)
  {
  }
};

Dual operator+(const Dual& a, const Dual& b)
{
  Dual r(a.V + b.V);
  for (int k = 0; k < 3; ++k)
  {
    r.D[k] = a.D[k] + b.D[k];
  }
  return r;
}

Dual operator-(const Dual& a, const Dual& b)
{
  Dual r(a.V - b.V);
  for (int k = 0; k < 3; ++k)
  {
    r.D[k] = a.D[k] - b.D[k];
  }
  return r;
}

Dual operator*(const Dual& a, const Dual& b)
{
  Dual r(a.V * b.V);
  for (int k = 0; k < 3; ++k)
  {
    r.D[k] = a.D[k] * b.V + a.V * b.D[k];
  }
  return r;
}

/// vtkLagrangeTetra::InterpolateFunctions, 15-point branch.
template <class T>
void Tetra15(const T pc[3], T* w)
{
  const T r = pc[0], s = pc[1], t = pc[2];
  const T u = T(1.0) - r - s - t;
  const T ur = u * r, us = u * s, ut = u * t, rs = r * s, rt = r * t, st = s * t;
  const T urs = ur * s, urt = ur * t, ust = us * t, rst = rs * t;
  const T urst = urs * t;
  w[0] = u - T(2.0) * (ur + us + ut) + T(3.0) * (urs + urt + ust) - T(4.0) * urst;
  w[1] = r - T(2.0) * (ur + rs + rt) + T(3.0) * (urs + urt + rst) - T(4.0) * urst;
  w[2] = s - T(2.0) * (rs + us + st) + T(3.0) * (urs + rst + ust) - T(4.0) * urst;
  w[3] = t - T(2.0) * (ut + rt + st) + T(3.0) * (urt + ust + rst) - T(4.0) * urst;
  w[4] = T(4.0) * ur - T(12.0) * (urs + urt) + T(32.0) * urst;
  w[5] = T(4.0) * rs - T(12.0) * (urs + rst) + T(32.0) * urst;
  w[6] = T(4.0) * us - T(12.0) * (urs + ust) + T(32.0) * urst;
  w[7] = T(4.0) * ut - T(12.0) * (urt + ust) + T(32.0) * urst;
  w[8] = T(4.0) * rt - T(12.0) * (urt + rst) + T(32.0) * urst;
  w[9] = T(4.0) * st - T(12.0) * (rst + ust) + T(32.0) * urst;
  w[10] = T(27.0) * urs - T(108.0) * urst;
  w[11] = T(27.0) * urt - T(108.0) * urst;
  w[12] = T(27.0) * rst - T(108.0) * urst;
  w[13] = T(27.0) * ust - T(108.0) * urst;
  w[14] = T(256.0) * urst;
}

/// vtkHigherOrderInterpolation::WedgeShapeFunctions, 21-point branch.
template <class T>
void Wedge21(const T pc[3], T* w)
{
  const T r = pc[0], s = pc[1];
  const T t = T(2.0) * pc[2] - T(1.0); // this branch uses t in [-1, 1]
  const T rsm = T(1.0) - r - s, rs = r * s, tp = T(1.0) + t, tm = T(1.0) - t;
  const T mt = T(-0.5) * t * tm, pt = T(0.5) * t * tp, pm = tp * tm;
  const T c0 = rsm * (T(1.0) - T(2.0) * (r + s) + T(3.0) * rs);
  const T c1 = r - T(2.0) * (rsm * r + rs) + T(3.0) * rsm * rs;
  const T c2 = s - T(2.0) * (rsm * s + rs) + T(3.0) * rsm * rs;
  const T e0 = rsm * (T(4.0) * r - T(12.0) * rs);
  const T e1 = T(4.0) * rs - T(12.0) * rsm * rs;
  const T e2 = rsm * (T(4.0) * s - T(12.0) * rs);
  w[0] = mt * c0;
  w[1] = mt * c1;
  w[2] = mt * c2;
  w[3] = pt * c0;
  w[4] = pt * c1;
  w[5] = pt * c2;
  w[6] = mt * e0;
  w[7] = mt * e1;
  w[8] = mt * e2;
  w[9] = pt * e0;
  w[10] = pt * e1;
  w[11] = pt * e2;
  w[12] = pm * c0;
  w[13] = pm * c1;
  w[14] = pm * c2;
  w[15] = T(27.0) * mt * rsm * rs;
  w[16] = T(27.0) * pt * rsm * rs;
  w[17] = pm * e0;
  w[18] = pm * e1;
  w[19] = pm * e2;
  w[20] = T(27.0) * pm * rsm * rs;
}

template <int N, class F>
void Evaluate(F formula, const double pc[3], double* w, double* derivs)
{
  if (!derivs)
  {
    formula(pc, w);
    return;
  }
  Dual x[3], out[N];
  for (int k = 0; k < 3; ++k)
  {
    x[k] = Dual(pc[k]);
    x[k].D[k] = 1.0;
  }
  formula(x, out);
  for (int i = 0; i < N; ++i)
  {
    if (w)
    {
      w[i] = out[i].V;
    }
    for (int k = 0; k < 3; ++k)
    {
      derivs[k * N + i] = out[i].D[k];
    }
  }
}
}

void Tetra15Functions(const double pc[3], double* w, double* derivs)
{
  Evaluate<Tetra15Nodes>(
    [](const auto* p, auto* out) { Tetra15(p, out); }, pc, w, derivs);
}

void Wedge21Functions(const double pc[3], double* w, double* derivs)
{
  Evaluate<Wedge21Nodes>(
    [](const auto* p, auto* out) { Wedge21(p, out); }, pc, w, derivs);
}

void Tetra15NodeCoords(int node, double pc[3])
{
  // Vertices, the 6 mid-edges (VTK's quadratic tetrahedron order), the face
  // centres of faces (u,r,s), (u,r,t), (r,s,t), (u,s,t), the body centre.
  static constexpr double coords[Tetra15Nodes][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 0.5, 0, 0 }, { 0.5, 0.5, 0 }, { 0, 0.5, 0 }, { 0, 0, 0.5 }, { 0.5, 0, 0.5 },
    { 0, 0.5, 0.5 }, { 1 / 3., 1 / 3., 0 }, { 1 / 3., 0, 1 / 3. }, { 1 / 3., 1 / 3., 1 / 3. },
    { 0, 1 / 3., 1 / 3. }, { 0.25, 0.25, 0.25 } };
  for (int k = 0; k < 3; ++k)
  {
    pc[k] = coords[node][k];
  }
}

void Wedge21NodeCoords(int node, double pc[3])
{
  // vtkHigherOrderWedge21ParametricCoords.
  static constexpr double coords[Wedge21Nodes][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 }, { 0.5, 0, 0 }, { 0.5, 0.5, 0 }, { 0, 0.5, 0 },
    { 0.5, 0, 1 }, { 0.5, 0.5, 1 }, { 0, 0.5, 1 }, { 0, 0, 0.5 }, { 1, 0, 0.5 }, { 0, 1, 0.5 },
    { 1 / 3., 1 / 3., 0 }, { 1 / 3., 1 / 3., 1 }, { 0.5, 0, 0.5 }, { 0.5, 0.5, 0.5 },
    { 0, 0.5, 0.5 }, { 1 / 3., 1 / 3., 0.5 } };
  for (int k = 0; k < 3; ++k)
  {
    pc[k] = coords[node][k];
  }
}
}
}
