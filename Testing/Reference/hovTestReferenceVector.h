/**
 * @file hovTestReferenceVector.h
 * @brief Long double 3-vector arithmetic of the hovTestReference*.cxx
 * sources and the colour accumulator the Boost quadratures integrate
 * (internal to the reference; the tests do not use it).
 */
#ifndef hovTestReferenceVector_h
#define hovTestReferenceVector_h

#include "hovTestReference.h"

#include <algorithm>
#include <cmath>

namespace hovTestRef
{
inline Vec3 Sub(const Vec3& a, const Vec3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
inline Vec3 Add(const Vec3& a, const Vec3& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
inline Vec3 Scale(const Vec3& a, Real s)
{
  return { a[0] * s, a[1] * s, a[2] * s };
}
inline Real Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline Real Norm(const Vec3& a)
{
  return std::sqrt(Dot(a, a));
}
inline Vec3 Unit(const Vec3& a)
{
  return Scale(a, 1 / Norm(a));
}
inline Vec3 FromDouble(const double* p)
{
  return { p[0], p[1], p[2] };
}

/// Distance between the segments [p1, q1] and [p2, q2] (hovTestReferenceGeometry.cxx).
Real SegmentDistance(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2);

/// A 3-vector the Boost quadrature can integrate (abs = max norm).
struct QVec
{
  Real V[3];
  QVec(Real x = 0)
    : V{ x, x, x }
  {
  }
  QVec(Real a, Real b, Real c)
    : V{ a, b, c }
  {
  }
  QVec& operator+=(const QVec& o)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->V[c] += o.V[c];
    }
    return *this;
  }
  QVec operator-() const { return QVec(-V[0], -V[1], -V[2]); }
};
inline QVec operator+(QVec a, const QVec& b)
{
  return a += b;
}
inline QVec operator-(const QVec& a, const QVec& b)
{
  return QVec(a.V[0] - b.V[0], a.V[1] - b.V[1], a.V[2] - b.V[2]);
}
inline QVec operator*(const QVec& a, Real s)
{
  return QVec(a.V[0] * s, a.V[1] * s, a.V[2] * s);
}
inline QVec operator*(Real s, const QVec& a)
{
  return a * s;
}
inline Real abs(const QVec& a)
{
  return std::max({ std::fabs(a.V[0]), std::fabs(a.V[1]), std::fabs(a.V[2]) });
}
}

#endif
