// Bernstein-form polynomials on [0, 1]: see hovBernstein.h.
#include "hovBernstein.h"

#include <vector> // the equispaced-Lagrange table

#include <algorithm> // std::min, std::max
#include <cmath>     // std::abs, std::cos
#include <limits>    // epsilon

namespace hov
{
namespace
{
constexpr double Eps = std::numeric_limits<double>::epsilon();
constexpr double Pi = 3.14159265358979323846;

/// Binomial coefficients C(n, k) for n <= MaxBernsteinDegree (exact in double).
struct BinomialTable
{
  double C[MaxBernsteinDegree + 1][MaxBernsteinDegree + 1] = {};
  constexpr BinomialTable()
  {
    for (int n = 0; n <= MaxBernsteinDegree; ++n)
    {
      C[n][0] = 1.0;
      for (int k = 1; k <= n; ++k)
      {
        C[n][k] = C[n - 1][k - 1] + (k <= n - 1 ? C[n - 1][k] : 0.0);
      }
    }
  }
};
// Built at compile time: no initialisation order or thread-safety question.
constexpr BinomialTable Binomials;

int ClampDegree(int n)
{
  return std::min(std::max(n, 0), MaxBernsteinDegree);
}

/// Sign of v with exact zeros as 0.
int SignOf(double v)
{
  return (v > 0.0) - (v < 0.0);
}

/// Sign changes of B[j] - level, zeros skipped.
int SignChanges(const BernsteinPolynomial& b, double level)
{
  int changes = 0, last = 0;
  for (int j = 0; j <= b.Degree; ++j)
  {
    const int s = SignOf(b.B[j] - level);
    if (s != 0)
    {
      changes += (last != 0 && s != last) ? 1 : 0;
      last = s;
    }
  }
  return changes;
}

/// The single root of b = level in [y0, y1] where the end values bracket it:
/// Newton from the secant point, kept inside the bracket, bisection when a
/// Newton step leaves it; stops at a 2-ulp bracket or an exact zero.
double SolveBracketed(const BernsteinPolynomial& b, double level, double y0, double y1)
{
  double f0 = EvaluateBernstein(b, y0) - level;
  double f1 = EvaluateBernstein(b, y1) - level;
  if (SignOf(f0) * SignOf(f1) > 0)
  {
    return std::abs(f0) <= std::abs(f1) ? y0 : y1; // rounding lost the bracket
  }
  double y = (f0 != f1) ? y0 + (y1 - y0) * f0 / (f0 - f1) : 0.5 * (y0 + y1);
  for (int iter = 0; iter < 200; ++iter)
  {
    y = std::min(std::max(y, y0), y1);
    double f, slope;
    EvaluateBernsteinWithDerivative(b, y, f, slope);
    f -= level;
    if (f == 0.0)
    {
      return y;
    }
    (SignOf(f) == SignOf(f0) ? y0 : y1) = y;
    (SignOf(f) == SignOf(f0) ? f0 : f1) = f;
    if (y1 - y0 <= 2.0 * Eps * std::max(std::abs(y0), std::abs(y1)))
    {
      break;
    }
    const double newton = (slope != 0.0) ? y - f / slope : y0 - 1.0;
    y = (newton > y0 && newton < y1) ? newton : 0.5 * (y0 + y1);
  }
  return std::abs(f0) <= std::abs(f1) ? y0 : y1;
}

/// Appends @p y unless it repeats the last root (within @p merge).
void AddRoot(double y, double merge, double* roots, int maxRoots, int& count, bool& complete)
{
  if (count > 0 && y - roots[count - 1] <= merge)
  {
    return;
  }
  if (count >= maxRoots)
  {
    complete = false;
    return;
  }
  roots[count++] = y;
}
}

double Binomial(int n, int k)
{
  return (n < 0 || n > MaxBernsteinDegree || k < 0 || k > n) ? 0.0 : Binomials.C[n][k];
}

double EvaluateBernstein(const BernsteinPolynomial& b, double y)
{
  const int n = ClampDegree(b.Degree);
  double w[MaxBernsteinDegree + 1];
  std::copy(b.B, b.B + n + 1, w);
  const double u = 1.0 - y;
  for (int level = n; level > 0; --level)
  {
    for (int j = 0; j < level; ++j)
    {
      w[j] = u * w[j] + y * w[j + 1];
    }
  }
  return w[0];
}

void EvaluateBernsteinWithDerivative(
  const BernsteinPolynomial& b, double y, double& value, double& slope)
{
  const int n = ClampDegree(b.Degree);
  if (n == 0)
  {
    value = b.B[0];
    slope = 0.0;
    return;
  }
  double w[MaxBernsteinDegree + 1];
  std::copy(b.B, b.B + n + 1, w);
  const double u = 1.0 - y;
  for (int level = n; level > 1; --level)
  {
    for (int j = 0; j < level; ++j)
    {
      w[j] = u * w[j] + y * w[j + 1];
    }
  }
  // w[0], w[1]: the degree-1 stage; b = u w0 + y w1, b' = n (w1 - w0).
  value = u * w[0] + y * w[1];
  slope = n * (w[1] - w[0]);
}

void SubdivideBernstein(const BernsteinPolynomial& b, double y, BernsteinPolynomial* left,
  BernsteinPolynomial* right)
{
  const int n = ClampDegree(b.Degree);
  double w[MaxBernsteinDegree + 1];
  std::copy(b.B, b.B + n + 1, w);
  BernsteinPolynomial l, r;
  l.Degree = r.Degree = n;
  const double u = 1.0 - y;
  l.B[0] = w[0];
  r.B[n] = w[n];
  for (int level = n; level > 0; --level)
  {
    for (int j = 0; j < level; ++j)
    {
      w[j] = u * w[j] + y * w[j + 1];
    }
    l.B[n - level + 1] = w[0];
    r.B[level - 1] = w[level - 1];
  }
  if (left)
  {
    *left = l;
  }
  if (right)
  {
    *right = r;
  }
}

BernsteinPolynomial RestrictBernstein(const BernsteinPolynomial& b, double y0, double y1)
{
  BernsteinPolynomial right = b, out = b;
  if (y0 > 0.0)
  {
    SubdivideBernstein(b, y0, nullptr, &right);
  }
  if (y1 < 1.0)
  {
    // y1 in right's coordinate: (y1 - y0) / (1 - y0).
    const double yr = (y0 > 0.0) ? (y1 - y0) / (1.0 - y0) : y1;
    SubdivideBernstein(right, yr, &out, nullptr);
  }
  else
  {
    out = right;
  }
  return out;
}

void BernsteinRange(const BernsteinPolynomial& b, double& lo, double& hi)
{
  const int n = ClampDegree(b.Degree);
  lo = hi = b.B[0];
  for (int j = 1; j <= n; ++j)
  {
    lo = std::min(lo, b.B[j]);
    hi = std::max(hi, b.B[j]);
  }
}

void BernsteinRangeSubdivided(const BernsteinPolynomial& b, int pieces, double& lo, double& hi)
{
  if (pieces <= 1)
  {
    BernsteinRange(b, lo, hi);
    return;
  }
  // Peel pieces off the left: piece k is [k/P, (k+1)/P]; the remainder
  // [k/P, 1] is split at 1/(P - k) of its length.
  BernsteinPolynomial rest = b, piece;
  lo = b.B[0];
  hi = b.B[0];
  for (int k = 0; k < pieces; ++k)
  {
    if (k + 1 < pieces)
    {
      SubdivideBernstein(rest, 1.0 / (pieces - k), &piece, &rest);
    }
    else
    {
      piece = rest;
    }
    double l, h;
    BernsteinRange(piece, l, h);
    lo = std::min(lo, l);
    hi = std::max(hi, h);
  }
}

BernsteinPolynomial BernsteinDerivative(const BernsteinPolynomial& b)
{
  const int n = ClampDegree(b.Degree);
  BernsteinPolynomial d;
  d.Degree = std::max(n - 1, 0);
  for (int j = 0; j < n; ++j)
  {
    d.B[j] = n * (b.B[j + 1] - b.B[j]);
  }
  return d;
}

BernsteinPolynomial ElevateBernstein(const BernsteinPolynomial& b, int degree)
{
  BernsteinPolynomial e = b;
  const int target = ClampDegree(degree);
  while (e.Degree < target)
  {
    // One step n -> n+1: E[j] = j/(n+1) B[j-1] + (1 - j/(n+1)) B[j].
    const int n = e.Degree;
    BernsteinPolynomial next;
    next.Degree = n + 1;
    next.B[0] = e.B[0];
    next.B[n + 1] = e.B[n];
    for (int j = 1; j <= n; ++j)
    {
      const double a = static_cast<double>(j) / (n + 1);
      next.B[j] = a * e.B[j - 1] + (1.0 - a) * e.B[j];
    }
    e = next;
  }
  return e;
}

bool MultiplyBernstein(
  const BernsteinPolynomial& a, const BernsteinPolynomial& b, BernsteinPolynomial& out)
{
  const int m = ClampDegree(a.Degree), n = ClampDegree(b.Degree);
  if (m + n > MaxBernsteinDegree)
  {
    return false;
  }
  // (ab)_k = sum_{i+j=k} C(m,i) C(n,j) / C(m+n,k) a_i b_j.
  BernsteinPolynomial p;
  p.Degree = m + n;
  for (int i = 0; i <= m; ++i)
  {
    for (int j = 0; j <= n; ++j)
    {
      p.B[i + j] += Binomials.C[m][i] * Binomials.C[n][j] * a.B[i] * b.B[j];
    }
  }
  for (int k = 0; k <= m + n; ++k)
  {
    p.B[k] /= Binomials.C[m + n][k];
  }
  out = p;
  return true;
}

BernsteinPolynomial BernsteinFromMonomial(const Polynomial& p, int minDegree)
{
  const int m = EffectiveDegree(p);
  const int n = ClampDegree(std::max(m, minDegree));
  // B[j] = sum_{k <= j} C(j,k) / C(n,k) a_k.
  BernsteinPolynomial b;
  b.Degree = n;
  for (int j = 0; j <= n; ++j)
  {
    double s = 0.0;
    for (int k = 0; k <= std::min(j, m); ++k)
    {
      s += Binomials.C[j][k] / Binomials.C[n][k] * p.C[k];
    }
    b.B[j] = s;
  }
  return b;
}

namespace
{
/// The cosines of ApproximateBernstein's Chebyshev interpolants of degree m
/// <= 8, each computed once by the expression the interpolant used to
/// evaluate per call (so the values are the same): Node[m][i] =
/// cos(pi i / m), Term[m][i][k] = cos(pi i k / m).
struct ChebyshevCosines
{
  double Node[9][9] = {};
  double Term[9][9][9] = {};
  ChebyshevCosines()
  {
    for (int m = 1; m <= 8; ++m)
    {
      for (int i = 0; i <= m; ++i)
      {
        this->Node[m][i] = std::cos(Pi * i / m);
        for (int k = 0; k <= m; ++k)
        {
          this->Term[m][i][k] = std::cos(Pi * i * k / m);
        }
      }
    }
  }
};

const ChebyshevCosines& Cosines()
{
  static const ChebyshevCosines cosines; // thread-safe initialisation
  return cosines;
}
}

Polynomial ApproximateBernstein(const BernsteinPolynomial& b, int maxDegree, double& errorBound)
{
  const int n = ClampDegree(b.Degree);
  const int m = std::min(std::min(std::max(maxDegree, 0), 8), n);
  Polynomial q;
  q.Degree = m;
  if (m == n)
  {
    // Exact: a_k = C(n,k) (k-th forward difference of B at 0).
    double diff[MaxBernsteinDegree + 1];
    std::copy(b.B, b.B + n + 1, diff);
    for (int k = 0; k <= n; ++k)
    {
      q.C[k] = Binomials.C[n][k] * diff[0];
      for (int j = 0; j + k < n; ++j)
      {
        diff[j] = diff[j + 1] - diff[j];
      }
    }
  }
  else
  {
    // Chebyshev interpolant at the m + 1 extreme points x_i = cos(pi i / m).
    const ChebyshevCosines& cosines = Cosines();
    double f[9], c[9];
    for (int i = 0; i <= m; ++i)
    {
      f[i] = EvaluateBernstein(b, 0.5 * (1.0 + cosines.Node[m][i]));
    }
    for (int k = 0; k <= m; ++k)
    {
      double s = 0.0;
      for (int i = 0; i <= m; ++i)
      {
        s += ((i == 0 || i == m) ? 0.5 : 1.0) * f[i] * cosines.Term[m][i][k];
      }
      c[k] = ((k == 0 || k == m) ? 1.0 : 2.0) * s / m;
    }
    // sum c_k T_k(x) in monomials of x (T_{k+1} = 2x T_k - T_{k-1}), then x = 2y - 1.
    // T_k has degree k <= m <= 8: nine coefficients. T_{k+1} is built only
    // while k < m (it would need a tenth at k = 8).
    double tPrev[9] = { 1.0 }, tCur[9] = { 0.0, 1.0 }, px[9] = {};
    px[0] = c[0];
    for (int k = 1; k <= m; ++k)
    {
      for (int j = 0; j <= k; ++j)
      {
        px[j] += c[k] * tCur[j];
      }
      if (k == m)
      {
        break;
      }
      double tNext[9] = {};
      for (int j = 0; j <= k; ++j)
      {
        tNext[j + 1] += 2.0 * tCur[j];
        tNext[j] -= tPrev[j];
      }
      std::copy(tCur, tCur + 9, tPrev);
      std::copy(tNext, tNext + 9, tCur);
    }
    Polynomial inX;
    inX.Degree = m;
    std::copy(px, px + m + 1, inX.C);
    q = ComposeAffine(inX, -1.0, 2.0);
    q.Degree = m;
  }
  const BernsteinPolynomial back = BernsteinFromMonomial(q, n);
  double worst = 0.0, scale = 0.0, coefSum = 0.0;
  for (int k = 0; k <= m; ++k)
  {
    coefSum += std::abs(q.C[k]);
  }
  for (int j = 0; j <= n; ++j)
  {
    worst = std::max(worst, std::abs(b.B[j] - back.B[j]));
    scale = std::max(scale, std::abs(b.B[j]));
  }
  errorBound = worst + 4.0 * (n + 2) * Eps * (scale + coefSum);
  return q;
}

int BernsteinRoots(const BernsteinPolynomial& b, double level, double* roots, int maxRoots,
  const BernsteinRootSettings& settings, bool* complete)
{
  struct Item
  {
    double Y0, Y1;
    BernsteinPolynomial P;
  };
  bool done = true;
  int count = 0;
  const int n = ClampDegree(b.Degree);
  const double merge = std::max(settings.Resolution, 4.0 * Eps);
  if (b.B[0] == level)
  {
    AddRoot(0.0, merge, roots, maxRoots, count, done);
  }
  // Depth-first, left first (roots come out sorted); depth <= 64 needs <= 65 entries.
  Item stack[66];
  int top = 0;
  stack[top++] = { 0.0, 1.0, b };
  stack[0].P.Degree = n;
  int examined = 0;
  while (top > 0)
  {
    const Item item = stack[--top];
    if (++examined > settings.MaxIntervals)
    {
      done = false;
      break;
    }
    const int changes = SignChanges(item.P, level);
    // An end exactly at the level hides its sign: split rather than solve.
    const bool endAtLevel = item.P.B[0] == level || item.P.B[n] == level;
    if (changes == 0)
    {
      // No interior root; a root at the right end is caught by B[n] == level.
    }
    else if (changes == 1 && !endAtLevel)
    {
      AddRoot(SolveBracketed(b, level, item.Y0, item.Y1), merge, roots, maxRoots, count, done);
    }
    else if (item.Y1 - item.Y0 <= settings.Resolution || top + 2 > 66)
    {
      AddRoot(0.5 * (item.Y0 + item.Y1), merge, roots, maxRoots, count, done);
    }
    else
    {
      const double mid = 0.5 * (item.Y0 + item.Y1);
      Item left{ item.Y0, mid, {} }, right{ mid, item.Y1, {} };
      SubdivideBernstein(item.P, 0.5, &left.P, &right.P);
      stack[top++] = right;
      stack[top++] = left;
      continue;
    }
    if (item.P.B[n] == level)
    {
      AddRoot(item.Y1, merge, roots, maxRoots, count, done);
    }
  }
  if (complete)
  {
    *complete = done;
  }
  return count;
}

namespace
{
/// EquispacedLagrangeBernstein's product (below), uncached.
BernsteinPolynomial EquispacedLagrangeProduct(int n, int i)
{
  // Product over k != i of the linear factors (n y - k) / (i - k), each with
  // Bernstein coefficients (value at 0, value at 1).
  BernsteinPolynomial p;
  p.Degree = 0;
  p.B[0] = 1.0;
  n = ClampDegree(n);
  for (int k = 0; k <= n; ++k)
  {
    if (k == i)
    {
      continue;
    }
    BernsteinPolynomial f;
    f.Degree = 1;
    f.B[0] = static_cast<double>(-k) / (i - k);
    f.B[1] = static_cast<double>(n - k) / (i - k);
    MultiplyBernstein(p, f, p);
  }
  return p;
}

/// Every (n, i) with 0 <= i <= n <= MaxBernsteinDegree (~500 polynomials, ~0.2 MB),
/// built once (a function-local static: thread-safe initialisation). The face
/// nets, derivative bounds and field restrictions ask for these thousands of
/// times per cell.
struct EquispacedTable
{
  std::vector<BernsteinPolynomial> P;
  EquispacedTable()
  {
    for (int n = 0; n <= MaxBernsteinDegree; ++n)
    {
      for (int i = 0; i <= n; ++i)
      {
        P.push_back(EquispacedLagrangeProduct(n, i));
      }
    }
  }
};
}

BernsteinPolynomial EquispacedLagrangeBernstein(int n, int i)
{
  static const EquispacedTable table;
  const int c = ClampDegree(n);
  if (n < 0 || i < 0 || i > c)
  {
    return EquispacedLagrangeProduct(n, i); // outside the table: as before
  }
  return table.P[c * (c + 1) / 2 + i];
}
}
