// Sum-factorised interpolation on Lagrange cells (see hovLagrangeBasis.h).
//
// Each sum reads the node values in the order of LagrangeBasis::SumNodes (one
// gather per node, no copy); the outer sums run over partial sums.
// Hexahedron of orders (p0, p1, p2), nodes (i, j, k):
//   x = sum_k l_k(t) sum_j l_j(s) sum_i l_i(r) X_ijk: O(p^4) instead of the
//   node loop's three-factor product per value and derivative.
// Tetrahedron of order n, tau = (r, s, t, u = 1 - r - s - t):
//   x = sum_a E_a(r) sum_b E_b(s) sum_c E_c(t) E_{n-a-b-c}(u) X_abc,
// E Silvester's Eta(n, ., .). The innermost sum runs over the nodes (one
// gather each); the outer ones over the O(n^2) partial sums, so a node costs
// one weight product instead of the node loop's four-factor product per value
// and derivative. Derivatives: d/dr = d/dtau_0 - d/dtau_3 (likewise s, t); the
// u-part d/dtau_3 is accumulated once and subtracted at the end.
// Wedge of orders (p, p, q), nodes (i, j, k), c = p - i - j:
//   x = sum_k l_k(t) sum_j E_j(s) sum_i E_i(r) E_c(1 - r - s) X_ijk.
// The same products as the node loop, summed in another order: the results
// agree with it to rounding (TestLagrangeBasis.InterpolateMatchesWeights).
#include "hovLagrangeBasis.h"

#include "hovLagrangeFactors.h" // Eta1D, Lagrange1D

