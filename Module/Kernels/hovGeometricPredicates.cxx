// Filtered exact orientation predicates (see hovGeometricPredicates.h).
#include "hovGeometricPredicates.h"

#include <boost/multiprecision/cpp_int.hpp> // cpp_rational: exact fallback

#include <cmath>

namespace hov
{
namespace
{
using Rational = boost::multiprecision::cpp_rational;

constexpr double Eps = 1.1102230246251565e-16; // 2^-53, half an ulp of 1
constexpr double ErrBound2 = (3.0 + 16.0 * Eps) * Eps;
constexpr double ErrBound3 = (7.0 + 56.0 * Eps) * Eps;
// Below this permanent, products of differences may have lost bits to
// underflow and the a-priori bound no longer holds: decide exactly.
constexpr double TinyPermanent = 1e-250;

int Sign(const Rational& r)
{
  return r.sign() > 0 ? 1 : (r.sign() < 0 ? -1 : 0);
}

bool Finite(const double* p, int n)
{
  for (int i = 0; i < n; ++i)
  {
    if (!std::isfinite(p[i]))
    {
      return false;
    }
  }
  return true;
}

/// Accept the double determinant when it is clearly away from zero.
bool Decided(double det, double permanent, double bound)
{
  return std::isfinite(det) && std::isfinite(permanent) && permanent > TinyPermanent &&
    std::fabs(det) > bound * permanent;
}

int Det3Sign(const Rational m[3][3])
{
  const Rational det = m[0][2] * (m[1][0] * m[2][1] - m[2][0] * m[1][1]) +
    m[1][2] * (m[2][0] * m[0][1] - m[0][0] * m[2][1]) +
    m[2][2] * (m[0][0] * m[1][1] - m[1][0] * m[0][1]);
  return Sign(det);
}

// ---- Stage 2: expansion arithmetic (Shewchuk) when the differences are exact.
/// Exact a - b as x + y (y = 0 iff the difference was exact).
inline double DiffTail(double a, double b, double x)
{
  const double bvirt = a - x;
  const double avirt = x + bvirt;
  return (a - avirt) + (bvirt - b);
}

inline void TwoSum(double a, double b, double& x, double& y)
{
  x = a + b;
  const double bvirt = x - a;
  const double avirt = x - bvirt;
  y = (a - avirt) + (b - bvirt);
}

/// The tail y of x = a + b (TwoSum's, x given).
inline void TwoSumTail(double a, double b, double x, double& y)
{
  const double bvirt = x - a;
  const double avirt = x - bvirt;
  y = (a - avirt) + (b - bvirt);
}

/// h = e + b (nonoverlapping, increasing magnitude, zeros eliminated).
int Grow(const double* e, int n, double b, double* h)
{
  double q = b;
  int k = 0;
  for (int i = 0; i < n; ++i)
  {
    double qn, hh;
    TwoSum(q, e[i], qn, hh);
    q = qn;
    if (hh != 0)
    {
      h[k++] = hh;
    }
  }
  if (q != 0 || k == 0)
  {
    h[k++] = q;
  }
  return k;
}

/// h = e * b (exact with fma, no underflow assumed).
int Scale(const double* e, int n, double b, double* h)
{
  double q = e[0] * b;
  double hh = std::fma(e[0], b, -q);
  int k = 0;
  if (hh != 0)
  {
    h[k++] = hh;
  }
  for (int i = 1; i < n; ++i)
  {
    const double p1 = e[i] * b;
    const double p0 = std::fma(e[i], b, -p1);
    double sum;
    TwoSum(q, p0, sum, hh);
    if (hh != 0)
    {
      h[k++] = hh;
    }
    q = p1 + sum; // Fast_Two_Sum(p1, sum)
    hh = sum - (q - p1);
    if (hh != 0)
    {
      h[k++] = hh;
    }
  }
  if (q != 0 || k == 0)
  {
    h[k++] = q;
  }
  return k;
}

int Add(const double* e, int ne, const double* f, int nf, double* h)
{
  double tmp[64];
  int n = ne;
  std::copy(e, e + ne, tmp);
  for (int i = 0; i < nf; ++i)
  {
    n = Grow(tmp, n, f[i], h);
    std::copy(h, h + n, tmp);
  }
  return n;
}

/// Exact sign of x*y - z*w (2-term products, exact doubles).
int Minor(double x, double y, double z, double w, double* m)
{
  const double p = x * y, q = z * w;
  const double e[2] = { std::fma(x, y, -p), p };
  const double f[2] = { -std::fma(z, w, -q), -q };
  double a[2], b[2];
  const int na = Grow(e, 1, e[1], a);
  const int nb = Grow(f, 1, f[1], b);
  return Add(a, na, b, nb, m);
}

/**
 * det[r0; r1; r2] by cofactors when every product and difference on the way
 * is exact in double (each checked: the fma residual of a product, the tail
 * of a sum, are zero), e.g. points of a grid with integer or dyadic
 * coordinates, where a corner lying exactly on a face plane makes the filter
 * fail. False if any step rounds. Entries as ExactRows() leaves them (no
 * under/overflow, so a zero residual means an exact product).
 */
bool DoubleDet3(const double* const r[3], double& det)
{
  double acc = 0;
  for (int i = 0; i < 3; ++i)
  {
    const double* u = r[(i + 1) % 3];
    const double* v = r[(i + 2) % 3];
    const double p = u[0] * v[1], q = v[0] * u[1];
    const double m = p - q;
    const double t = m * r[i][2];
    const double sum = acc + t;
    double tail;
    TwoSumTail(acc, t, sum, tail);
    if (std::fma(u[0], v[1], -p) != 0 || std::fma(v[0], u[1], -q) != 0 ||
      DiffTail(p, q, m) != 0 || std::fma(m, r[i][2], -t) != 0 || tail != 0 ||
      !std::isfinite(sum))
    {
      return false;
    }
    acc = sum;
  }
  det = acc;
  return true;
}

/// Exact sign of det[r0; r1; r2] for exact double entries (no under/overflow).
int ExpansionDet3(const double* r0, const double* r1, const double* r2)
{
  const double* r[3] = { r0, r1, r2 };
  double det;
  if (DoubleDet3(r, det))
  {
    return det > 0 ? 1 : (det < 0 ? -1 : 0);
  }
  double acc[64];
  int nacc = 0;
  for (int i = 0; i < 3; ++i)
  {
    const double* u = r[(i + 1) % 3];
    const double* v = r[(i + 2) % 3];
    double m[8], t[16], sum[64];
    const int nm = Minor(u[0], v[1], v[0], u[1], m); // u_x v_y - v_x u_y
    const int nt = Scale(m, nm, r[i][2], t);
    nacc = nacc == 0 ? (std::copy(t, t + nt, acc), nt) : Add(acc, nacc, t, nt, sum);
    if (i > 0)
    {
      std::copy(sum, sum + nacc, acc);
    }
  }
  const double top = acc[nacc - 1];
  return top > 0 ? 1 : (top < 0 ? -1 : 0);
}

/// Rows r = x - y computed exactly (tails zero) with entries safe from under/overflow.
bool ExactRows(const double* x[3], const double* y[3], double r[3][3])
{
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      const double v = y[i] ? x[i][j] - y[i][j] : x[i][j];
      if (y[i] && DiffTail(x[i][j], y[i][j], v) != 0)
      {
        return false;
      }
      const double m = std::fabs(v);
      if (m != 0 && !(m > 1e-75 && m < 1e75))
      {
        return false;
      }
      r[i][j] = v;
    }
  }
  return true;
}
}

