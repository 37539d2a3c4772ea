#include "hovChebyshevFit.h"

#include <cmath>  // fabs
#include <limits> // epsilon

namespace hov
{
namespace detail
{
namespace
{
constexpr double Eps = std::numeric_limits<double>::epsilon();
}

void ChebyshevPoints(double a, double b, double t[ChebN + 1])
{
  const double* cs = ChebyshevCosines;
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  for (int j = 0; j <= ChebN; ++j)
  {
    t[j] = (j == 0) ? b : (j == ChebN) ? a : mid + half * cs[j];
  }
}

namespace
{
/// cos(Pi j k / ChebN) for j, k in [0, ChebN], row j contiguous in k.
struct CosProducts
{
  double T[ChebN + 1][ChebN + 1];
  CosProducts()
  {
    for (int j = 0; j <= ChebN; ++j)
    {
      for (int k = 0; k <= ChebN; ++k)
      {
        this->T[j][k] = ChebyshevCosine(j * k);
      }
    }
  }
};
}

void ChebyshevCoefficients(const double f[ChebN + 1], double c[ChebN + 1])
{
  // Each c_k sums 0.5 (f_0 + (-1)^k f_N), then f_j cos(pi j k/N) for j = 1 ..
  // N - 1 in this order; all k at once per j (independent sums side by
  // side), with the same operations per k as one k after the other.
  static const CosProducts table; // thread-safe initialisation (C++11)
  for (int k = 0; k <= ChebN; ++k)
  {
    c[k] = 0.5 * (f[0] + ((k % 2) ? -f[ChebN] : f[ChebN]));
  }
  for (int j = 1; j < ChebN; ++j)
  {
    const double* row = table.T[j];
    const double fj = f[j];
    for (int k = 0; k <= ChebN; ++k)
    {
      c[k] += fj * row[k];
    }
  }
  for (int k = 0; k <= ChebN; ++k)
  {
    c[k] *= 2.0 / ChebN; // one multiplication by 1/8 (2 c_k could overflow)
  }
  c[0] *= 0.5;
  c[ChebN] *= 0.5;
}

int TruncationDegree(const double c[ChebN + 1], double floor, double tolerance, double& bound)
{
  double tail[ChebN + 2] = {};
  for (int k = ChebN; k >= 0; --k)
  {
    tail[k] = tail[k + 1] + std::fabs(c[k]); // tail[k] = sum_{j >= k} |c_j|
  }
  const double rounding = 64.0 * Eps * tail[0] + floor;
  int m = 0;
  while (m < MaxPieceDegree && 2.0 * tail[m + 1] + rounding > tolerance)
  {
    ++m;
  }
  bound = 2.0 * tail[m + 1] + rounding;
  return m;
}

Polynomial ChebyshevToLocal(const double* c, int m, double a, double b)
{
  double tPrev[MaxPieceDegree + 1] = { 1.0 }, tCur[MaxPieceDegree + 1] = { 0.0, 1.0 };
  Polynomial mono;
  mono.Degree = m;
  mono.C[0] = c[0];
  if (m >= 1)
  {
    mono.C[1] += c[1];
  }
  for (int k = 2; k <= m; ++k)
  {
    double tNext[MaxPieceDegree + 1] = {};
    for (int j = 0; j <= k; ++j)
    {
      tNext[j] = (j > 0 ? 2.0 * tCur[j - 1] : 0.0) - tPrev[j];
    }
    for (int j = 0; j <= k; ++j)
    {
      tPrev[j] = tCur[j];
      tCur[j] = tNext[j];
      mono.C[j] += c[k] * tNext[j];
    }
  }
  // x = -1 + tau / half.
  Polynomial local = ComposeAffine(mono, -1.0, 2.0 / (b - a));
  local.Degree = EffectiveDegree(local);
  return local;
}
}
}
