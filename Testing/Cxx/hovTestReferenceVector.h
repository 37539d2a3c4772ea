/**
 * @file hovTestReferenceVector.h
 * @brief Long double 3-vector arithmetic of the hovTestReference*.cxx
 * sources (internal to the reference; the tests do not use it).
 */
#ifndef hovTestReferenceVector_h
#define hovTestReferenceVector_h

#include "hovTestReference.h"

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
}

#endif