int Orient2dExact(const double a[2], const double b[2], const double c[2])
{
  if (!Finite(a, 2) || !Finite(b, 2) || !Finite(c, 2))
  {
    return 0;
  }
  const Rational cx(c[0]), cy(c[1]);
  const Rational det = (Rational(a[0]) - cx) * (Rational(b[1]) - cy) -
    (Rational(a[1]) - cy) * (Rational(b[0]) - cx);
  return Sign(det);
}

int Orient2d(const double a[2], const double b[2], const double c[2])
{
  const double detLeft = (a[0] - c[0]) * (b[1] - c[1]);
  const double detRight = (a[1] - c[1]) * (b[0] - c[0]);
  const double det = detLeft - detRight;
  if (Decided(det, std::fabs(detLeft) + std::fabs(detRight), ErrBound2))
  {
    return det > 0 ? 1 : -1;
  }
  const double* x[3] = { a, b, nullptr };
  const double* y[3] = { c, c, nullptr };
  const double zero[3] = { 0, 0, 0 };
  x[2] = zero;
  double r[3][3];
  const double ac[3] = { a[0], a[1], 0 }, bc[3] = { b[0], b[1], 0 }, cc[3] = { c[0], c[1], 0 };
  x[0] = ac;
  x[1] = bc;
  y[0] = y[1] = cc;
  if (ExactRows(x, y, r))
  {
    double m[8];
    const int n = Minor(r[0][0], r[1][1], r[0][1], r[1][0], m);
    return m[n - 1] > 0 ? 1 : (m[n - 1] < 0 ? -1 : 0);
  }
  return Orient2dExact(a, b, c);
}

