/**
 * @file hovShapeArithmetic.h
 * @brief The number types the shape functions of hovCellShapes.cxx are
 * evaluated in besides double (one template for all): forward-mode dual
 * numbers (value and gradient in r, s, t: CellShapeDerivatives of the
 * quadratic cells) and polynomials in one variable (the expansion along a
 * parametric line: CellShapeFunctionsAlongLine). Private to the kernels.
 */
#ifndef hovShapeArithmetic_h
#define hovShapeArithmetic_h

#include "hovPolynomial.h" // Polynomial::MaxDegree

namespace hov
{
namespace detail
{
/// Forward-mode dual number: value and gradient with respect to (r, s, t).
struct Dual
{
  double V = 0.0;
  double G[3] = { 0.0, 0.0, 0.0 };
  Dual() = default;
  Dual(double v) // NOLINT: implicit from constants, like a scalar
    : V(v)
  {
  }
};
inline Dual operator+(const Dual& a, const Dual& b)
{
  Dual r(a.V + b.V);
  for (int k = 0; k < 3; ++k)
  {
    r.G[k] = a.G[k] + b.G[k];
  }
  return r;
}
inline Dual operator-(const Dual& a, const Dual& b)
{
  Dual r(a.V - b.V);
  for (int k = 0; k < 3; ++k)
  {
    r.G[k] = a.G[k] - b.G[k];
  }
  return r;
}
inline Dual operator-(const Dual& a)
{
  return Dual(0.0) - a;
}
inline Dual operator*(const Dual& a, const Dual& b)
{
  Dual r(a.V * b.V);
  for (int k = 0; k < 3; ++k)
  {
    r.G[k] = a.G[k] * b.V + a.V * b.G[k];
  }
  return r;
}
inline Dual operator/(const Dual& a, double b)
{
  return a * Dual(1.0 / b);
}

/// Polynomial in one variable y, truncated to Polynomial::MaxDegree (the
/// shape functions of the supported cells never exceed degree 6 along a line).
struct LinePoly
{
  static constexpr int N = Polynomial::MaxDegree + 1;
  double C[N] = {};
  LinePoly() = default;
  LinePoly(double v) // NOLINT: implicit from constants
  {
    this->C[0] = v;
  }
};
inline LinePoly operator+(const LinePoly& a, const LinePoly& b)
{
  LinePoly r;
  for (int k = 0; k < LinePoly::N; ++k)
  {
    r.C[k] = a.C[k] + b.C[k];
  }
  return r;
}
inline LinePoly operator-(const LinePoly& a, const LinePoly& b)
{
  LinePoly r;
  for (int k = 0; k < LinePoly::N; ++k)
  {
    r.C[k] = a.C[k] - b.C[k];
  }
  return r;
}
inline LinePoly operator-(const LinePoly& a)
{
  return LinePoly(0.0) - a;
}
inline LinePoly operator*(const LinePoly& a, const LinePoly& b)
{
  LinePoly r;
  for (int i = 0; i < LinePoly::N; ++i)
  {
    if (a.C[i] == 0.0)
    {
      continue;
    }
    for (int j = 0; i + j < LinePoly::N; ++j)
    {
      r.C[i + j] += a.C[i] * b.C[j];
    }
  }
  return r;
}
inline LinePoly operator/(const LinePoly& a, double b)
{
  return a * LinePoly(1.0 / b);
}
}
}

#endif
