#include "hovPolynomial.h"

#include <algorithm> // std::max, std::min, std::sort
#include <cmath>     // fma, fabs, sqrt, ldexp, ilogb, isfinite
#include <limits>    // epsilon, infinity

namespace hov
{
namespace
{
constexpr double Eps = std::numeric_limits<double>::epsilon();

// Safeguarded Newton stops after this many steps even if the bracket has not
// shrunk to 2 ulp. Bisection alone needs at most ~64 steps per binade crossed
// and the brackets live in [lo, hi] (<= 2100 binades), so this is only reached
// for pathological input; the last iterate is returned.
constexpr int MaxSolveIterations = 2200;

/// Kahan's discriminant bh^2 - a c: the exact products are used (through FMA)
/// when the difference cancels, so the error is <= 2 ulp of the result.
double Discriminant(double bh, double a, double c)
{
  const double p = bh * bh;
  const double q = a * c;
  double d = p - q;
  if (p + q >= 3.0 * std::fabs(d))
  {
    const double dp = std::fma(bh, bh, -p);
    const double dq = std::fma(a, c, -q);
    d = (p - q) + (dp - dq);
  }
  return d;
}

/// Collects roots in increasing order, clamping onto [lo, hi] within the
/// slack and merging roots closer than the slack.
struct RootList
{
  double* Roots;
  int Count = 0;
  double Lo, Hi, Slack;

  RootList(double* roots, double lo, double hi)
    : Roots(roots)
    , Lo(lo)
    , Hi(hi)
    , Slack(RootEndSlackUlps * Eps * std::max(std::fabs(lo), std::fabs(hi)))
  {
  }