int Orient3dExact(const double a[3], const double b[3], const double c[3], const double d[3])
{
  if (!Finite(a, 3) || !Finite(b, 3) || !Finite(c, 3) || !Finite(d, 3))
  {
    return 0;
  }
  const double* rows[3] = { a, b, c };
  Rational m[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      m[i][j] = Rational(rows[i][j]) - Rational(d[j]);
    }
  }
  return Det3Sign(m);
}

namespace
{
/// det of rows (ad, bd, cd) in double with its permanent (Shewchuk's orient3dfast).
inline void Det3(const double ad[3], const double bd[3], const double cd[3], double& det,
  double& permanent)
{
  const double bdxcdy = bd[0] * cd[1], cdxbdy = cd[0] * bd[1];
  const double cdxady = cd[0] * ad[1], adxcdy = ad[0] * cd[1];
  const double adxbdy = ad[0] * bd[1], bdxady = bd[0] * ad[1];
  det = ad[2] * (bdxcdy - cdxbdy) + bd[2] * (cdxady - adxcdy) + cd[2] * (adxbdy - bdxady);
  permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(ad[2]) +
    (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bd[2]) +
    (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cd[2]);
}
}

bool AxisAlignedPlane(const double a[3], const double b[3], const double c[3], int& k, int& sigma)
{
  for (k = 0; k < 3; ++k)
  {
    if (a[k] == b[k] && a[k] == c[k])
    {
      for (int j = 0; j < 3; ++j)
      {
        if (!(a[j] - a[j] == 0 && b[j] - b[j] == 0 && c[j] - c[j] == 0))
        {
          return false; // not finite
        }
      }
      // det[a-d; b-d; c-d] = ((b-a)x(c-a)).(a-d) and the cross product's
      // other components vanish; its k-th is the 2D orientation in the
      // cyclically next two coordinates.
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double pa[2] = { a[i], a[j] }, pb[2] = { b[i], b[j] }, pc[2] = { c[i], c[j] };
      sigma = Orient2d(pa, pb, pc);
      return true;
    }
  }
  return false;
}

int Orient3d(const double a[3], const double b[3], const double c[3], const double d[3])
{
  const double ad[3] = { a[0] - d[0], a[1] - d[1], a[2] - d[2] };
  const double bd[3] = { b[0] - d[0], b[1] - d[1], b[2] - d[2] };
  const double cd[3] = { c[0] - d[0], c[1] - d[1], c[2] - d[2] };
  double det, permanent;
  Det3(ad, bd, cd, det, permanent);
  if (Decided(det, permanent, ErrBound3))
  {
    return det > 0 ? 1 : -1;
  }
  const double* x[3] = { a, b, c };
  const double* y[3] = { d, d, d };
  double r[3][3];
  if (ExactRows(x, y, r))
  {
    return ExpansionDet3(r[0], r[1], r[2]);
  }
  return Orient3dExact(a, b, c, d);
}

int Orient3dDirectionExact(
  const double a[3], const double b[3], const double c[3], const double w[3])
{
  if (!Finite(a, 3) || !Finite(b, 3) || !Finite(c, 3) || !Finite(w, 3))
  {
    return 0;
  }
  Rational m[3][3];
  for (int j = 0; j < 3; ++j)
  {
    m[0][j] = Rational(b[j]) - Rational(a[j]);
    m[1][j] = Rational(c[j]) - Rational(a[j]);
    m[2][j] = Rational(w[j]);
  }
  return -Det3Sign(m);
}

int Orient3dDirection(const double a[3], const double b[3], const double c[3], const double w[3])
{
  // Six rounded differences and three exact entries: the orient3d bound holds.
  const double ba[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double ca[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  double det, permanent;
  Det3(ba, ca, w, det, permanent);
  if (Decided(det, permanent, ErrBound3))
  {
    return det > 0 ? -1 : 1;
  }
  const double* x[3] = { b, c, w };
  const double* y[3] = { a, a, nullptr };
  double r[3][3];
  if (ExactRows(x, y, r))
  {
    return -ExpansionDet3(r[0], r[1], r[2]);
  }
  return Orient3dDirectionExact(a, b, c, w);
}
}
