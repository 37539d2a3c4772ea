/**
 * @file hovSpecialFunctions.h
 * @brief Thin wrappers over libcerf (Faddeeva package) for the real functions
 * the exact segment integral needs.
 *
 * - Erfcx(x) = exp(x^2) erfc(x), the scaled complementary error function:
 *   finite and smooth for every real x, ~1/(sqrt(pi) x) for large x, so no
 *   overflow where exp(x^2) alone would overflow.
 * - Dawson(x) = exp(-x^2) * integral_0^x exp(t^2) dt: ~1/(2x) for large x.
 *
 * libcerf is accurate to a few ulp over the whole real line (Johnson's Faddeeva
 * package). No special function is hand-written in this module.
 *
 * Thread safety: re-entrant.
 */
#ifndef hovSpecialFunctions_h
#define hovSpecialFunctions_h

#include "hovConfig.h"

namespace hov
{
HOV_EXPORT double Erfcx(double x);
HOV_EXPORT double Dawson(double x);
}

#endif
