/**
 * @file hovSegmentIntegral.h
 * @brief Exact emission-absorption integral over a ray segment on which the
 * extinction and the colour vary linearly (HIAC eq. 8, Williams & Max 1992).
 *
 * Parametrise the segment by x in [0,1] from its front (eye side) to its back,
 * length L. Extinction tau(x) = tauFront (1-x) + tauBack x. The optical depth
 * from the front is D(x) = a x + b x^2 with a = tauFront L, b = (tauBack -
 * tauFront) L / 2, and T(x) = exp(-D(x)). The segment's premultiplied colour
 * and opacity are
 *
 *  - Williams-Max (emission = chromaticity c(x) times tau(x)):
 *      C = integral_0^1 c(x) tau(x) L T(x) dx = WFront cFront + WBack cBack,
 *      WFront = 1 - K0, WBack = K0 - T(1), K0 = integral_0^1 T(x) dx
 *    (integration by parts: tau L T = -T').
 *  - Wilhelms-Van Gelder (emission g(x) per unit length, independent of tau):
 *      C = L integral_0^1 g(x) T(x) dx = L (VFront gFront + VBack gBack),
 *      VBack = K1 = integral_0^1 x T(x) dx, VFront = K0 - K1.
 *  - Opacity A = 1 - T(1) = -expm1(-(a + tauBack L)/2 ... ) for both.
 *
 * K0 in closed form (completing the square): with s = sqrt(|b|),
 *   b > 0: K0 = sqrt(pi)/(2 s) (erfcx(a/2s) - T(1) erfcx(c/2s)),
 *   b < 0: K0 = (F(a/2s) - T(1) F(c/2s)) / s, F = Dawson's integral,
 * with c = tauBack L >= 0. Both terms are non-negative and bounded (erfcx <= 1,
 * F <= 0.55), so nothing overflows; and K1 = (A - a K0) / (2 b).
 *
 * Branches (each threshold is explained where it is defined in the .cxx):
 *  - thin segments, D(1) <= 1/4: every weight from its Taylor series in D
 *    written in a Bernstein basis whose terms are all positive (evaluated by
 *    Horner's rule in r = a/D(1)); relative accuracy a few ulp where the
 *    closed form would cancel (1 - K0 for small depth);
 *  - |b| < 1/16 (near-constant extinction) or a^2 >= 400 |b| (steep decay),
 *    Wilhelms-Van Gelder only: K1 from its series in b over the moments
 *    M_k(a) = integral_0^1 x^k e^{-a x} dx, where (A - a K0)/(2b) would cancel;
 *  - otherwise the closed forms above.
 *  - infinite extinction (an opaque medium, e.g. opacity 1 in GPU-compatible
 *    semantics) anywhere on the segment: A = 1, C = cFront (Williams-Max) or 0
 *    (Wilhelms-Van Gelder). No Inf or NaN is ever returned for finite colours.
 *
 * The approximate method of HIAC (section 4) keeps the exact opacity of the
 * linear extinction but uses the average of the front and back colours.
 *
 * Thread safety: re-entrant; no state.
 * @sa hovRayIntegrator.h, hovCompositing.h
 */
#ifndef hovSegmentIntegral_h
#define hovSegmentIntegral_h

#include "hovCompositing.h"
#include "hovConfig.h"

namespace hov
{
/// How glow energy relates to extinction (HIAC section 5).
enum class EmissionModel
{
  WilliamsMax = 0,       ///< g = c tau: the colour is a chromaticity (what VTK does).
  WilhelmsVanGelder = 1  ///< g is its own quantity: emitted radiance per unit length.
};

/// How a linear segment is integrated.
enum class SegmentMethod
{
  Exact = 0,      ///< Closed form (Williams-Max / HIAC eq. 8).
  Approximate = 1 ///< HIAC's fast method: exact opacity, averaged colour.
};

/// Weights of the exact integral for linear extinction (see file doc).
struct SegmentWeights
{
  double Alpha = 0.0;         ///< 1 - T(1)
  double Transmittance = 1.0; ///< T(1)
  double WFront = 0.0;        ///< Williams-Max weight of the front colour
  double WBack = 0.0;         ///< Williams-Max weight of the back colour
  double VFront = 1.0 / 2.0;  ///< Wilhelms-Van Gelder weight of the front emission (times L)
  double VBack = 1.0 / 2.0;   ///< Wilhelms-Van Gelder weight of the back emission (times L)
};

/// One end of a segment: extinction per unit length and colour (chromaticity
/// for Williams-Max, emission per unit length for Wilhelms-Van Gelder).
struct SegmentEnd
{
  double Tau = 0.0;
  double Color[3] = { 0.0, 0.0, 0.0 };
};

/**
 * Exact weights for optical depth rates @p depthFront = tauFront L and
 * @p depthBack = tauBack L (both >= 0 and finite). @p withEmissionWeights
 * also computes VFront/VBack (only Wilhelms-Van Gelder needs them).
 */
HOV_EXPORT SegmentWeights ExactSegmentWeights(
  double depthFront, double depthBack, bool withEmissionWeights);

/**
 * Premultiplied RGBA of a segment of length @p length (>= 0) whose extinction
 * and colour vary linearly from @p front to @p back.
 */
HOV_EXPORT RGBA IntegrateSegment(double length, const SegmentEnd& front, const SegmentEnd& back,
  EmissionModel emission, SegmentMethod method);
}

#endif
