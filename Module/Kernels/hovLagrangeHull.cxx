// Bernstein-Bezier hull of a Lagrange cell's field: see hovLagrangeHull.h.
#include "hovLagrangeHull.h"

#include "hovBernsteinFactors.h" // the factors' bases and conversions

#include <algorithm> // std::max, std::min, std::swap, std::find
#include <array>     // factor multi-indices
#include <cmath>     // std::abs
#include <limits>    // epsilon

namespace hov
{
using namespace detail;
namespace
{
constexpr double Eps = std::numeric_limits<double>::epsilon();

/// Factors of @p basis, the parametric coordinates each reads (first index), and
/// the factor multi-index of every node.
int ShapeFactors(const LagrangeBasis& basis, FactorShape shapes[3], int first[3])
{
  const int* o = basis.GetOrder();
  switch (basis.GetShape())
  {
    case LagrangeShape::Tetra:
      shapes[0] = { 3, o[0] };
      first[0] = 0;
      return 1;
    case LagrangeShape::Wedge:
      shapes[0] = { 2, o[0] };
      shapes[1] = { 1, o[2] };
      first[0] = 0;
      first[1] = 2;
      return 2;
    default:
      for (int d = 0; d < 3; ++d)
      {
        shapes[d] = { 1, o[d] };
        first[d] = d;
      }
      return 3;
  }
}

/// The factor multi-index of a node of @p basis in factor @p d.
std::array<int, 3> NodeFactorIndex(const LagrangeBasis& basis, int node, int d)
{
  const std::array<int, 4>& idx = basis.NodeIndex(node);
  switch (basis.GetShape())
  {
    case LagrangeShape::Tetra:
      return { idx[0], idx[1], idx[2] };
    case LagrangeShape::Wedge:
      return d == 0 ? std::array<int, 3>{ idx[0], idx[1], 0 } : std::array<int, 3>{ idx[2], 0, 0 };
    default:
      return { idx[d], 0, 0 };
  }
}
}

bool LagrangeHull::Initialize(const LagrangeBasis& basis)
{
  this->N = 0;
  this->NumFactors = 0;
  if (!basis.IsInitialized() || basis.IsSpecial())
  {
    return false;
  }
  this->Basis = basis;
  FactorShape shapes[3];
  int first[3];
  const int nf = ShapeFactors(basis, shapes, first);
  this->Residual = Eps;
  this->GammaSize = 0.0;
  std::vector<std::vector<std::array<int, 3>>> indices(nf);
  for (int d = 0; d < nf; ++d)
  {
    const int n = shapes[d].Size();
    // M[j][a] = B_a(x_j), x_j the factor's equispaced nodes (multi-index j / order).
    std::vector<long double> original, m;
    if (!EquispacedFactorMatrices(shapes[d], indices[d], original, m))
    {
      return false;
    }
    Factor& f = this->Factors[d];
    f.Size = n;
    f.T.assign(m.begin(), m.end());
    long double rho = 0.0L;
    for (int i = 0; i < n; ++i)
    {
      long double row = 0.0L;
      for (int j = 0; j < n; ++j)
      {
        long double s = i == j ? 1.0L : 0.0L;
        for (int k = 0; k < n; ++k)
        {
          s -= original[static_cast<size_t>(i) * n + k] * f.T[static_cast<size_t>(k) * n + j];
        }
        row += std::abs(s);
      }
      rho = std::max(rho, row);
    }
    this->Residual += rho < 0.25L ? static_cast<double>(2.0L * rho) : 1.0;
    this->GammaSize += n;
  }
  this->NumFactors = nf;
  // Tensor layout of the nodes (factor 0 slowest).
  const int nodes = basis.GetNodeCount();
  this->Layout.assign(nodes, 0);
  for (int i = 0; i < nodes; ++i)
  {
    int pos = 0;
    for (int d = 0; d < nf; ++d)
    {
      const std::array<int, 3> m = NodeFactorIndex(basis, i, d);
      const auto it = std::find(indices[d].begin(), indices[d].end(), m);
      pos = pos * this->Factors[d].Size + static_cast<int>(it - indices[d].begin());
    }
    this->Layout[i] = pos;
  }
  this->N = nodes;
  // Row sums of |T| = products of the factors' row sums (Kronecker product).
  std::vector<double> ones(nodes, 1.0);
  this->Apply(ones.data(), true);
  this->RowAbs = ones;
  return true;
}

void LagrangeHull::Apply(double* v, bool absolute) const
{
  double line[MaxNodes];
  int inner = this->N;
  int outer = 1;
  for (int d = 0; d < this->NumFactors; ++d)
  {
    const Factor& f = this->Factors[d];
    inner /= f.Size;
    // Axis d has stride inner; the blocks before it repeat outer times.
    for (int o = 0; o < outer; ++o)
    {
      for (int i = 0; i < inner; ++i)
      {
        double* base = v + static_cast<size_t>(o) * f.Size * inner + i;
        for (int a = 0; a < f.Size; ++a)
        {
          const double* row = f.T.data() + static_cast<size_t>(a) * f.Size;
          double s = 0.0;
          for (int j = 0; j < f.Size; ++j)
          {
            s += (absolute ? std::abs(row[j]) : row[j]) * base[static_cast<size_t>(j) * inner];
          }
          line[a] = s;
        }
        for (int a = 0; a < f.Size; ++a)
        {
          base[static_cast<size_t>(a) * inner] = line[a];
        }
      }
    }
    outer *= f.Size;
  }
}

void LagrangeHull::Coefficients(const double* f, double* b) const
{
  for (int i = 0; i < this->N; ++i)
  {
    b[this->Layout[i]] = f[i];
  }
  this->Apply(b, false);
}

double LagrangeHull::BasisFunction(int a, const double pc[3]) const
{
  FactorShape shapes[3];
  int first[3];
  ShapeFactors(this->Basis, shapes, first);
  double v = 1.0;
  for (int d = this->NumFactors - 1; d >= 0; --d)
  {
    const int size = this->Factors[d].Size;
    const int k = a % size;
    a /= size;
    std::vector<std::array<int, 3>> indices;
    shapes[d].Indices(indices);
    v *= shapes[d].Function(indices[k], pc + first[d]);
  }
  return v;
}

void LagrangeHull::Hull(const double* f, double& lo, double& hi) const
{
  const int n = this->N;
  double b[MaxNodes], absB[MaxNodes];
  double maxF = 0.0;
  for (int i = 0; i < n; ++i)
  {
    b[this->Layout[i]] = f[i];
    absB[this->Layout[i]] = std::abs(f[i]);
    maxF = std::max(maxF, std::abs(f[i]));
  }
  this->Apply(b, false);
  this->Apply(absB, true);
  const double gamma = 2.0 * (this->GammaSize + 2.0) * Eps;
  lo = 1e300;
  hi = -1e300;
  for (int a = 0; a < n; ++a)
  {
    const double e = gamma * absB[a] + this->Residual * this->RowAbs[a] * maxF;
    lo = std::min(lo, b[a] - e);
    hi = std::max(hi, b[a] + e);
  }
  const double widen = OutsideSlack * (hi - lo) + 4.0 * Eps * std::max(std::abs(lo), std::abs(hi));
  lo -= widen;
  hi += widen;
}
}
