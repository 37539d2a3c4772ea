// The Chebyshev steps shared by the cell restrictions (hovChebyshevFit.h):
// ChebyshevCoefficients must be, bit for bit, the DCT-I written one
// coefficient after the other (each a sum in the documented order; the kernel
// runs all coefficients at once), and the coefficients must interpolate: the
// series at the sample points gives the samples back to rounding. The cosine
// table must be cos(pi m / N) correctly rounded (against long double), exactly
// antisymmetric and exactly 0 at pi / 2.
#include "hovChebyshevFit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

namespace
{
using hov::detail::ChebN;
constexpr double Pi = 3.141592653589793238462643383279502884;

/// The reference: one coefficient after the other, with the kernel's cosines.
void OneByOne(const double f[ChebN + 1], double c[ChebN + 1])
{
  for (int k = 0; k <= ChebN; ++k)
  {
    double sum = 0.5 * (f[0] + ((k % 2) ? -f[ChebN] : f[ChebN]));
    for (int j = 1; j < ChebN; ++j)
    {
      sum += f[j] * hov::detail::ChebyshevCosine(j * k);
    }
    c[k] = sum * (2.0 / ChebN);
  }
  c[0] *= 0.5;
  c[ChebN] *= 0.5;
}

/// |v - x| within half an ulp of v (correct rounding of the long double x;
/// long double pi leaves ~1e-19 where the cosine is 0).
bool CorrectlyRounded(double v, long double x)
{
  const long double halfUlp =
    0.5L * (std::nextafter(std::fabs(v), 2.0) - std::fabs(v)) + 1e-18L;
  return std::fabs(static_cast<long double>(v) - x) <= halfUlp;
}

TEST(ChebyshevFit, CosinesAreCorrectlyRounded)
{
  if (sizeof(long double) <= sizeof(double))
  {
    GTEST_SKIP() << "long double is no wider than double here: no reference";
  }
  const long double pi = 3.141592653589793238462643383279502884L;
  for (int m = 0; m <= ChebN; ++m)
  {
    EXPECT_TRUE(CorrectlyRounded(hov::detail::ChebyshevCosines[m], std::cos(pi * m / ChebN)))
      << m;
    EXPECT_EQ(hov::detail::ChebyshevCosines[ChebN - m], -hov::detail::ChebyshevCosines[m]) << m;
  }
  EXPECT_EQ(hov::detail::ChebyshevCosines[ChebN / 2], 0.0);
  for (int m = -4 * ChebN; m < 4 * ChebN; ++m)
  {
    EXPECT_TRUE(CorrectlyRounded(hov::detail::ChebyshevCosine(m), std::cos(pi * m / ChebN)))
      << m;
  }
  // What std::cos(Pi m / N) in double gives instead (the table before): not 0 at pi / 2.
  EXPECT_FALSE(CorrectlyRounded(std::cos(Pi * 8 / ChebN), 0.0L));
}

TEST(ChebyshevFit, CoefficientsAreTheDctBitForBit)
{
  std::mt19937_64 rng(77);
  std::normal_distribution<double> nd;
  double worst = 0.0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    double f[ChebN + 1], c[ChebN + 1], ref[ChebN + 1];
    const double scale = std::pow(10.0, (trial % 41) - 20);
    for (double& v : f)
    {
      v = scale * nd(rng);
    }
    if (trial % 10 == 0)
    {
      f[trial % (ChebN + 1)] = 0.0;
    }
    hov::detail::ChebyshevCoefficients(f, c);
    OneByOne(f, ref);
    ASSERT_EQ(std::memcmp(c, ref, sizeof(c)), 0) << "trial " << trial;
    // Interpolation: sum_k c_k T_k(x_j) = f_j at x_j = cos(pi j / N).
    double size = 0.0;
    for (double v : f)
    {
      size += std::fabs(v);
    }
    for (int j = 0; j <= ChebN; ++j)
    {
      double value = 0.0;
      for (int k = 0; k <= ChebN; ++k)
      {
        value += c[k] * std::cos(Pi * j * k / ChebN);
      }
      const double e = std::fabs(value - f[j]) / size;
      worst = std::max(worst, e);
      EXPECT_LE(e, 1e-14) << "trial " << trial << " point " << j;
    }
  }
  std::cout << "[measured] ChebyshevFit: interpolation error " << worst << " of sum |f|"
            << std::endl;
}
}
