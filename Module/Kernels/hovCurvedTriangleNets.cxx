// Triangular Bernstein nets of the curved face search: see hovCurvedTriangleNets.h.
#include "hovCurvedTriangleNets.h"

#include "hovBernsteinFactors.h" // the triangle factor's conversion
#include "hovLagrangeBasis.h"     // MaxLagrangeOrder

#include <array>   // the per-degree tables
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

/// m! / (i! j! k!) at TriangleNetIndex(m, j, k), i = m - j - k (built once).
const double* Multinomials(int m)
{
  static const std::array<std::array<double, MaxSize>, MaxDegree + 1> tables = [] {
    std::array<std::array<double, MaxSize>, MaxDegree + 1> t{};
    for (int d = 0; d <= MaxDegree; ++d)
    {
      for (int j = 0; j <= d; ++j)
      {
        for (int k = 0; j + k <= d; ++k)
        {
          t[d][TriangleNetIndex(d, j, k)] =
            Factorial(d) / (Factorial(d - j - k) * Factorial(j) * Factorial(k));
        }
      }
    }
    return t;
  }();
  return tables[m].data();
}

/// The triangle factor's conversion from equispaced values (hovBernsteinFactors.h:
/// its multi-indices (a, b) are the powers of u and v in TriangleNetIndex
/// order), per degree, in double; empty if singular. Built once.
const std::vector<double>& Conversion(int n)
{
  static const std::array<std::vector<double>, MaxDegree + 1> tables = [] {
    std::array<std::vector<double>, MaxDegree + 1> t;
    for (int d = 1; d <= MaxDegree; ++d)
    {
      std::vector<std::array<int, 3>> indices;
      std::vector<long double> m, inverse;
      if (EquispacedFactorMatrices(FactorShape{ 2, d }, indices, m, inverse))
      {
        t[d].assign(inverse.begin(), inverse.end());
      }
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
