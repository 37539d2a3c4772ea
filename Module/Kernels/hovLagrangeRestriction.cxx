// A Lagrange field along a parametric line, in Bernstein form: see hovLagrangeRestriction.h.
#include "hovLagrangeRestriction.h"

#include <algorithm> // std::max, std::fill
#include <cmath>     // std::abs
#include <limits>    // epsilon

namespace hov
{
namespace
{
constexpr double Eps = std::numeric_limits<double>::epsilon();
constexpr int MaxO = MaxLagrangeOrder;

/// Scaled Bernstein coefficients C(N,j) B[j] of a polynomial of degree N:
/// the product of two is the convolution of their coefficients.
struct Scaled
{
  int N = 0;
  double C[MaxBernsteinDegree + 1];
  void One()
  {
    this->N = 0;
    this->C[0] = 1.0;
  }
  void Zero(int degree)
  {
    this->N = degree;
    std::fill(this->C, this->C + degree + 1, 0.0);
  }
  /// Multiply by the linear polynomial with values a at y = 0 and b at y = 1.
  void MulLinear(double a, double b)
  {
    this->C[this->N + 1] = this->C[this->N] * b;
    for (int j = this->N; j > 0; --j)
    {
      this->C[j] = this->C[j] * a + this->C[j - 1] * b;
    }
    this->C[0] *= a;
    ++this->N;
  }
};

/// acc += f * (a conv b), acc of degree a.N + b.N.
void AddProduct(const double* a, int na, const double* b, int nb, double f, double* acc)
{
  for (int i = 0; i <= na; ++i)
  {
    const double fa = f * a[i];
    for (int j = 0; j <= nb; ++j)
    {
      acc[i + j] += fa * b[j];
    }
  }
}

template <bool Abs>
double Val(double v)
{
  return Abs ? std::abs(v) : v;
}

/// The 1D Lagrange polynomial l_i of order p on nodes m/p along x(y) = x0 + y (x1 - x0).
template <bool Abs>
void Lagrange1D(int p, int i, double x0, double x1, Scaled& out)
{
  out.One();
  for (int k = 0; k <= p; ++k)
  {
    if (k != i)
    {
      out.MulLinear(Val<Abs>((p * x0 - k) / (i - k)), Val<Abs>((p * x1 - k) / (i - k)));
    }
  }
}

/// Silvester's Eta(n, c, tau(y)) for c = 0..n, tau from tau0 to tau1.
template <bool Abs>
void EtaTable(int n, double tau0, double tau1, Scaled* e)
{
  e[0].One();
  for (int c = 1; c <= n; ++c)
  {
    e[c] = e[c - 1];
    e[c].MulLinear(Val<Abs>((n * tau0 - c + 1.0) / c), Val<Abs>((n * tau1 - c + 1.0) / c));
  }
}

template <bool Abs>
void Hexahedron(const LagrangeBasis& basis, const double* values, const double* start,
  const double* end, Scaled& g)
{
  const int* p = basis.GetOrder();
  Scaled l[3][MaxO + 1];
  for (int d = 0; d < 3; ++d)
  {
    for (int i = 0; i <= p[d]; ++i)
    {
      Lagrange1D<Abs>(p[d], i, start[d], end[d], l[d][i]);
    }
  }
  // G[i][j] = sum_k f_ijk l2_k (degree p2); H[i] = sum_j G[i][j] l1_j; g = sum_i H[i] l0_i.
  double G[MaxO + 1][MaxO + 1][MaxO + 1];
  for (int i = 0; i <= p[0]; ++i)
    for (int j = 0; j <= p[1]; ++j)
      std::fill(G[i][j], G[i][j] + p[2] + 1, 0.0);
  for (int node = 0; node < basis.GetNodeCount(); ++node)
  {
    const std::array<int, 4>& ijk = basis.NodeIndex(node);
    const double f = Val<Abs>(values[node]);
    const Scaled& lk = l[2][ijk[2]];
    for (int m = 0; m <= p[2]; ++m)
    {
      G[ijk[0]][ijk[1]][m] += f * lk.C[m];
    }
  }
  g.Zero(p[0] + p[1] + p[2]);
  for (int i = 0; i <= p[0]; ++i)
  {
    double H[2 * MaxO + 1];
    std::fill(H, H + p[1] + p[2] + 1, 0.0);
    for (int j = 0; j <= p[1]; ++j)
    {
      AddProduct(G[i][j], p[2], l[1][j].C, p[1], 1.0, H);
    }
    AddProduct(H, p[1] + p[2], l[0][i].C, p[0], 1.0, g.C);
  }
}

template <bool Abs>
void Tetra(const LagrangeBasis& basis, const double* values, const double* start,
  const double* end, Scaled& g)
{
  const int n = basis.GetOrder()[0];
  const double tau0[4] = { start[0], start[1], start[2], 1.0 - start[0] - start[1] - start[2] };
  const double tau1[4] = { end[0], end[1], end[2], 1.0 - end[0] - end[1] - end[2] };
  Scaled e[4][MaxO + 1];
  for (int d = 0; d < 4; ++d)
  {
    EtaTable<Abs>(n, tau0[d], tau1[d], e[d]);
  }
  g.Zero(n);
  for (int node = 0; node < basis.GetNodeCount(); ++node)
  {
    const std::array<int, 4>& lam = basis.NodeIndex(node);
    double p01[MaxO + 1] = {}, p23[MaxO + 1] = {};
    AddProduct(e[0][lam[0]].C, lam[0], e[1][lam[1]].C, lam[1], 1.0, p01);
    AddProduct(e[2][lam[2]].C, lam[2], e[3][lam[3]].C, lam[3], 1.0, p23);
    AddProduct(p01, lam[0] + lam[1], p23, lam[2] + lam[3], Val<Abs>(values[node]), g.C);
  }
}

template <bool Abs>
void Wedge(const LagrangeBasis& basis, const double* values, const double* start,
  const double* end, Scaled& g)
{
  const int p = basis.GetOrder()[0], q = basis.GetOrder()[2];
  Scaled e[3][MaxO + 1], l[MaxO + 1];
  EtaTable<Abs>(p, start[0], end[0], e[0]);
  EtaTable<Abs>(p, start[1], end[1], e[1]);
  EtaTable<Abs>(p, 1.0 - start[0] - start[1], 1.0 - end[0] - end[1], e[2]);
  for (int k = 0; k <= q; ++k)
  {
    Lagrange1D<Abs>(q, k, start[2], end[2], l[k]);
  }
  // T[k] = sum_ij f_ijk Eta_i Eta_j Eta_(p-i-j) (degree p); g = sum_k T[k] l_k.
  double T[MaxO + 1][MaxO + 1];
  for (int k = 0; k <= q; ++k)
  {
    std::fill(T[k], T[k] + p + 1, 0.0);
  }
  for (int node = 0; node < basis.GetNodeCount(); ++node)
  {
    const std::array<int, 4>& ijk = basis.NodeIndex(node);
    const int c = p - ijk[0] - ijk[1];
    double p01[MaxO + 1] = {};
    AddProduct(e[0][ijk[0]].C, ijk[0], e[1][ijk[1]].C, ijk[1], 1.0, p01);
    AddProduct(p01, ijk[0] + ijk[1], e[2][c].C, c, Val<Abs>(values[node]), T[ijk[2]]);
  }
  g.Zero(p + q);
  for (int k = 0; k <= q; ++k)
  {
    AddProduct(T[k], p, l[k].C, q, 1.0, g.C);
  }
}

/// Closed-form cells: samples at y = m/D, converted with the equispaced
/// Lagrange-to-Bernstein coefficients (scaled form).
template <bool Abs>
void Sampled(const LagrangeBasis& basis, const double* values, const double* start,
  const double* step, Scaled& g)
{
  const int degree = basis.GetLineDegree();
  g.Zero(degree);
  for (int m = 0; m <= degree; ++m)
  {
    const double y = static_cast<double>(m) / degree;
    const double pc[3] = { start[0] + y * step[0], start[1] + y * step[1],
      start[2] + y * step[2] };
    double f = 0.0;
    basis.Interpolate(pc, values, 1, &f, nullptr);
    const BernsteinPolynomial lm = EquispacedLagrangeBernstein(degree, m);
    for (int j = 0; j <= degree; ++j)
    {
      g.C[j] += Val<Abs>(f) * Val<Abs>(lm.B[j]) * Binomial(degree, j);
    }
  }
}

template <bool Abs>
void Compute(const LagrangeBasis& basis, const double* values, const double start[3],
  const double step[3], Scaled& g)
{
  const double end[3] = { start[0] + step[0], start[1] + step[1], start[2] + step[2] };
  if (basis.IsSpecial())
  {
    Sampled<Abs>(basis, values, start, step, g);
  }
  else if (basis.GetShape() == LagrangeShape::Hexahedron)
  {
    Hexahedron<Abs>(basis, values, start, end, g);
  }
  else if (basis.GetShape() == LagrangeShape::Tetra)
  {
    Tetra<Abs>(basis, values, start, end, g);
  }
  else
  {
    Wedge<Abs>(basis, values, start, end, g);
  }
}
}

bool LagrangeFieldAlongLine(const LagrangeBasis& basis, const double* values,
  const double start[3], const double step[3], BernsteinPolynomial& out, double* roundingBound)
{
  if (!basis.IsInitialized() || basis.GetLineDegree() > MaxBernsteinDegree)
  {
    return false;
  }
  Scaled g;
  Compute<false>(basis, values, start, step, g);
  out.Degree = g.N;
  for (int j = 0; j <= g.N; ++j)
  {
    out.B[j] = g.C[j] / Binomial(g.N, j);
  }
  if (roundingBound)
  {
    Scaled a;
    Compute<true>(basis, values, start, step, a);
    double worst = 0.0;
    for (int j = 0; j <= a.N; ++j)
    {
      worst = std::max(worst, a.C[j] / Binomial(a.N, j));
    }
    *roundingBound = (2.0 * a.N + 16.0) * Eps * worst;
  }
  return true;
}
}
