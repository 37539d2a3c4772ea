// Triangular Bernstein nets of the curved face search: see hovCurvedTriangleNets.h.
#include "hovCurvedTriangleNets.h"

#include "hovLagrangeBasis.h" // MaxLagrangeOrder

#include <array>   // the per-degree tables
#include <cmath>   // std::abs, std::pow
#include <utility> // std::swap
#include <vector>  // the tables

namespace hov
{
namespace detail
{
namespace
{
constexpr int MaxDegree = 10;
static_assert(MaxDegree >= MaxLagrangeOrder, "triangular nets up to the largest Lagrange order");
constexpr int MaxSize = TriangleNetSize(MaxDegree);

/// B^n_{ijk}(l0, l1, l2) for every i + j + k = n, at TriangleNetIndex(n, j, k)
/// (the triangular recursion B^m_{ijk} = l0 B^{m-1}_{i-1,j,k} + l1 B^{m-1}_{i,j-1,k}
/// + l2 B^{m-1}_{i,j,k-1}: no factorials, no cancellation for l in [0, 1]).
void TriangleBasis(int n, double l0, double l1, double l2, double* b)
{
  double prev[MaxSize];
  b[0] = 1.0;
  for (int m = 1; m <= n; ++m)
  {
    const int size = TriangleNetSize(m - 1);
    for (int q = 0; q < size; ++q)
    {
      prev[q] = b[q];
    }
    for (int j = 0; j <= m; ++j)
    {
      for (int k = 0; j + k <= m; ++k)
      {
        double s = 0.0;
        if (j + k <= m - 1)
        {
          s += l0 * prev[TriangleNetIndex(m - 1, j, k)];
        }
        if (j > 0)
        {
          s += l1 * prev[TriangleNetIndex(m - 1, j - 1, k)];
        }
        if (k > 0)
        {
          s += l2 * prev[TriangleNetIndex(m - 1, j, k - 1)];
        }
        b[TriangleNetIndex(m, j, k)] = s;
      }
    }
  }
}

/// m! / (i! j! k!) at TriangleNetIndex(m, j, k), i = m - j - k (built once).
const double* Multinomials(int m)
{
  static const std::array<std::array<double, MaxSize>, MaxDegree + 1> tables = [] {
    std::array<std::array<double, MaxSize>, MaxDegree + 1> t{};
    for (int d = 0; d <= MaxDegree; ++d)
    {
      // B^d at l = (1, 1, 1) is the multinomial coefficient.
      TriangleBasis(d, 1.0, 1.0, 1.0, t[d].data());
    }
    return t;
  }();
  return tables[m].data();
}

/// The inverse of the collocation matrix V[p][q] = B^n_q(point p) at the
/// equispaced points, row-major (N x N, N = TriangleNetSize(n)); empty if singular.
std::vector<double> ConversionMatrix(int n)
{
  const int size = TriangleNetSize(n);
  std::vector<double> a(static_cast<size_t>(size) * size), inv(a.size(), 0.0);
  for (int j = 0; j <= n; ++j)
  {
    for (int k = 0; j + k <= n; ++k)
    {
      const int p = TriangleNetIndex(n, j, k);
      const double u = static_cast<double>(j) / n, v = static_cast<double>(k) / n;
      TriangleBasis(n, 1.0 - u - v, u, v, &a[static_cast<size_t>(p) * size]);
      inv[static_cast<size_t>(p) * size + p] = 1.0;
    }
  }
  // Gauss-Jordan with partial pivoting: [V | I] -> [I | V^-1].
  for (int c = 0; c < size; ++c)
  {
    int pivot = c;
    for (int r = c + 1; r < size; ++r)
    {
      pivot = std::abs(a[static_cast<size_t>(r) * size + c]) >
          std::abs(a[static_cast<size_t>(pivot) * size + c])
        ? r
        : pivot;
    }
    if (!(std::abs(a[static_cast<size_t>(pivot) * size + c]) > 0.0))
    {
      return {};
    }
    for (int q = 0; q < size; ++q)
    {
      std::swap(a[static_cast<size_t>(c) * size + q], a[static_cast<size_t>(pivot) * size + q]);
      std::swap(inv[static_cast<size_t>(c) * size + q], inv[static_cast<size_t>(pivot) * size + q]);
    }
    const double d = a[static_cast<size_t>(c) * size + c];
    for (int q = 0; q < size; ++q)
    {
      a[static_cast<size_t>(c) * size + q] /= d;
      inv[static_cast<size_t>(c) * size + q] /= d;
    }
    for (int r = 0; r < size; ++r)
    {
      const double f = a[static_cast<size_t>(r) * size + c];
      if (r == c || f == 0.0)
      {
        continue;
      }
      for (int q = 0; q < size; ++q)
      {
        a[static_cast<size_t>(r) * size + q] -= f * a[static_cast<size_t>(c) * size + q];
        inv[static_cast<size_t>(r) * size + q] -= f * inv[static_cast<size_t>(c) * size + q];
      }
    }
  }
  return inv;
}

const std::vector<double>& Conversion(int n)
{
  static const std::array<std::vector<double>, MaxDegree + 1> tables = [] {
    std::array<std::vector<double>, MaxDegree + 1> t;
    for (int d = 1; d <= MaxDegree; ++d)
    {
      t[d] = ConversionMatrix(d);
    }
    return t;
  }();
  return tables[n];
}
}

bool EquispacedTriangleBernstein(int n, const double* values, int stride, int dim, double* out)
{
  if (n < 1 || n > MaxDegree || Conversion(n).empty())
  {
    return false;
  }
  const std::vector<double>& m = Conversion(n);
  const int size = TriangleNetSize(n);
  for (int q = 0; q < size; ++q)
  {
    for (int c = 0; c < dim; ++c)
    {
      double s = 0.0;
      for (int p = 0; p < size; ++p)
      {
        s += m[static_cast<size_t>(q) * size + p] * values[stride * p + c];
      }
      out[dim * q + c] = s;
    }
  }
  return true;
}

void EvaluateTriangleNet(
  const double* net, int n, double u, double v, double x[3], double xu[3], double xv[3])
{
  // x and both derivatives from the degree m = n - 1 basis:
  //   x   = sum B^m_{ijk} (l0 b_{i+1,j,k} + u b_{i,j+1,k} + v b_{i,j,k+1}),
  //   x_u = n sum B^m_{ijk} (b_{i,j+1,k} - b_{i+1,j,k}), x_v likewise with b_{i,j,k+1}.
  const int m = n - 1;
  const double l0 = 1.0 - u - v;
  double pu[MaxDegree + 1], pv[MaxDegree + 1], pl[MaxDegree + 1];
  pu[0] = pv[0] = pl[0] = 1.0;
  for (int q = 1; q <= m; ++q)
  {
    pu[q] = pu[q - 1] * u;
    pv[q] = pv[q - 1] * v;
    pl[q] = pl[q - 1] * l0;
  }
  const double* coef = Multinomials(m);
  for (int c = 0; c < 3; ++c)
  {
    x[c] = xu[c] = xv[c] = 0.0;
  }
  int q = 0, p = 0; // the (j, k) entry of the degree m and of the degree n layout
  for (int j = 0; j <= m; ++j, ++p)
  {
    const int row = n + 1 - j; // TriangleNetIndex(n, j + 1, k) - TriangleNetIndex(n, j, k)
    for (int k = 0; j + k <= m; ++k, ++q, ++p)
    {
      const double w = coef[q] * pu[j] * pv[k] * pl[m - j - k];
      const double* pi = net + 3 * p; // b_{i+1, j, k}
      const double* pj = pi + 3 * row;
      const double* pk = pi + 3;
      for (int c = 0; c < 3; ++c)
      {
        x[c] += w * (l0 * pi[c] + u * pj[c] + v * pk[c]);
        xu[c] += w * (pj[c] - pi[c]);
        xv[c] += w * (pk[c] - pi[c]);
      }
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    xu[c] *= n;
    xv[c] *= n;
  }
}

void SplitTriangleNet(const double* net, double* first, double* second, int n, int m)
{
  const int a = m == 0 ? 1 : 0, b = m == 2 ? 1 : 2; // the edge's vertices, a < b
  double w[MaxDegree + 1];
  int index[MaxDegree + 1];
  for (int c = 0; c <= n; ++c)
  {
    // The row of index m = c: w[t] has index b = t, index a = d - t.
    const int d = n - c;
    for (int t = 0; t <= d; ++t)
    {
      int ijk[3];
      ijk[m] = c;
      ijk[a] = d - t;
      ijk[b] = t;
      index[t] = TriangleNetIndex(n, ijk[1], ijk[2]);
      w[t] = net[index[t]];
    }
    // Stage r: the a-half gets w[0], the b-half w[d - r] (before the averaging).
    for (int r = 0; r <= d; ++r)
    {
      first[index[r]] = w[0];
      second[index[d - r]] = w[d - r];
      for (int i = 0; i < d - r; ++i)
      {
        w[i] = 0.5 * (w[i] + w[i + 1]);
      }
    }
  }
}
}
}
