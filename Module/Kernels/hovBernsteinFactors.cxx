// Bernstein bases of the Lagrange cells' factors: see hovBernsteinFactors.h.
#include "hovBernsteinFactors.h"

#include <algorithm> // std::swap
#include <cmath>     // std::abs

namespace hov
{
namespace detail
{
double Factorial(int n)
{
  double f = 1.0;
  for (int k = 2; k <= n; ++k)
  {
    f *= k;
  }
  return f;
}

double Power(double x, int k)
{
  double p = 1.0;
  for (int i = 0; i < k; ++i)
  {
    p *= x;
  }
  return p;
}

/// Inverts the n x n row-major @p m in place (Gauss-Jordan, partial pivoting,
/// long double); false if singular.
bool InvertDense(std::vector<long double>& m, int n)
{
  const auto at = [n](int r, int c) { return static_cast<size_t>(r) * n + c; };
  std::vector<long double> inv(static_cast<size_t>(n) * n, 0.0L);
  for (int i = 0; i < n; ++i)
  {
    inv[at(i, i)] = 1.0L;
  }
  for (int c = 0; c < n; ++c)
  {
    int pivot = c;
    for (int r = c + 1; r < n; ++r)
    {
      pivot = std::abs(m[at(r, c)]) > std::abs(m[at(pivot, c)]) ? r : pivot;
    }
    const long double p = m[at(pivot, c)];
    if (p == 0.0L)
    {
      return false;
    }
    for (int k = 0; k < n && pivot != c; ++k)
    {
      std::swap(m[at(pivot, k)], m[at(c, k)]);
      std::swap(inv[at(pivot, k)], inv[at(c, k)]);
    }
    for (int k = 0; k < n; ++k)
    {
      m[at(c, k)] /= p;
      inv[at(c, k)] /= p;
    }
    for (int r = 0; r < n; ++r)
    {
      const long double f = m[at(r, c)];
      for (int k = 0; r != c && f != 0.0L && k < n; ++k)
      {
        m[at(r, k)] -= f * m[at(c, k)];
        inv[at(r, k)] -= f * inv[at(c, k)];
      }
    }
  }
  m.swap(inv);
  return true;
}

int FactorShape::Size() const
{
  const int p = this->Order;
  return this->Kind == 3 ? (p + 1) * (p + 2) * (p + 3) / 6
    : this->Kind == 2    ? (p + 1) * (p + 2) / 2
                         : p + 1;
}

void FactorShape::Indices(std::vector<std::array<int, 3>>& out) const
{
  out.clear();
  const int p = this->Order;
  for (int a = 0; a <= p; ++a)
    for (int b = 0; b <= (this->Kind >= 2 ? p - a : 0); ++b)
      for (int c = 0; c <= (this->Kind == 3 ? p - a - b : 0); ++c)
        out.push_back({ a, b, c });
}

double FactorShape::Function(const std::array<int, 3>& m, const double* x) const
{
  const int p = this->Order;
  if (this->Kind == 1)
  {
    return Factorial(p) / (Factorial(m[0]) * Factorial(p - m[0])) * Power(x[0], m[0]) *
      Power(1.0 - x[0], p - m[0]);
  }
  const int dims = this->Kind;
  double last = 1.0, v = Factorial(p);
  int rest = p;
  for (int d = 0; d < dims; ++d)
  {
    last -= x[d];
    rest -= m[d];
    v *= Power(x[d], m[d]) / Factorial(m[d]);
  }
  return v * Power(last, rest) / Factorial(rest);
}

bool EquispacedFactorMatrices(const FactorShape& shape, std::vector<std::array<int, 3>>& indices,
  std::vector<long double>& m, std::vector<long double>& t)
{
  const int n = shape.Size();
  shape.Indices(indices);
  m.assign(static_cast<size_t>(n) * n, 0.0L);
  for (int j = 0; j < n; ++j)
  {
    double x[3];
    for (int k = 0; k < 3; ++k)
    {
      x[k] = static_cast<double>(indices[j][k]) / shape.Order;
    }
    for (int a = 0; a < n; ++a)
    {
      m[static_cast<size_t>(j) * n + a] = shape.Function(indices[a], x);
    }
  }
  t = m;
  return InvertDense(t, n);
}
}
}
