/**
 * @file hovKernelTestReference.h
 * @brief Independent high-precision references for the kernel tests.
 *
 * Nothing here calls the kernels or reuses their formulas (no erfcx, no
 * Dawson, no series, no integration by parts): every reference is a direct
 * quadrature of the defining integral.
 *
 *  - ReferenceSegmentWeights(): the weights of hovSegmentIntegral.h by
 *    Gauss-Legendre quadrature (Boost.Math nodes) in cpp_bin_float_50, on
 *    panels whose ends are where the optical depth D(x) reaches 1, 2, 4, ...,
 *    128 (so the integrand varies by a bounded factor per panel whatever the
 *    depth, 1e-300 or 1e300), and the negligible tail beyond D = 128
 *    (e^-128 ~ 2.6e-56 relative) dropped.
 *  - ReferenceRay(): a ray through a piecewise-linear transfer function given
 *    by its raw nodes (not hov::TransferFunction), integrated in long double
 *    with Boost tanh-sinh over every interval between breakpoints. The optical
 *    depth is integrated analytically per interval (linear or -ln(1-a)
 *    extinction), the emission integral numerically.
 */
#ifndef hovKernelTestReference_h
#define hovKernelTestReference_h

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/expm1.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace hovtest
{
using Mp = boost::multiprecision::cpp_bin_float_50;

// ---------------------------------------------------------------------------
// Segment weights
// ---------------------------------------------------------------------------

struct ReferenceWeights
{
  Mp Alpha, Transmittance, K0, WFront, WBack, VFront, VBack;
};

/**
 * Weights of a segment with depth rates a = tauFront L, c = tauBack L:
 * with D(x) = a x + b x^2, b = (c - a)/2, T = exp(-D),
 *   WFront = int_0^1 (1 - T), WBack = int_0^1 (T - T(1)),
 *   VBack = int_0^1 x T, VFront = int_0^1 (1 - x) T, K0 = int_0^1 T.
 * @p fine selects panels every 0.5 of optical depth and a 20-point rule (used
 * to check the default panels/rule against each other).
 */
inline ReferenceWeights ReferenceSegmentWeights(double depthFront, double depthBack, bool fine = false)
{
  using boost::math::expm1;
  const Mp a = depthFront;
  const Mp c = depthBack;
  const Mp b = (c - a) / 2;
  const Mp d1 = (a + c) / 2;
  ReferenceWeights r;
  r.Transmittance = d1 > 1e7 ? Mp(0) : Mp(exp(-d1));
  r.Alpha = d1 > 1e7 ? Mp(1) : Mp(-expm1(-d1));

  // Panel ends: x where D(x) = level (D is increasing since tau >= 0). The
  // stable root 2d / (a + sqrt(a^2 + 4 b d)) also covers a = 0 and b < 0.
  const Mp cut = 128;
  auto xOfDepth = [&](const Mp& d) {
    Mp disc = a * a + 4 * b * d;
    if (disc < 0)
    {
      disc = 0;
    }
    return Mp(2 * d / (a + sqrt(disc)));
  };
  std::vector<Mp> xs{ Mp(0) };
  const Mp top = d1 < cut ? d1 : cut;
  if (fine)
  {
    for (Mp d = 0.5; d < top; d += 0.5)
    {
      xs.push_back(xOfDepth(d));
    }
  }
  else
  {
    for (Mp d = 1; d < top; d *= 2)
    {
      xs.push_back(xOfDepth(d));
    }
  }
  const Mp xEnd = d1 > cut ? xOfDepth(cut) : Mp(1);
  xs.push_back(xEnd);

  // D(x) and D(1) - D(x) as sums of non-negative terms (no cancellation).
  auto depth = [&](const Mp& x) { return Mp(x * (a * (2 - x) + c * x) / 2); };
  auto rest = [&](const Mp& x) { return Mp((1 - x) * (a * (1 - x) + c * (1 + x)) / 2); };

  Mp wFront = 0, wBack = 0, k0 = 0, v0 = 0, v1 = 0;
  auto accumulate = [&](const Mp& x, const Mp& weight) {
    const Mp d = depth(x);
    const Mp e = exp(-d);
    const Mp oneMinusT = d < 0.5 ? Mp(-expm1(-d)) : Mp(1 - e);
    const Mp rd = rest(x);
    const Mp backFactor = rd < 0.5 ? Mp(-expm1(-rd)) : Mp(1 - r.Transmittance / e);
    wFront += weight * oneMinusT;
    wBack += weight * e * backFactor;
    k0 += weight * e;
    v1 += weight * x * e;
    v0 += weight * (1 - x) * e;
  };
  auto panel = [&](const Mp& x0, const Mp& x1, const auto& nodes, const auto& weights) {
    const Mp half = (x1 - x0) / 2;
    const Mp mid = (x1 + x0) / 2;
    for (size_t i = 0; i < nodes.size(); ++i)
    {
      const Mp w = half * weights[i];
      if (nodes[i] == 0)
      {
        accumulate(mid, w);
      }
      else
      {
        accumulate(mid + half * nodes[i], w);
        accumulate(mid - half * nodes[i], w);
      }
    }
  };
  for (size_t p = 0; p + 1 < xs.size(); ++p)
  {
    if (fine)
    {
      using G = boost::math::quadrature::gauss<Mp, 20>;
      panel(xs[p], xs[p + 1], G::abscissa(), G::weights());
    }
    else
    {
      using G = boost::math::quadrature::gauss<Mp, 30>;
      panel(xs[p], xs[p + 1], G::abscissa(), G::weights());
    }
  }
  // Beyond xEnd, T < e^-128: 1 - T = 1 to 55 digits and T is negligible.
  r.WFront = wFront + (1 - xEnd);
  r.WBack = wBack;
  r.K0 = k0;
  r.VFront = v0;
  r.VBack = v1;
  return r;
}

/// |got - ref| / |ref| (0 if both are 0, +inf if only ref is 0).
inline double RelErr(double got, const Mp& ref)
{
  if (ref == 0)
  {
    return got == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  }
  return static_cast<double>(abs(Mp(got) - ref) / abs(ref));
}

inline double AbsErr(double got, const Mp& ref)
{
  return static_cast<double>(abs(Mp(got) - ref));
}

// ---------------------------------------------------------------------------
// Ray through a piecewise-linear transfer function
// ---------------------------------------------------------------------------

enum class RefSemantics
{
  GPU,          ///< tau = -ln(1 - a)/u (true, not linearised, no clamp)
  Unstructured, ///< tau = a/u
  Raw           ///< tau = a
};

/// A transfer function given by its raw nodes (sorted by X; a jump is two
/// nodes at one X, left value first).
struct RefTransferFunction
{
  std::vector<double> ColorX;
  std::vector<std::array<double, 3>> Color;
  std::vector<double> OpacityX;
  std::vector<double> Opacity;
  RefSemantics Semantics = RefSemantics::Raw;
  double Unit = 1.0;
  double EmissionScale = 1.0;
};

/// Value of a piecewise-linear function at @p s using the linear piece that
/// contains @p hint (strictly inside it, or in a clamped outer region).
inline long double PwlAt(const std::vector<double>& xs, const std::vector<long double>& vs,
  long double s, long double hint)
{
  const auto it = std::upper_bound(xs.begin(), xs.end(), static_cast<double>(hint));
  const long i = static_cast<long>(it - xs.begin()) - 1;
  if (i < 0)
  {
    return vs.front();
  }
  if (i + 1 >= static_cast<long>(xs.size()))
  {
    return vs.back();
  }
  const long double w = (s - xs[i]) / (static_cast<long double>(xs[i + 1]) - xs[i]);
  return vs[i] + (vs[i + 1] - vs[i]) * w;
}

/// integral_{x0}^{x1} -ln(p(x)) dx for p linear from p0 to p1 (>= 0) over
/// [x0, x1]: (x1 - x0)(1 - ln q - (1 + r) log1p(r) / r), q = max(p0, p1),
/// r = (min - q)/q in [-1, 0]; +inf if p0 = p1 = 0.
inline long double MinusLogIntegral(long double p0, long double p1, long double width)
{
  const long double q = std::max(p0, p1);
  if (q <= 0.0L)
  {
    return std::numeric_limits<long double>::infinity();
  }
  const long double r = (std::min(p0, p1) - q) / q;
  long double g; // (1 + r) log1p(r) / r, -> 1 as r -> 0, 0 at r = -1
  if (r == -1.0L)
  {
    g = 0.0L;
  }
  else if (std::fabs(r) < 1e-5L)
  {
    g = (1.0L + r) * (1.0L - r / 2.0L + r * r / 3.0L - r * r * r / 4.0L);
  }
  else
  {
    g = (1.0L + r) * std::log1p(r) / r;
  }
  return width * (1.0L - std::log(q) - g);
}

struct RefRGBA
{
  long double R = 0, G = 0, B = 0, A = 0;
};

enum class RefEmission
{
  WilliamsMax,
  WilhelmsVanGelder
};

/**
 * Premultiplied RGBA of a ray of length @p length along which s goes linearly
 * from @p sFront (eye side) to @p sBack, by direct integration of
 *   C = int_0^L g(t) exp(-int_0^t tau) dt,  A = 1 - exp(-int_0^L tau),
 * with g = c tau (Williams-Max) or g = EmissionScale c / u (Wilhelms-Van Gelder).
 */
inline RefRGBA ReferenceRay(const RefTransferFunction& tf, double sFront, double sBack,
  double length, RefEmission emission, long double quadTol = 1e-16L)
{
  // Non-const: in Boost 1.74 the definition of integrate() lacks the const of its declaration.
  static boost::math::quadrature::tanh_sinh<long double> integrator;
  RefRGBA out;
  const long double sF = sFront, sB = sBack, L = length;
  const long double ds = sB - sF;
  std::vector<long double> r(tf.Color.size()), g(tf.Color.size()), bl(tf.Color.size());
  for (size_t i = 0; i < tf.Color.size(); ++i)
  {
    r[i] = tf.Color[i][0];
    g[i] = tf.Color[i][1];
    bl[i] = tf.Color[i][2];
  }
  std::vector<long double> op(tf.Opacity.begin(), tf.Opacity.end());

  // Breakpoints as fractions of the ray.
  std::vector<long double> xs{ 0.0L, 1.0L };
  if (ds != 0.0L)
  {
    const long double lo = std::min(sF, sB), hi = std::max(sF, sB);
    for (const auto* nodes : { &tf.ColorX, &tf.OpacityX })
    {
      for (double x : *nodes)
      {
        if (x > lo && x < hi)
        {
          xs.push_back((x - sF) / ds);
        }
      }
    }
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());

  const bool wm = emission == RefEmission::WilliamsMax;
  const long double invU = 1.0L / tf.Unit;
  long double depth = 0.0L; // optical depth at the current piece's front
  for (size_t p = 0; p + 1 < xs.size(); ++p)
  {
    const long double x0 = xs[p], x1 = xs[p + 1];
    const long double hint = sF + ds * 0.5L * (x0 + x1);
    auto sOf = [&](long double x) { return sF + ds * x; };
    auto opacity = [&](long double x) { return PwlAt(tf.OpacityX, op, sOf(x), hint); };
    const long double a0 = opacity(x0), a1 = opacity(x1);
    // Extinction per unit length and the optical depth from x0 to x.
    auto tau = [&](long double x) -> long double {
      const long double a = opacity(x);
      switch (tf.Semantics)
      {
        case RefSemantics::GPU:
          return a >= 1.0L ? std::numeric_limits<long double>::infinity() : -std::log1p(-a) * invU;
        case RefSemantics::Unstructured:
          return a * invU;
        default:
          return a;
      }
    };
    auto depthTo = [&](long double x) -> long double {
      if (tf.Semantics == RefSemantics::GPU)
      {
        const long double a = a0 + (a1 - a0) * ((x - x0) / (x1 - x0));
        return L * invU * MinusLogIntegral(1.0L - a0, 1.0L - a, x - x0);
      }
      return L * (x - x0) * 0.5L * (tau(x0) + tau(x));
    };
    auto color = [&](int ch, long double x) {
      const std::vector<long double>& v = ch == 0 ? r : (ch == 1 ? g : bl);
      return PwlAt(tf.ColorX, v, sOf(x), hint);
    };
    const long double pieceDepth = depthTo(x1);
    if (!std::isfinite(static_cast<double>(pieceDepth)) && a0 >= 1.0L && a1 >= 1.0L)
    {
      // Opaque interval: everything left is absorbed at its front.
      const long double t = std::exp(-depth);
      if (wm)
      {
        out.R += t * color(0, x0);
        out.G += t * color(1, x0);
        out.B += t * color(2, x0);
      }
      depth = std::numeric_limits<long double>::infinity();
      break;
    }
    // Emission integral, on sub-panels over which the depth grows by <= ~2.
    const int sub = static_cast<int>(std::min<long double>(256.0L, 1.0L + std::floor(pieceDepth / 2.0L)));
    for (int ch = 0; ch < 3; ++ch)
    {
      auto f = [&](long double x) -> long double {
        const long double dtau = tau(x);
        if (!std::isfinite(static_cast<double>(dtau)))
        {
          return 0.0L; // the a = 1 end point of an interval (measure zero)
        }
        const long double src =
          wm ? color(ch, x) * dtau * L : tf.EmissionScale * invU * color(ch, x) * L;
        return src * std::exp(-(depth + depthTo(x)));
      };
      long double sum = 0.0L;
      for (int j = 0; j < sub; ++j)
      {
        const long double u0 = x0 + (x1 - x0) * j / sub;
        const long double u1 = j + 1 == sub ? x1 : x0 + (x1 - x0) * (j + 1) / sub;
        if (u1 > u0)
        {
          sum += integrator.integrate(f, u0, u1, quadTol);
        }
      }
      (ch == 0 ? out.R : (ch == 1 ? out.G : out.B)) += sum;
    }
    depth += pieceDepth;
  }
  out.A = std::isfinite(static_cast<double>(depth)) ? -std::expm1(-depth) : 1.0L;
  return out;
}

// ---------------------------------------------------------------------------
// Random inputs (fixed seeds everywhere)
// ---------------------------------------------------------------------------

/// Log-uniform in [lo, hi] (both > 0).
inline double LogUniform(std::mt19937_64& rng, double lo, double hi)
{
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

inline double Uniform(std::mt19937_64& rng, double lo, double hi)
{
  std::uniform_real_distribution<double> u(lo, hi);
  return u(rng);
}

/// Full-precision printing of a double for failure messages.
inline std::string Str(double v)
{
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}
}

#endif
