/**
 * @file hovPolynomialSegment.h
 * @brief Emission-absorption integral over a ray segment on which the scalar
 * is a polynomial s(t) of degree <= 8 (quadratic tetrahedra, HIAC section
 * 5.2; trilinear hexahedra and other straight-edged higher-order cells), and
 * the ordered isovalue crossings of s(t).
 *
 * Domain: t in [0, L], t = 0 at the segment's front (eye side); s given in
 * the monomial basis in t (hovPolynomial.h), finite coefficients; the table
 * of hovTransferFunction.h (colour and extinction linear in s between nodes).
 *
 * Splitting (HIAC 5.2, generalised): the extrema of s (roots of s', by
 * FindRoots) cut [0, L] into runs where s is monotone; on each run every table
 * node between the run's end values is crossed exactly once, at the root of
 * s(t) = X_k found by SolveMonotone (bracketed, full precision). Each piece
 * [tA, tB] is monotone and inside one table interval, so with
 * u(y) = (s(tA + h y) - sA) / (sB - sA), y in [0,1], h = tB - tA,
 *   tau = tauA + (tauB - tauA) u,   colour = cA + (cB - cA) u
 * are polynomials and the optical depth
 *   D(y) = h tauA y + h (tauB - tauA) int_0^y u
 * is EXACT (polynomial antiderivative; rounding only; but see the sampled
 * route below). The piece's opacity is
 * A = 1 - exp(-D(1)) (expm1), as in hovSegmentIntegral.
 *
 * Colour, same emission semantics as hovSegmentIntegral.h:
 *  - Williams-Max, C = int c tau e^-D = cA A + (cB - cA) W,
 *      W = int_0^1 u'(y) (e^{-D(y)} - e^{-D(1)}) dy   (integration by parts;
 *    for a linear s this is the closed form's WBack). One scalar quadrature;
 *    none at all if the colour is constant on the piece (then C = cA A).
 *  - Wilhelms-Van Gelder, C = int g e^-D = h (gA V0 + gB V1),
 *      V0 = int_0^1 (1 - u) e^{-D},  V1 = int_0^1 u e^{-D}.
 * The quadrature is Gauss-Kronrod per panel: first the 3-7 pair (7-point
 * Kronrod value, exact for degree 11, estimate |K7 - G3|); if that estimate
 * misses the panel's budget, the 7-15 pair (15-point Kronrod value, exact for
 * degree 29, estimate |K15 - G7|) and bisection as below. HIAC used 5-point
 * Gauss. The estimates are pessimistic: for these analytic integrands the
 * Kronrod value is typically many orders more accurate than the Gauss one.
 * On rendered pixels' thin pieces the 3-7 pair is accepted on > 99.9% of the
 * panels (zoo and tjunction datasets), halving the exponentials.
 * Initial panels end where D reaches 1, 2, 4, ..., 32 so that e^{-D} varies by
 * a bounded factor per panel; beyond D = DepthCut = 64 the rest of the piece
 * contributes < e^-64 ~ 1.6e-28 (times max colour) and is not integrated (its
 * bound is added to the error estimate). A panel is bisected until
 *   (transmittance in front of the piece) * (colour factor) * |K - G|
 *     <= Tolerance * (panel length) / L,
 * colour factor max|cB - cA| (Williams-Max) or h max(|gA|,|gB|) (WVG), so the
 * composited segment's colour error estimate is <= Tolerance (default 1e-9
 * absolute per channel) unless the panel budget (MaxPanels) or the bisection
 * depth (MaxBisectionDepth = 40) runs out (then Converged = false). A panel
 * whose |K - G| is within 50 eps of the same rule applied to the sizes of
 * the integrands' terms (as QUADPACK's resabs; Williams-Max: |u'| (e^-D +
 * e^-D(1)), since the integrand u' (e^-D - e^-D(1)) cancels on thin pieces)
 * is accepted too: that much is rounding, which bisecting does not reduce,
 * so a target under it (colours far beyond [0, 1], e.g. 1e300) would only
 * spend the whole budget
 * (Converged is still false if the target was missed; ErrorEstimate says
 * what was reached).
 * ErrorEstimate is the sum over panels of those weighted estimates plus the
 * DepthCut tails; the opacity has no truncation error.
 *
 * Measured (TestPolynomialSegment*, GCC 12 Release): against an independent
 * long double reference, max colour/opacity error 2.2e-16 (quadratics with an
 * interior extremum, ~13 pieces each), 3.0e-16 (degrees 2..8, linear
 * semantics), 2.0e-7 for GPU-compatible semantics (the table's own bound
 * 2 GPUTolerance = 2e-6); the true error was <= 1.3e-3 of ErrorEstimate on
 * every exercised segment (< 1e-3 on 99.9%); composition and reversal agree
 * to 2.7e-15; a
 * quadratic segment through a 10-node table costs ~5 us (8 pieces; the
 * linear path ~0.3 us for 4 pieces), see hovBenchPolynomial.
 *
 * Many smooth nodes (the sampled route): a table refined to a tight
 * GPU-compatible tolerance has thousands of nodes, nearly all smooth
 * (TransferFunction::IsSmoothNode(): no jump, finite extinction, colour
 * linear and extinction convex across the node), and one exact piece per
 * node crossed costs a root, a composition and a quadrature each: a 48^2
 * image took 55 s (hovRobustness case 4603043616, up to 24,388 pieces per
 * segment). So when the runs make more than MaxPanels / 2 and at least
 * 4,096 pieces (nodes crossed plus runs), at most 16 of them not bounded
 * by smooth nodes (or by extrema of s), no end of a run lies within
 * Horner's rounding or NodeSnap of a node (the route evaluates s by plain
 * Horner and unrounded), and
 * Tolerance is a positive number, the segment first goes to
 * IntegrateShadedPolynomial without shading (hovShadedSegment.h). That
 * keeps every non-smooth node and every extremum of s as a breakpoint, steps
 * over evenly spaced smooth crossings (never locating them) so that 32
 * pieces remain, and integrates them by adaptive Clenshaw-Curtis panels,
 * bisected as the estimate asks, with the same Tolerance and emission
 * model, within (pieces of the exact walk) / 64 panel evaluations, accepted
 * or bisected (at most MaxPanels). It stops at the first panel that misses
 * its budget or when the evaluations run out; then the exact walk runs after
 * all, so the result is either converged (colour and opacity within the
 * estimate: Sampled = true, Pieces = Panels = the accepted panels) or the
 * exact one. An evaluation costs as much as 10-17 exact pieces, so a try
 * that fails adds about a quarter of the walk. Measured (hovBenchPolynomial
 * RefinedTable: 16,394 nodes, about 11,000 crossings per segment): at
 * tolerance 1e-9 no try converges, 4.6-6.9 ms per segment instead of
 * 4.3-4.7 (four runs on a noisy machine); at 1e-6, 89% converge, 0.40-0.46
 * ms instead of 4.2-4.5. Case 4603043616 now takes 9.8 s; TestShadedSegment
 * checks the route against the exact walk.
 *
 * Exact paths and degenerate input:
 *  - effective degree <= 1: IntegrateLinearScalar (the linear cells' exact
 *    path; bitwise the same result); zero or negative or non-finite length,
 *    an empty table or non-finite coefficients: transparent, 0 pieces;
 *  - a piece on which the table's values are equal at both ends, or with
 *    infinite extinction at an end (opaque medium): IntegrateSegment on the
 *    end values (exact; opaque gives A = 1, C = cFront or 0, never NaN);
 *  - depth rates h tau are capped at 1e300 (e^-D is 0 long before);
 *  - a polynomial of effective degree 9 is rejected (transparent, Converged
 *    false): its depth would not fit the fixed storage.
 * Compositing: pieces front to back with CompositeBehind(); integration stops
 * when the accumulated opacity reaches 1.
 *
 * Thread safety: re-entrant (the table is read only); no heap allocation in
 * IntegratePolynomialScalar except on the sampled route (its breakpoint
 * lists).
 * @sa hovPolynomial.h, hovRayIntegrator.h, hovSegmentIntegral.h
 */
