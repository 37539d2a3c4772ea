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
  return Orient3dDirectionExact(a, b, c, w);
}
}
