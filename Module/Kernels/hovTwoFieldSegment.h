/**
 * @file hovTwoFieldSegment.h
 * @brief Emission-absorption integral over one ray segment where the
 * extinction comes from one field s1(t) and the colour from another field
 * s2(t) (HIAC section 5: "the optical density mapped to a different scalar
 * field than the color"), both polynomials in t of degree <= 8.
 *
 * Tables: the extinction is read from table @p extinction at s1 (only its Tau
 * is used), the colour from table @p color at s2 (only its Color, or its
 * Wilhelms-Van Gelder emission with that table's EmissionFactor). They may be
 * the same hov::TransferFunction object (one property queried separately for
 * colour and extinction) or two tables built from two specs. Every node of a
 * table is a breakpoint of the field that reads it (a table's colour nodes
 * also cut the extinction field's pieces; tau is linear across them, so this
 * only adds pieces).
 *
 * Splitting: [0, L] is cut at the extrema of s1 and of s2 and at every t
 * where s1 crosses a node of the extinction table or s2 a node of the colour
 * table (each field walked over its monotone runs exactly as in
 * hovPolynomialSegment.h; the two walks are merged in t). On a piece
 * [tA, tA + h] both fields are monotone and inside one interval of their
 * tables, so with uD, uC the normalised restrictions of s1, s2 to the piece
 * (0 -> 1), tau = tauA + (tauB - tauA) uD and c = cA + (cB - cA) uC are
 * polynomials in y = (t - tA)/h:
 *  - optical depth D(y) = h tauA y + h (tauB - tauA) int_0^y uD: EXACT;
 *  - Williams-Max colour cA A + (cB - cA) int_0^1 uC' (e^-D - e^-D(1)) (by
 *    parts; the colour field need not be the extinction field);
 *  - Wilhelms-Van Gelder colour h (gA int (1 - uC) e^-D + gB int uC e^-D);
 *    with the adaptive Gauss-Kronrod 7-15 quadrature and error control of
 *    hovPolynomialSegment (hovPieceQuadrature.h): ErrorEstimate <= Tolerance
 *    unless Converged is false.
 * Exact closed-form path: on a piece where tau is linear in t (s1 of degree
 * <= 1, or tauA = tauB) and the colour is linear in t (s2 of degree <= 1, or
 * cA = cB) the piece is IntegrateSegment on its end values (Williams & Max
 * closed form, no quadrature); in particular two linear fields (linear cells)
 * are integrated exactly piece by piece. Infinite extinction at a piece end
 * (opaque medium) also goes to IntegrateSegment (A = 1, C = cFront or 0).
 *
 * Consistency: with s1 = s2 and the same table the pieces, end values and
 * quadrature are those of IntegratePolynomialScalar (same object and same
 * coefficients: that function is called directly, bitwise equal; two equal
 * tables: bitwise equal for degree >= 2, 2.1e-16 for linear fields, which go
 * through IntegrateSegment per piece instead of IntegrateLinearScalar).
 *
 * Measured (TestTwoFieldSegment, GCC 12 Release): against an independent
 * long double reference with separate raw tables and fields of degree 1..4,
 * worst colour/opacity error 3.3e-16 (Williams-Max), 1.9e-16 (Wilhelms-Van
 * Gelder); two linear fields (closed form, no quadrature) 2.4e-16; constant
 * extinction with a quadratic colour against the closed form 5.6e-17.
 *
 * Degenerate input: length <= 0 or not finite, an empty table, non-finite
 * coefficients: transparent, 0 pieces; degree > 8: transparent, Converged
 * false. Compositing stops at opacity 1.
 *
 * Thread safety: re-entrant (tables read only); no heap allocation.
 * @sa hovPolynomialSegment.h, hovSegmentIntegral.h, hovTransferFunction.h
 */
#ifndef hovTwoFieldSegment_h
#define hovTwoFieldSegment_h

#include "hovConfig.h"
#include "hovPolynomial.h"
#include "hovPolynomialSegment.h" // PolynomialSegmentSettings, PolynomialSegmentResult

namespace hov
{
class TransferFunction;

/**
 * Integral over [0, @p length] of extinction @p extinction(s1(t)) and colour
 * @p color(s2(t)) (file doc). Settings and result as IntegratePolynomialScalar.
 */
HOV_EXPORT PolynomialSegmentResult IntegrateTwoFields(const TransferFunction& extinction,
  const Polynomial& s1, const TransferFunction& color, const Polynomial& s2, double length,
  const PolynomialSegmentSettings& settings);
}

#endif