#ifndef hovPolynomialSegment_h
#define hovPolynomialSegment_h

#include "hovCompositing.h"
#include "hovConfig.h"
#include "hovPolynomial.h"
#include "hovSegmentIntegral.h" // EmissionModel

#include <vector> // IsovalueCrossings output

namespace hov
{
class TransferFunction;

struct PolynomialSegmentSettings
{
  EmissionModel Emission = EmissionModel::WilliamsMax;
  /// Absolute error target per colour channel of the segment's premultiplied RGBA.
  double Tolerance = 1e-9;
  /// Quadrature panels allowed per segment before giving up on the tolerance.
  int MaxPanels = 4096;
};

struct PolynomialSegmentResult
{
  RGBA Color;                 ///< premultiplied, front-to-back composited
  double ErrorEstimate = 0.0; ///< estimated bound on the colour error (max channel)
  int Pieces = 0;             ///< monotone one-interval pieces integrated (Sampled: panels)
  int Panels = 0;             ///< quadrature panels (0 on exact paths)
  bool Converged = true;      ///< false if the tolerance could not be met
  bool Sampled = false;       ///< the sampled route past many smooth nodes (file doc)
};

/// Integral over [0, @p length] of the table @p tf along s(t) (see file doc).
HOV_EXPORT PolynomialSegmentResult IntegratePolynomialScalar(const TransferFunction& tf,
  const Polynomial& s, double length, const PolynomialSegmentSettings& settings);

/// One isovalue crossing: where, which isovalue, and how s passes it.
struct IsovalueCrossing
{
  double T = 0.0;
  int Index = 0;     ///< into the isovalue array
  int Direction = 0; ///< +1 s increasing through it, -1 decreasing, 0 touching
};

/**
 * Every t in [0, @p length] where s(t) equals one of the @p count isovalues
 * (FindRoots; a tangency is reported once with Direction 0), sorted by t then
 * by index, into @p out (cleared first). Direction compares the sign of
 * s - iso just before and after the crossing (at the midpoints to the
 * neighbouring roots or ends); at an end of the segment only the inner side
 * is known and gives the direction. A constant s reports nothing. Returns
 * the number of crossings.
 */
HOV_EXPORT int IsovalueCrossings(const Polynomial& s, double length, const double* isovalues,
  int count, std::vector<IsovalueCrossing>& out);
}

#endif
