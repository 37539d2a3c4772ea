/**
 * @file hovThinSeries.h
 * @brief Internal to the segment kernels: the thin-segment Taylor series of
 * hovSegmentIntegral (coefficient tables, branch threshold, number of terms
 * per binary exponent of the depth) and the series itself, written once over
 * the value type (ThinWilliamsMaxSeries), shared by the scalar kernel
 * (hovSegmentIntegral.cxx) and the batched one (hovSegmentBatchLanes.cxx) so
 * that both evaluate exactly the same series with the same number of terms.
 *
 * Not part of the public API (namespace hov::detail).
 */
#ifndef hovThinSeries_h
#define hovThinSeries_h

#include "hovConfig.h" // HOV_EXPORT

#include <algorithm> // std::min
#include <cmath>     // std::fma, std::ldexp, std::pow
#include <cstdint>   // exponent bits
#include <cstring>   // memcpy
#include <limits>    // infinity

#if defined(__GNUC__)
#define HOV_THIN_INLINE inline __attribute__((always_inline))
#else
#define HOV_THIN_INLINE inline
#endif

namespace hov
{
namespace detail
{
// Below this total depth D(1) the closed form K0 = sqrt(pi)/(2s)(...) loses
// digits in 1 - K0 (absolute error ~ eps / D(1), measured 3e-14 relative just
// above 1/8); the Taylor series in D converges like D^n/n! and needs at most
// 14 terms for 2^-56 relative at 1/4, which by Horner's rule costs less than
// the two erfcx calls of the closed form.
constexpr double ThinDepth = 0.25;
constexpr int MaxThinOrder = 16;

// Depth rates are capped here: a+b stays finite, T(1) underflows to 0, and
// every weight is already exact in double precision.
constexpr double DepthCap = 1e300;

/**
 * Coefficients of the thin-segment series. With D(x) = x (a (1-x) + D1 x),
 *   integral_0^1 x^m D^n dx / n! = sum_k P[m][n][k] a^(n-k) D1^k,
 *     P[m][n][k] = (n+k+m)! / (k! (2n+m+1)!),            m = 0, 1
 *   integral_0^1 (1-x) D^n dx / n! = sum_k Q[n][k] a^(n-k) D1^k,
 *     Q[n][k] = (n+k)! (n-k+1) / (k! (2n+2)!).
 * All terms are positive for a >= 0, D1 >= 0.
 */
struct ThinTables
{
  double P0[MaxThinOrder + 1][MaxThinOrder + 1] = {};
  double P1[MaxThinOrder + 1][MaxThinOrder + 1] = {};
  double Q[MaxThinOrder + 1][MaxThinOrder + 1] = {};
  double InvFactorial[MaxThinOrder + 1] = {};
};

constexpr ThinTables MakeThinTables()
{
  ThinTables t{};
  double fact[2 * MaxThinOrder + 4] = {};
  fact[0] = 1.0;
  for (int i = 1; i < 2 * MaxThinOrder + 4; ++i)
  {
    fact[i] = fact[i - 1] * i;
  }
  for (int n = 0; n <= MaxThinOrder; ++n)
  {
    t.InvFactorial[n] = 1.0 / fact[n];
    for (int k = 0; k <= n; ++k)
    {
      t.P0[n][k] = fact[n + k] / (fact[k] * fact[2 * n + 1]);
      t.P1[n][k] = fact[n + k + 1] / (fact[k] * fact[2 * n + 2]);
      t.Q[n][k] = fact[n + k] * (n - k + 1) / (fact[k] * fact[2 * n + 2]);
    }
  }
  return t;
}

inline constexpr ThinTables Thin = MakeThinTables();

/**
 * The thin Williams-Max series with @p N terms, written once over the value
 * type T: one segment (double, hovSegmentIntegral.cxx) or Lanes segments side
 * by side (a GCC/Clang vector of doubles, hovSegmentBatchLanes.cxx), with the
 * same IEEE operations in the same order per value, so every lane equals the
 * scalar kernel bit for bit. For depth rate @p a and total depth @p d1
 * (r = a/d1 in [0, 2]):
 *   WFront = sum_{n=1}^{N} (-1)^(n+1) D1^n Q_n(r),  Q_n(r) = sum_j P0[n][n-j] r^j,
 *   alpha  = sum_{n=1}^{N} (-1)^(n+1) D1^n / n!,
 * Q_n by Horner's rule (positive coefficients: no cancellation), the outer
 * sums by Horner's rule in d1^2 on odd and even terms separately (two
 * independent chains of half the length: the chain latency dominates).
 * Outputs @p w = WFront before clamping and @p alpha (WBack = alpha - w).
 * N is a compile-time constant so that both loops unroll completely.
 *
 * @p Mad is how each Horner step x * y + z is rounded: FusedMulAdd (once,
 * std::fma: the CPU's fused multiply-add where it has one) or
 * SeparateMulAdd (twice). The kernels pick one per process (FusedSeries()),
 * so the scalar and batched kernels round alike on any one machine.
 *
 * @p keep(n, c) sets term n's coefficient c as it enters the outer sums:
 * c as it is (AllTerms, the default), or an exact zero for lanes that need
 * fewer than n terms (the lane kernels' blocks of mixed term counts: a lane's
 * chains then stay +0 until its own first term, where they become exactly
 * what N = its own count starts with, 0 * d2 + c).
 */
struct AllTerms
{
  template <typename T>
  void operator()(int, T&) const
  {
  }
};

/// x = x * y + z, rounded twice (after the product and after the sum): only
/// where the including file is compiled without contraction
/// (-ffp-contract=off, as the kernels are: Kernels/CMakeLists.txt).
struct SeparateMulAdd
{
  template <typename T>
  HOV_THIN_INLINE void operator()(T& x, const T& y, const T& z) const
  {
    x = x * y + z;
  }
};

/// x = x * y + z, rounded once (std::fma per value). In the kernels' FMA
/// code (the scalar kernel's target("fma") copies, the lane kernels' "fma"
/// clones, AArch64) that is one instruction, for four lanes in the lane
/// kernels; compiled without FMA it is a call to the C library's fma, which
/// the kernels never make in practice (FusedSeries() is true only where the
/// FMA code runs).
struct FusedMulAdd
{
  HOV_THIN_INLINE void operator()(double& x, double y, double z) const { x = std::fma(x, y, z); }
  template <typename V>
  HOV_THIN_INLINE void operator()(V& x, const V& y, const V& z) const
  {
    for (int l = 0; l < static_cast<int>(sizeof(V) / sizeof(double)); ++l)
    {
      x[l] = std::fma(x[l], y[l], z[l]);
    }
  }
};

template <int N, typename Mad, typename T, typename Keep = AllTerms>
HOV_THIN_INLINE void ThinWilliamsMaxSeries(
  const T& a, const T& d1, T& w, T& alpha, const Keep& keep = Keep())
{
  const Mad mad;
  const T r = a / d1;
  const T d2 = d1 * d1;
  T wOdd = T{}, wEven = T{}, aOdd = T{}, aEven = T{};
#pragma GCC unroll 16
  for (int n = N; n >= 1; --n)
  {
    const double* p = Thin.P0[n];
    T h = T{} + p[0];
#pragma GCC unroll 16
    for (int j = 1; j <= n; ++j)
    {
      mad(h, r, T{} + p[j]);
    }
    T f = T{} + Thin.InvFactorial[n]; // 0 + f is f
    keep(n, h);
    keep(n, f);
    if (n % 2)
    {
      mad(wOdd, d2, h);
      mad(aOdd, d2, f);
    }
    else
    {
      mad(wEven, d2, h);
      mad(aEven, d2, f);
    }
  }
  // sum_n (-1)^(n+1) c_n d^n = d (odd part in d^2) - d^2 (even part in d^2).
  w = d1 * wOdd - d2 * wEven;
  alpha = d1 * aOdd - d2 * aEven;
}

/// Whether the kernels have FMA code for this platform: x86-64 with GCC or
/// Clang (target attributes and target_clones, not on Apple) or AArch64.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(__APPLE__)
#define HOV_FMA_CLONES 1
#else
#define HOV_FMA_CLONES 0
#endif

/**
 * Whether the thin series rounds each Horner step once (FusedMulAdd) or twice
 * (SeparateMulAdd), for the whole process: once where the CPU has FMA3
 * instructions (x86-64 CPUs since 2012-2013, AMD Piledriver and Intel Haswell
 * on, checked with __builtin_cpu_supports("fma"), the same test that picks the
 * lane kernels' "fma" clone) and on AArch64; twice elsewhere, so no machine
 * runs a software fma. Both are within the series' 2^-56 bound; the scalar
 * kernel (hovSegmentIntegral.cxx) and the batched one
 * (hovSegmentBatchLanes.cxx) read this same setting, so they agree bit for bit
 * on any one machine, and every machine with FMA gives the same bits.
 */
HOV_EXPORT bool FusedSeries();

/**
 * For tests and comparisons across machines: round the series as @p fused
 * asks where that is available (fused needs the CPU's FMA) and return the
 * setting now in force. Not to be called while segments are being integrated.
 */
HOV_EXPORT bool SetFusedSeries(bool fused);

/// Number of series terms that reach 2^-56 relative accuracy for total depth
/// d1: the first terms of WFront and WBack are both >= d1/3 and term n is
/// bounded by d1^n/n!, so n terms suffice once d1^n/(n+1)! < 2^-56/3. The
/// emission weights (first terms 1/2) need d1^(n+1)/(n+1)! < 2^-56 as well.
struct ThinTermTable
{
  double MaxDepth[MaxThinOrder + 1] = {};
  ThinTermTable()
  {
    const double stop = std::ldexp(1.0, -56) / 3.0;
    double fact = 1.0;
    for (int n = 1; n <= MaxThinOrder; ++n)
    {
      fact *= n + 1; // (n+1)!
      const double wm = std::pow(stop * fact, 1.0 / n);
      const double wvg = std::pow(3.0 * stop * fact, 1.0 / (n + 1));
      this->MaxDepth[n] = std::min(wm, wvg);
    }
  }
  int Terms(double d1) const
  {
    int n = 1;
    while (n < MaxThinOrder && d1 > this->MaxDepth[n])
    {
      ++n;
    }
    return n;
  }
};

/// Terms for every binary exponent of d1 <= ThinDepth: d1 < 2^(e+1) for
/// biased exponent e, so Terms(2^(e+1)) is enough (at most one extra term).
struct ThinTermByExponent
{
  static constexpr int Lowest = 1023 - 80; // below 2^-80 one term is exact
  int Terms[1023 - Lowest] = {};
  /// AtLeast[n]: the smallest d1 with at least n terms (a power of two, the
  /// first with its exponent), so n <= operator()(d1) iff AtLeast[n] <= d1 for
  /// 2 <= n <= MaxThinOrder and 0 < d1 <= ThinDepth (+inf if no such d1).
  double AtLeast[MaxThinOrder + 1] = {};
  ThinTermByExponent()
  {
    const ThinTermTable table;
    for (int e = Lowest; e < 1023; ++e)
    {
      this->Terms[e - Lowest] = table.Terms(std::ldexp(1.0, e - 1023 + 1));
    }
    for (int n = 0; n <= MaxThinOrder; ++n)
    {
      this->AtLeast[n] = n <= 1 ? 0.0 : std::numeric_limits<double>::infinity();
      for (int e = 1022; e >= Lowest && n > 1; --e)
      {
        if (this->Terms[e - Lowest] >= n)
        {
          this->AtLeast[n] = std::ldexp(1.0, e - 1023); // the binade's first value
        }
      }
    }
  }
  int operator()(double d1) const
  {
    std::uint64_t bits;
    std::memcpy(&bits, &d1, sizeof(bits));
    const int e = static_cast<int>((bits >> 52) & 0x7ff);
    return e < Lowest ? 1 : this->Terms[std::min(e, 1022) - Lowest];
  }
};

/// The table of terms per exponent (built once, thread-safe static initialisation).
inline const ThinTermByExponent& ThinTerms()
{
  static const ThinTermByExponent table;
  return table;
}
}
}

#endif