namespace hov
{
namespace
{
using detail::Eta1D;
using detail::Lagrange1D;

template <int C, bool G>
void HexahedronSum(const int* order, const int* node, const Lagrange1D (&l)[3],
  const double* values, double* value, double* gradient)
{
  double v[C] = {}, g[3 * C] = {};
  for (int k = 0; k <= order[2]; ++k)
  {
    double b[C] = {}, br[C] = {}, bs[C] = {};
    for (int j = 0; j <= order[1]; ++j)
    {
      double a[C] = {}, ar[C] = {};
      for (int i = 0; i <= order[0]; ++i)
      {
        const double* X = values + static_cast<size_t>(*node++) * C;
        for (int c = 0; c < C; ++c)
        {
          a[c] += l[0].L[i] * X[c];
          if (G)
          {
            ar[c] += l[0].D[i] * X[c];
          }
        }
      }
      for (int c = 0; c < C; ++c)
      {
        b[c] += l[1].L[j] * a[c];
        if (G)
        {
          br[c] += l[1].L[j] * ar[c];
          bs[c] += l[1].D[j] * a[c];
        }
      }
    }
    for (int c = 0; c < C; ++c)
    {
      v[c] += l[2].L[k] * b[c];
      if (G)
      {
        g[3 * c] += l[2].L[k] * br[c];
        g[3 * c + 1] += l[2].L[k] * bs[c];
        g[3 * c + 2] += l[2].D[k] * b[c];
      }
    }
  }
  for (int c = 0; c < C; ++c)
  {
    value[c] = v[c];
    for (int d = 0; G && d < 3; ++d)
    {
      gradient[3 * c + d] = g[3 * c + d];
    }
  }
}

template <int C, bool G>
void TetraSum(int n, const int* node, const Eta1D (&e)[4], const double* values, double* value,
  double* gradient)
{
  double R[C] = {}, Rr[C] = {}, Rs[C] = {}, Rt[C] = {}, Ru[C] = {};
  for (int a = 0; a <= n; ++a)
  {
    double Q[C] = {}, Qs[C] = {}, Qt[C] = {}, Qu[C] = {};
    for (int b = 0; a + b <= n; ++b)
    {
      double P[C] = {}, Pt[C] = {}, Pu[C] = {};
      const int m = n - a - b;
      for (int c = 0; c <= m; ++c)
      {
        const double* X = values + static_cast<size_t>(*node++) * C;
        const double ec = e[2].E[c], eu = e[3].E[m - c];
        const double w = ec * eu;
        const double wt = G ? e[2].D[c] * eu : 0.0, wu = G ? ec * e[3].D[m - c] : 0.0;
        for (int k = 0; k < C; ++k)
        {
          P[k] += w * X[k];
          if (G)
          {
            Pt[k] += wt * X[k];
            Pu[k] += wu * X[k];
          }
        }
      }
      const double eb = e[1].E[b], db = e[1].D[b];
      for (int k = 0; k < C; ++k)
      {
        Q[k] += eb * P[k];
        if (G)
        {
          Qs[k] += db * P[k];
          Qt[k] += eb * Pt[k];
          Qu[k] += eb * Pu[k];
        }
      }
    }
    const double ea = e[0].E[a], da = e[0].D[a];
    for (int k = 0; k < C; ++k)
    {
      R[k] += ea * Q[k];
      if (G)
      {
        Rr[k] += da * Q[k];
        Rs[k] += ea * Qs[k];
        Rt[k] += ea * Qt[k];
        Ru[k] += ea * Qu[k];
      }
    }
  }
  for (int k = 0; k < C; ++k)
  {
    value[k] = R[k];
    if (G)
    {
      gradient[3 * k] = Rr[k] - Ru[k];
      gradient[3 * k + 1] = Rs[k] - Ru[k];
      gradient[3 * k + 2] = Rt[k] - Ru[k];
    }
  }
}

template <int C, bool G>
void WedgeSum(int p, int q, const int* node, const Eta1D (&e)[3], const Lagrange1D& l,
  const double* values, double* value, double* gradient)
{
  double R[C] = {}, Rr[C] = {}, Rs[C] = {}, Rt[C] = {}, Ru[C] = {};
  for (int k = 0; k <= q; ++k)
  {
    double Q[C] = {}, Qr[C] = {}, Qs[C] = {}, Qu[C] = {};
    for (int j = 0; j <= p; ++j)
    {
      double P[C] = {}, Pr[C] = {}, Pu[C] = {};
      for (int i = 0; i + j <= p; ++i)
      {
        const double* X = values + static_cast<size_t>(*node++) * C;
        const int c = p - i - j;
        const double ei = e[0].E[i], ec = e[2].E[c];
        const double w = ei * ec;
        const double wr = G ? e[0].D[i] * ec : 0.0, wu = G ? ei * e[2].D[c] : 0.0;
        for (int m = 0; m < C; ++m)
        {
          P[m] += w * X[m];
          if (G)
          {
            Pr[m] += wr * X[m];
            Pu[m] += wu * X[m];
          }
        }
      }
      const double ej = e[1].E[j], dj = e[1].D[j];
      for (int m = 0; m < C; ++m)
      {
        Q[m] += ej * P[m];
        if (G)
        {
          Qr[m] += ej * Pr[m];
          Qs[m] += dj * P[m];
          Qu[m] += ej * Pu[m];
        }
      }
    }
    const double lk = l.L[k], dk = l.D[k];
    for (int m = 0; m < C; ++m)
    {
      R[m] += lk * Q[m];
      if (G)
      {
        Rr[m] += lk * Qr[m];
        Rs[m] += lk * Qs[m];
        Rt[m] += dk * Q[m];
        Ru[m] += lk * Qu[m];
      }
    }
  }
  for (int m = 0; m < C; ++m)
  {
    value[m] = R[m];
    if (G)
    {
      gradient[3 * m] = Rr[m] - Ru[m];
      gradient[3 * m + 1] = Rs[m] - Ru[m];
      gradient[3 * m + 2] = Rt[m];
    }
  }
}

/// The sums for @p C components, with or without the gradient.
template <int C>
void Sum(LagrangeShape shape, const int* order, const int* node, const double pc[3],
  const double* values, double* value, double* gradient)
{
  const int p = order[0];
  if (shape == LagrangeShape::Hexahedron)
  {
    Lagrange1D l[3];
    for (int d = 0; d < 3; ++d)
    {
      l[d].Compute(order[d], pc[d], gradient != nullptr);
    }
    gradient ? HexahedronSum<C, true>(order, node, l, values, value, gradient)
             : HexahedronSum<C, false>(order, node, l, values, value, gradient);
    return;
  }
  if (shape == LagrangeShape::Tetra)
  {
    Eta1D e[4];
    for (int d = 0; d < 3; ++d)
    {
      e[d].Compute(p, pc[d]);
    }
    e[3].Compute(p, 1.0 - pc[0] - pc[1] - pc[2]);
    gradient ? TetraSum<C, true>(p, node, e, values, value, gradient)
             : TetraSum<C, false>(p, node, e, values, value, gradient);
    return;
  }
  Eta1D e[3];
  e[0].Compute(p, pc[0]);
  e[1].Compute(p, pc[1]);
  e[2].Compute(p, 1.0 - pc[0] - pc[1]);
  Lagrange1D l;
  l.Compute(order[2], pc[2], gradient != nullptr);
  gradient ? WedgeSum<C, true>(p, order[2], node, e, l, values, value, gradient)
           : WedgeSum<C, false>(p, order[2], node, e, l, values, value, gradient);
}
}

void LagrangeBasis::InterpolateFactorised(const double pc[3], const double* values, int components,
  double* value, double* gradient) const
{
  const int* node = this->SumNodes.data();
  switch (components)
  {
    case 1:
      Sum<1>(this->Shape, this->Order, node, pc, values, value, gradient);
      return;
    case 2:
      Sum<2>(this->Shape, this->Order, node, pc, values, value, gradient);
      return;
    case 3:
      Sum<3>(this->Shape, this->Order, node, pc, values, value, gradient);
      return;
    default:
      Sum<4>(this->Shape, this->Order, node, pc, values, value, gradient);
  }
}
}
