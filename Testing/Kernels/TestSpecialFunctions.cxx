// Tests of hovSpecialFunctions: Erfcx and Dawson (libcerf wrappers) against
// 50-digit references: exp(x^2) erfc(x) in cpp_bin_float_50, and Dawson's
// integral by Gauss-Legendre quadrature of its definition; asymptotic series
// where x^2 would exceed the multiprecision exponent range.

#include "hovSpecialFunctions.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"

#include <boost/math/special_functions/erf.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using hovtest::Mp;
using hovtest::Str;
using hovtest::Tolerances;
using hovtest::Worst;

namespace
{
/// Dawson's F(x) = int_0^x exp(-(x-t)(x+t)) dt = int_0^x exp(-u (2x - u)) du
/// (u = x - t), on panels where the exponent reaches 1, 2, 4, ... 128.
Mp ReferenceDawson(double xd)
{
  if (xd < 0)
  {
    return -ReferenceDawson(-xd);
  }
  const Mp x = xd;
  if (xd > 1e4)
  {
    // F(x) = 1/(2x) sum_n (2n-1)!! / (2x^2)^n; the 5th term is < 1e-40.
    const Mp y = 1 / (2 * x * x);
    return (1 + y + 3 * y * y + 15 * y * y * y + 105 * y * y * y * y) / (2 * x);
  }
  const Mp top = x * x;
  std::vector<Mp> us{ Mp(0) };
  for (Mp d = 1; d < top && d < 128; d *= 2)
  {
    us.push_back(d / (x + sqrt(x * x - d)));
  }
  us.push_back(top > 128 ? Mp(128 / (x + sqrt(x * x - 128))) : x);
  using G = boost::math::quadrature::gauss<Mp, 30>;
  Mp sum = 0;
  for (size_t p = 0; p + 1 < us.size(); ++p)
  {
    const Mp half = (us[p + 1] - us[p]) / 2, mid = (us[p + 1] + us[p]) / 2;
    for (size_t i = 0; i < G::abscissa().size(); ++i)
    {
      for (int sgn : { 1, -1 })
      {
        const Mp u = mid + sgn * half * G::abscissa()[i];
        sum += half * G::weights()[i] * exp(-u * (2 * x - u));
      }
    }
  }
  return sum;
}

Mp ReferenceErfcx(double xd)
{
  const Mp x = xd;
  if (xd > 1e4)
  {
    // erfcx(x) = 1/(x sqrt(pi)) sum_n (-1)^n (2n-1)!! / (2x^2)^n.
    const Mp y = 1 / (2 * x * x);
    return (1 - y + 3 * y * y - 15 * y * y * y + 105 * y * y * y * y) /
      (x * boost::math::constants::root_pi<Mp>());
  }
  return exp(x * x) * boost::math::erfc(x);
}

const std::vector<double>& Arguments()
{
  static const std::vector<double> v = { 0.0, 1e-300, 1e-100, 1e-10, 1e-3, 0.1, 0.5, 0.9241388730,
    1.0, 1.5, 2.0, 3.0, 5.0, 7.5, 10.0, 26.0, 50.0, 100.0, 1e3, 9999.0, 1e5, 1e8, 1e150, 1e300 };
  return v;
}

/// @p f (called @p name) against its reference @p ref at x: the relative error
/// is recorded in @p worst and must be within SpecialFunctionRel.
void ExpectMatchesReference(
  const char* name, double (*f)(double), Mp (*ref)(double), double x, Worst& worst)
{
  SCOPED_TRACE("x=" + Str(x));
  const double got = f(x);
  const double e = hovtest::RelErr(got, ref(x));
  worst.Add(e, "x=" + Str(x));
  EXPECT_LE(e, Tolerances.SpecialFunctionRel) << name << "(" << Str(x) << ") = " << Str(got);
}
}

TEST(SpecialFunctions, ErfcxMatchesReference)
{
  Worst worst;
  for (double x0 : Arguments())
  {
    for (double x : { x0, -x0 })
    {
      if (x < -26.0)
      {
        continue; // erfcx(x) ~ 2 exp(x^2) overflows: not used by the kernels
      }
      ExpectMatchesReference("Erfcx", hov::Erfcx, ReferenceErfcx, x, worst);
    }
  }
  hovtest::ReportMeasured("Erfcx relative error", worst);
}

TEST(SpecialFunctions, DawsonMatchesReference)
{
  Worst worst;
  for (double x0 : Arguments())
  {
    for (double x : { x0, -x0 })
    {
      ExpectMatchesReference("Dawson", hov::Dawson, ReferenceDawson, x, worst);
    }
  }
  hovtest::ReportMeasured("Dawson relative error", worst);
  // The reference itself: F'(x) = 1 - 2 x F(x) at x = 2 by a central difference.
  const Mp d = (ReferenceDawson(2.0 + 1e-6) - ReferenceDawson(2.0 - 1e-6)) / Mp(2e-6);
  EXPECT_NEAR(static_cast<double>(d), static_cast<double>(1 - 4 * ReferenceDawson(2.0)), Tolerances.FiniteDifferenceAbs);
}
