#include "hovSegmentIntegral.h"

#include "hovSpecialFunctions.h" // Erfcx, Dawson (libcerf)
#include "hovThinSeries.h"       // thin-segment series tables

#include <algorithm> // std::max, std::min
#include <array>     // coefficient tables
#include <atomic>    // the series' rounding, set once per process
#include <cmath>     // exp, expm1, sqrt, isfinite
#include <cstdint>   // exponent bits
#include <cstring>   // memcpy
#include <utility>   // integer_sequence (unrolled series)

namespace hov
{
namespace
{
using detail::MaxThinOrder;
using detail::Thin;
using detail::ThinDepth;
using detail::DepthCap;

constexpr double SqrtPi = 1.7724538509055160273;

// Wilhelms-Van Gelder only: K1 = (A - a K0)/(2b) has absolute error
// ~ eps (A + a K0) / (2|b|), relative ~ eps a^2 / |b| where K1 ~ 1/a^2. It is
// replaced by the series in b, sum_n (-b)^n/n! M_{2n+1}(a), below |b| = 1/16
// (terms <= |b|^n/n!: <= 9 terms for 2^-56) and where a^2 >= 400 |b| (terms
// ~ n! (4|b|/a^2)^n: <= 14 terms for 2^-56; the closed form's relative error
// is below 400 eps elsewhere).
constexpr double SmallSlope = 1.0 / 16.0;
constexpr double SteepDecayRatio = 400.0;
constexpr int MaxSlopeOrder = 16;

// Relative |b| below which b is treated as zero in the closed form: the
// neglected term b M_2(a) is below 1e-15 of K0, and a/(2 sqrt(b)) cannot
// overflow above it.
constexpr double ZeroSlopeRelative = 1e-15;

// Above this a, the moments M_k(a) come from the upward recurrence (stable
// when a > 2k); below it from a positive series and the downward recurrence.
constexpr double MomentUpwardFrom = 40.0;


/// sum_k coef[k] a^(n-k) d^k with precomputed powers.
inline double BernsteinSum(const double* coef, int n, const double* powA, const double* powD)
{
  double sum = 0.0;
  for (int k = 0; k <= n; ++k)
  {
    sum += coef[k] * powA[n - k] * powD[k];
  }
  return sum;
}

/// The thin series with N terms (hovThinSeries.h: ThinWilliamsMaxSeries),
/// each Horner step rounded as @p Mad; WBack = A - WFront with
/// A = sum (-1)^(n+1) D1^n/n! (WFront <= 2A/3: at most 2 bits lost). The hot
/// path of the CPU renderer.
template <int N, typename Mad>
inline void ThinWilliamsMax(double a, double d1, double& wFront, double& wBack, double& alphaOut)
{
  double w, alpha;
  detail::ThinWilliamsMaxSeries<N, Mad>(a, d1, w, alpha);
  wFront = w;
  wBack = alpha - w;
  alphaOut = alpha; // a function of D1 only: symmetric under reversal
}

#if HOV_FMA_CLONES
#define HOV_FMA_TARGET __attribute__((target("fma")))
#else
#define HOV_FMA_TARGET
#endif

/// ThinWilliamsMax() with fused steps, compiled for the CPU's FMA
/// instructions (std::fma is then one instruction); called only where
/// FusedSeries() found them.
template <int N>
HOV_FMA_TARGET void ThinWilliamsMaxFused(
  double a, double d1, double& wFront, double& wBack, double& alpha)
{
  ThinWilliamsMax<N, detail::FusedMulAdd>(a, d1, wFront, wBack, alpha);
}

/// Whether this CPU has FMA3 instructions (and the OS their registers) and
/// the kernels code for them (hovThinSeries.h: HOV_FMA_CLONES).
bool HardwareFma()
{
#if HOV_FMA_CLONES
  __builtin_cpu_init();
  return __builtin_cpu_supports("fma");
#elif defined(__aarch64__)
  return true;
#else
  return false;
#endif
}

std::atomic<bool>& FusedSeriesSetting()
{
  static std::atomic<bool> fused{ HardwareFma() };
  return fused;
}

template <int... N>
inline void ThinWilliamsMaxDispatch(int terms, double a, double d1, double& wFront, double& wBack,
  double& alpha, std::integer_sequence<int, N...>)
{
  using Fn = void (*)(double, double, double&, double&, double&);
  static constexpr Fn separate[] = { &ThinWilliamsMax<N + 1, detail::SeparateMulAdd>... };
  static constexpr Fn fused[] = { &ThinWilliamsMaxFused<N + 1>... };
  const bool useFused = FusedSeriesSetting().load(std::memory_order_relaxed);
  (useFused ? fused : separate)[terms - 1](a, d1, wFront, wBack, alpha);
}

/// Thin segment (D1 <= ThinDepth): all weights from the Taylor series in D.
SegmentWeights ThinWeights(double a, double d1, bool withEmission)
{
  const int terms = detail::ThinTerms()(d1);
  if (!(d1 > 0.0))
  {
    SegmentWeights none;
    none.Alpha = 0.0;
    none.Transmittance = 1.0;
    none.WFront = none.WBack = 0.0;
    none.VFront = none.VBack = 0.5;
    return none;
  }
  double wFront, wBack, alpha;
  ThinWilliamsMaxDispatch(
    terms, a, d1, wFront, wBack, alpha, std::make_integer_sequence<int, MaxThinOrder>());
  SegmentWeights w;
  w.WFront = std::max(0.0, wFront);
  w.WBack = std::max(0.0, wBack);
  w.Alpha = alpha; // the series of 1 - exp(-D1), to the same accuracy
  w.Transmittance = 1.0 - w.Alpha; // absolute accuracy is what compositing needs
  if (withEmission)
  {
    // VBack = K1 = sum_n (-1)^n I_{n,1}/n!, VFront = sum_n (-1)^n J_n/n!.
    double powA[MaxThinOrder + 1];
    double powD[MaxThinOrder + 1];
    powA[0] = powD[0] = 1.0;
    for (int n = 1; n <= terms; ++n)
    {
      powA[n] = powA[n - 1] * a;
      powD[n] = powD[n - 1] * d1;
    }
    double k1 = 0.0, v0 = 0.0, sign = 1.0;
    for (int n = 0; n <= terms; ++n)
    {
      k1 += sign * BernsteinSum(Thin.P1[n], n, powA, powD);
      v0 += sign * BernsteinSum(Thin.Q[n], n, powA, powD);
      sign = -sign;
    }
    w.VBack = k1;
    w.VFront = v0;
  }
  return w;
}

/**
 * Moments M_k(a) = integral_0^1 x^k exp(-a x) dx for k = 0..kMax (a > 0).
 * Large a: upward recurrence M_k = (k M_{k-1} - e^{-a}) / a from
 * M_0 = -expm1(-a)/a; each step damps errors by k/a < 1/2.
 * Otherwise: M_kMax = e^{-a} sum_j a^j / ((kMax+1)...(kMax+1+j)) (positive
 * terms) and the downward recurrence M_{k-1} = (a M_k + e^{-a}) / k, which
 * adds positive numbers only.
 */
void Moments(double a, int kMax, double* m)
{
  const double ea = std::exp(-a);
  if (a > MomentUpwardFrom)
  {
    m[0] = -std::expm1(-a) / a;
    for (int k = 1; k <= kMax; ++k)
    {
      m[k] = (k * m[k - 1] - ea) / a;
    }
    return;
  }
  double term = 1.0 / (kMax + 1);
  double sum = term;
  for (int j = 1; j < 400; ++j)
  {
    term *= a / (kMax + 1 + j);
    sum += term;
    if (term < 1e-17 * sum)
    {
      break;
    }
  }
  m[kMax] = ea * sum;
  for (int k = kMax; k > 0; --k)
  {
    m[k - 1] = (a * m[k] + ea) / k;
  }
}

/// K1 = integral_0^1 x exp(-a x - b x^2) dx as sum_n (-b)^n / n! M_{2n+1}(a),
/// for |b| < SmallSlope or a^2 >= SteepDecayRatio |b| (see the constants).
double FirstMomentSlopeSeries(double a, double b)
{
  constexpr int kMax = 2 * MaxSlopeOrder + 1;
  double m[kMax + 1];
  Moments(a, kMax, m);
  // Terms by their ratios, so that (-b)^n/n! and M_{2n+1}(a) never overflow or
  // underflow separately (a and |b| may be as large as DepthCap).
  double term = m[1];
  double sum = term;
  for (int n = 0; n < MaxSlopeOrder && m[2 * n + 1] > 0.0; ++n)
  {
    term *= (-b / (n + 1)) * (m[2 * n + 3] / m[2 * n + 1]);
    sum += term;
    if (std::abs(term) < 1e-17 * std::abs(sum))
    {
      break;
    }
  }
  return sum;
}
}

SegmentWeights ExactSegmentWeights(double depthFront, double depthBack, bool withEmissionWeights)
{
  const double a = std::min(std::max(depthFront, 0.0), DepthCap);
  const double c = std::min(std::max(depthBack, 0.0), DepthCap);
  const double d1 = 0.5 * (a + c); // total optical depth D(1)
  if (d1 <= ThinDepth)
  {
    return ThinWeights(a, d1, withEmissionWeights);
  }
  SegmentWeights w;
  w.Transmittance = std::exp(-d1);
  w.Alpha = -std::expm1(-d1);
  const double b = 0.5 * (c - a);
  double k0;
  if (std::abs(b) <= ZeroSlopeRelative * d1)
  {
    k0 = w.Alpha / d1;
  }
  else if (b > 0.0)
  {
    const double s = std::sqrt(b);
    k0 = SqrtPi / (2.0 * s) *
      (Erfcx(a / (2.0 * s)) - w.Transmittance * Erfcx(c / (2.0 * s)));
  }
  else
  {
    const double s = std::sqrt(-b);
    k0 = (Dawson(a / (2.0 * s)) - w.Transmittance * Dawson(c / (2.0 * s))) / s;
  }
  k0 = std::min(std::max(k0, w.Transmittance), 1.0); // T(1) <= K0 <= 1
  w.WFront = 1.0 - k0;
  w.WBack = k0 - w.Transmittance;
  if (withEmissionWeights)
  {
    const bool series = std::abs(b) < SmallSlope || a * a >= SteepDecayRatio * std::abs(b);
    double k1 = series ? FirstMomentSlopeSeries(a, b) : (w.Alpha - a * k0) / (2.0 * b);
    k1 = std::min(std::max(k1, 0.0), k0);
    w.VBack = k1;
    w.VFront = k0 - k1;
  }
  return w;
}

RGBA IntegrateSegment(double length, const SegmentEnd& front, const SegmentEnd& back,
  EmissionModel emission, SegmentMethod method)
{
  RGBA out;
  if (!(length > 0.0))
  {
    return out; // zero, negative or NaN length: nothing
  }
  const bool wm = emission == EmissionModel::WilliamsMax;
  const double depthFront = std::max(front.Tau, 0.0) * length;
  const double depthBack = std::max(back.Tau, 0.0) * length;
  if (!std::isfinite(depthFront) || !std::isfinite(depthBack))
  {
    // Opaque medium at (or immediately behind) the front: what is seen is the
    // front chromaticity; with emission independent of extinction an
    // infinitely dense medium shows nothing of its glow.
    out.A = 1.0;
    if (wm)
    {
      out.R = front.Color[0];
      out.G = front.Color[1];
      out.B = front.Color[2];
    }
    return out;
  }
  if (method == SegmentMethod::Approximate)
  {
    const double d1 = 0.5 * (depthFront + depthBack);
    out.A = -std::expm1(-d1);
    // Williams-Max: C = A * average chromaticity. Wilhelms-Van Gelder: the
    // average emission times integral of T for constant extinction, L A / D1.
    const double scale = wm ? 0.5 * out.A : 0.5 * length * (d1 > 0.0 ? out.A / d1 : 1.0);
    out.R = scale * (front.Color[0] + back.Color[0]);
    out.G = scale * (front.Color[1] + back.Color[1]);
    out.B = scale * (front.Color[2] + back.Color[2]);
    return out;
  }
  const SegmentWeights w = ExactSegmentWeights(depthFront, depthBack, !wm);
  out.A = w.Alpha;
  const double wf = wm ? w.WFront : length * w.VFront;
  const double wb = wm ? w.WBack : length * w.VBack;
  out.R = wf * front.Color[0] + wb * back.Color[0];
  out.G = wf * front.Color[1] + wb * back.Color[1];
  out.B = wf * front.Color[2] + wb * back.Color[2];
  return out;
}

namespace detail
{
bool FusedSeries()
{
  return FusedSeriesSetting().load(std::memory_order_relaxed);
}

bool SetFusedSeries(bool fused)
{
  FusedSeriesSetting().store(fused && HardwareFma(), std::memory_order_relaxed);
  return FusedSeries();
}
}
}
