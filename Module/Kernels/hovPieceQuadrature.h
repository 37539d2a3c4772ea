/**
 * @file hovPieceQuadrature.h
 * @brief The adaptive quadrature of one smooth piece of a ray segment, shared
 * by the one-field (hovPolynomialSegment.h) and the two-field
 * (hovTwoFieldSegment.h) polynomial segment integrals. Internal (namespace
 * hov::detail): callers use those two headers.
 *
 * A piece has length h, normalised coordinate y in [0,1]; the extinction is
 *   tau(y) = tauA + (tauB - tauA) uD(y)
 * and the colour (chromaticity or emission) is
 *   c(y) = cA + (cB - cA) uC(y),
 * with uD, uC polynomials (degree <= 8) going monotonically from 0 to 1 (the
 * normalised restriction of the extinction field and of the colour field to
 * the piece; uD = uC when one field drives both). The optical depth
 *   D(y) = h tauA y + h (tauB - tauA) int_0^y uD
 * is an exact polynomial; A = 1 - exp(-D(1)). Colour (see
 * hovPolynomialSegment.h for the derivation):
 *  - Williams-Max: C = cA A + (cB - cA) W, W = int_0^1 uC' (e^-D - e^-D(1)),
 *    integration by parts, valid for any uC with uC(0) = 0, uC(1) = 1;
 *  - Wilhelms-Van Gelder: C = h (gA V0 + gB V1), V0 = int (1 - uC) e^-D,
 *    V1 = int uC e^-D.
 * Quadrature: Gauss-Kronrod panels (the 3-7 pair first, the 7-15 pair when
 * |K7 - G3| misses the panel's budget and is above the rule's rounding),
 * initial panels at D = 1, 2, ..., 32, cut at D = 64, bisection until the
 * weighted |K15 - G7| meets the budget or is within 50 eps of the rule
 * applied to the sizes of the integrands' terms (all constants and their
 * reasons in the .cxx).
 *
 * Thread safety: re-entrant; no heap allocation.
 */
#ifndef hovPieceQuadrature_h
#define hovPieceQuadrature_h

#include "hovCompositing.h"
#include "hovConfig.h"
#include "hovPolynomial.h"
#include "hovSegmentIntegral.h" // SegmentEnd

namespace hov
{
namespace detail
{
/// One integrated piece: premultiplied RGBA and its quadrature bookkeeping.
struct PieceOutput
{
  RGBA Color;
  double Error = 0.0;     ///< colour error estimate of the piece (its own units)
  int Panels = 0;         ///< Gauss-Kronrod panels used
  bool Converged = true;  ///< false if the budget could not be met
};

/**
 * Piece of length @p h with table values @p fA (front) and @p fB (back): Tau
 * from the extinction field, Color from the colour field; @p uDepth and
 * @p uColor as in the file doc (uDepth of degree <= 8). @p transmitFront is
 * the transmittance in front of the piece, @p budgetPerLength the colour error
 * allowed per unit length of the whole segment; @p panelsLeft is decremented.
 * Requires finite fA.Tau, fB.Tau.
 */
HOV_EXPORT PieceOutput IntegrateSmoothPiece(const SegmentEnd& fA, const SegmentEnd& fB,
  const Polynomial& uDepth, const Polynomial& uColor, double h, double transmitFront,
  double budgetPerLength, bool emission, int& panelsLeft);
}
}

#endif