  void Add(double t)
  {
    if (!(t >= this->Lo - this->Slack && t <= this->Hi + this->Slack))
    {
      return; // outside, or NaN/inf from a vanishing leading coefficient
    }
    t = std::min(std::max(t, this->Lo), this->Hi);
    if (this->Count > 0 && t - this->Roots[this->Count - 1] <= this->Slack)
    {
      return;
    }
    if (this->Count < Polynomial::MaxDegree)
    {
      this->Roots[this->Count++] = t;
    }
  }
};

/// Roots of a t^2 + b t + c = 0 (coefficients scaled to <= 1) into @p list.
void QuadraticRoots(double a, double b, double c, RootList& list)
{
  double r[2];
  int n = 0;
  if (a == 0.0)
  {
    if (b == 0.0)
    {
      return;
    }
    r[n++] = -c / b;
  }
  else
  {
    const double bh = -0.5 * b; // exact
    const double d = Discriminant(bh, a, c);
    const double scale = bh * bh + std::fabs(a * c);
    if (std::fabs(d) <= NearDoubleRootEps * NearDoubleRootEps * scale)
    {
      r[n++] = bh / a; // tangency or double root: once
    }
    else if (d > 0.0)
    {
      // Cancellation-free: q has the sign of bh, so bh + sign(bh) sqrt(d) adds
      // magnitudes. q != 0 since d > 0.
      const double q = bh + std::copysign(std::sqrt(d), bh);
      r[n++] = q / a; // large and inaccurate-free; inf/out of range if a ~ 0
      r[n++] = c / q;
      if (r[0] > r[1])
      {
        std::swap(r[0], r[1]);
      }
    }
  }
  for (int i = 0; i < n; ++i)
  {
    list.Add(r[i]);
  }
}

/// Root of p - level between @p a and @p b, where the values @p fa and @p fb
/// have opposite signs (rtsafe-style safeguarded Newton). Starts from the
/// regula falsi point; stops when the Newton step is below an ulp of x (the
/// root is then within ~1 ulp plus the evaluation error over |p'|), the
/// bracket is 2 ulp wide, or p - level is zero within its evaluation error.
double Bracketed(const Polynomial& p, double level, double a, double b, double fa, double fb)
{
  double xNeg = fa < 0.0 ? a : b; // where p - level < 0
  double xPos = fa < 0.0 ? b : a;
  double x = a + (b - a) * (fa / (fa - fb)); // |fa/(fa-fb)| <= 1: inside [a, b]
  if (!(x > std::min(a, b) && x < std::max(a, b)))
  {
    x = 0.5 * a + 0.5 * b;
  }
  double fPrev = std::numeric_limits<double>::infinity();
  for (int iter = 0; iter < MaxSolveIterations; ++iter)
  {
    double bound = 0.0;
    const double f = EvaluateCompensated(p, x, level, &bound);
    if (std::fabs(f) <= bound)
    {
      return x; // zero within the evaluation error
    }
    (f < 0.0 ? xNeg : xPos) = x;
    const double lo = std::min(xNeg, xPos), hi = std::max(xNeg, xPos);
    if (hi - lo <= 2.0 * Eps * std::max(std::fabs(lo), std::fabs(hi)) ||
      hi - lo <= 2.0 * std::numeric_limits<double>::denorm_min())
    {
      return x;
    }
    double value = 0.0, slope = 0.0;
    EvaluateWithDerivative(p, x, value, slope);
    const double step = f / slope;
    double next = x - step;
    if (std::fabs(step) <= Eps * std::fabs(x) && next >= lo && next <= hi)
    {
      return next; // converged: the correction is below an ulp
    }
    // Bisect when Newton leaves the bracket or stalls (|f| not halved).
    if (!(next > lo && next < hi) || std::fabs(f) > 0.5 * std::fabs(fPrev))
    {
      next = 0.5 * lo + 0.5 * hi;
    }
    if (next == x)
    {
      return x;
    }
    fPrev = f;
    x = next;
  }
  return x;
}

/// FindRoots on a polynomial of exact degree p.Degree whose coefficients are
/// scaled to magnitude <= ~1.
void RootsRecursive(const Polynomial& p, double level, RootList& list)
{
  if (p.Degree <= 2)
  {
    QuadraticRoots(p.Degree == 2 ? p.C[2] : 0.0, p.Degree >= 1 ? p.C[1] : 0.0, p.C[0] - level, list);
    return;
  }
  // Extrema split [lo, hi] into intervals where p is monotone.
  double crit[Polynomial::MaxDegree];
  RootList critical(crit, list.Lo, list.Hi);
  RootsRecursive(Derivative(p), 0.0, critical);
  double x[Polynomial::MaxDegree + 2];
  int n = 0;
  x[n++] = list.Lo;
  for (int i = 0; i < critical.Count; ++i)
  {
    if (crit[i] > x[n - 1] && crit[i] < list.Hi)
    {
      x[n++] = crit[i];
    }
  }
  if (list.Hi > x[n - 1])
  {
    x[n++] = list.Hi;
  }
  double f[Polynomial::MaxDegree + 2];
  for (int i = 0; i < n; ++i)
  {
    double bound = 0.0;
    f[i] = EvaluateCompensated(p, x[i], level, &bound);
    if (std::fabs(f[i]) <= bound)
    {
      f[i] = 0.0; // an end root, a tangency or a multiple root
    }
  }
  for (int i = 0; i < n; ++i)
  {
    if (f[i] == 0.0)
    {
      list.Add(x[i]);
    }
    if (i + 1 < n && ((f[i] < 0.0 && f[i + 1] > 0.0) || (f[i] > 0.0 && f[i + 1] < 0.0)))
    {
      list.Add(Bracketed(p, level, x[i], x[i + 1], f[i], f[i + 1]));
    }
  }
}
}

Polynomial Polynomial::FromCoefficients(std::initializer_list<double> c)
{
  Polynomial p;
  int i = 0;
  for (double v : c)
  {
    if (i > MaxDegree)
    {
      break;
    }
    p.C[i++] = v;
  }
  p.Degree = std::max(0, i - 1);
  return p;
}

void EvaluateWithDerivative(const Polynomial& p, double t, double& value, double& slope)
{
  const int n = std::min(std::max(p.Degree, 0), Polynomial::MaxDegree);
  double r = p.C[n];
  double d = 0.0;
  for (int i = n - 1; i >= 0; --i)
  {
    d = d * t + r;
    r = r * t + p.C[i];
  }
  value = r;
  slope = d;
}

double EvaluateCompensated(const Polynomial& p, double t, double level, double* errorBound)
{
  const int n = std::min(std::max(p.Degree, 0), Polynomial::MaxDegree);
  double r = p.C[n];
  double e = 0.0;                   // running error term (Horner on the errors)
  double mag = std::fabs(p.C[n]);   // sum |c_i| |t|^i
  const double at = std::fabs(t);
  for (int i = n - 1; i >= 0; --i)
  {
    const double prod = r * t;
    const double prodErr = std::fma(r, t, -prod); // exact: r t = prod + prodErr
    const double sum = prod + p.C[i];
    const double z = sum - prod; // TwoSum: prod + c = sum + sumErr exactly
    const double sumErr = (prod - (sum - z)) + (p.C[i] - z);
    r = sum;
    e = std::fma(e, t, prodErr + sumErr);
    mag = mag * at + std::fabs(p.C[i]);
  }
  const double diff = r - level;
  const double z = diff - r;
  const double diffErr = (r - (diff - z)) + (-level - z);
  const double result = diff + (e + diffErr);
  if (errorBound)
  {
    // Graillat et al.: |result - exact| <= eps |exact| + gamma_2n^2 magnitude;
    // factors of 2 cover the level's subtraction and the rounding of the
    // bound itself; a few denormals cover underflow in the products.
    const double m = 2.0 * n + 2.0;
    const double gamma = m * Eps / (1.0 - m * Eps);
    *errorBound = 2.0 * Eps * std::fabs(result) + 2.0 * gamma * gamma * (mag + std::fabs(level)) +
      16.0 * std::numeric_limits<double>::denorm_min();
  }
  return result;
}

Polynomial ComposeAffine(const Polynomial& p, double offset, double scale)
{
  const int n = std::min(std::max(p.Degree, 0), Polynomial::MaxDegree);
  long double q[Polynomial::MaxDegree + 1] = {};
  q[0] = p.C[n];
  // Horner on polynomials: q <- q (offset + scale t) + C[i].
  for (int i = n - 1, deg = 0; i >= 0; --i, ++deg)
  {
    for (int j = deg + 1; j >= 1; --j)
    {
      q[j] = static_cast<long double>(offset) * q[j] + static_cast<long double>(scale) * q[j - 1];
    }
    q[0] = static_cast<long double>(offset) * q[0] + p.C[i];
  }
  Polynomial out;
  out.Degree = n;
  for (int j = 0; j <= n; ++j)
  {
    out.C[j] = static_cast<double>(q[j]);
  }
  return out;
}

int FindRoots(const Polynomial& p, double level, double lo, double hi, double* roots)
{
  if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi) || !std::isfinite(level))
  {
    return 0;
  }
  const int n = EffectiveDegree(p);
  double largest = std::fabs(level);
  for (int i = 0; i <= n; ++i)
  {
    if (!std::isfinite(p.C[i]))
    {
      return 0;
    }
    largest = std::max(largest, std::fabs(p.C[i]));
  }
  if (n == 0 || largest == 0.0)
  {
    return 0; // constant: no crossing (or identically at the level)
  }
  // Scale by a power of two (exact) so that the largest coefficient is ~1:
  // products in the discriminant and the bounds can neither overflow nor
  // lose all digits to underflow.
  const int e = std::ilogb(largest);
  Polynomial q;
  q.Degree = n;
  for (int i = 0; i <= n; ++i)
  {
    q.C[i] = std::ldexp(p.C[i], -e);
  }
  RootList list(roots, lo, hi);
  RootsRecursive(q, std::ldexp(level, -e), list);
  return list.Count;
}

double SolveMonotone(const Polynomial& p, double level, double lo, double hi)
{
  double boundLo = 0.0, boundHi = 0.0;
  const double fLo = EvaluateCompensated(p, lo, level, &boundLo);
  if (std::fabs(fLo) <= boundLo || !(hi > lo))
  {
    return lo;
  }
  const double fHi = EvaluateCompensated(p, hi, level, &boundHi);
  if (std::fabs(fHi) <= boundHi)
  {
    return hi;
  }
  if ((fLo < 0.0) == (fHi < 0.0))
  {
    return std::fabs(fLo) <= std::fabs(fHi) ? lo : hi; // not bracketed
  }
  if (EffectiveDegree(p) <= 2)
  {
    // Closed form (cheaper than Newton): exactly one root in a sign change.
    double roots[Polynomial::MaxDegree];
    if (FindRoots(p, level, lo, hi, roots) == 1)
    {
      return roots[0];
    }
  }
  return Bracketed(p, level, lo, hi, fLo, fHi);
}
}
