/**
 * @file hovEnclosure.h
 * @brief Rigorous range enclosure of a Lagrange cell's field along a ray
 * segment inside the cell, for affine AND curved geometry: a chain of
 * first-order Taylor models g(t) in Q_k(t) +- E_k, Q_k polynomials in
 * Bernstein form, E_k proven remainders.
 *
 * The field along the ray is g(t) = f(r(t)), r(t) the parametric point with
 * x(r(t)) = o + t d. On a piece T = [ta, tb] (midpoint tm, half-width h):
 *  1. rm = r(tm) by Newton (InvertLagrangeGeometry), residual
 *     rho = x(rm) - o - tm d, J = dx/dpc(rm), Y = J^-1 (floating point),
 *     v = Y d (the parametric direction of the ray);
 *  2. displacement bound: with |d2x_a/dr_b dr_c| <= M_abc on the box
 *     B = [-delta, 1+delta]^3 (CellDerivativeBounds, rigorous: maxima of the
 *     Bernstein nets of the second derivatives over B) and E0 = I - Y J,
 *     Taylor's theorem on the segment rm -> r(t) (in the convex domain)
 *     gives r(t) - rm = Y (d tau - rho - q) + E0 (r(t) - rm), |q_a| <=
 *     1/2 sum_bc M_abc |r - rm|_b |r - rm|_c. With s = |r(t) - rm|_inf this
 *     reads (1 - |E0|) s <= A + B s^2 (A = | |Y| (|d| h + |rho|) |_inf,
 *     B = |Y|_inf max_a sum_bc M_abc / 2); s is continuous in t and 0 at tm,
 *     so while (1 - |E0|)^2 > 4 A B it stays below the small root of the
 *     quadratic (a continuation argument: no Krawczyk box needed, since the
 *     segment is known to lie in the cell); refined componentwise to k >=
 *     |r(t) - rm| by three monotone iterations of
 *     k <- |v| h + |Y| (|rho| + q(k)) + |E0| k;
 *  3. linear model: r(t) = rm + v tau + e(t), tau = t - tm,
 *     |e| <= eps_r = |Y| (|rho| + q(k)) + |E0| k = O(h^2);
 *  4. field: Q(tau) = f(rm + v tau) is a polynomial (the field along a
 *     parametric LINE, exact, hovLagrangeRestriction.h) and
 *     |g(t) - Q(tau)| <= sum_b G_b eps_r,b =: E, G_b = |df/dr_b(rm)| +
 *     sum_c H_bc (k_c + eps_r,c) with |d2f/dr_b dr_c| <= H_bc on B (mean
 *     value theorem; eps_r < delta keeps the mean value point in B).
 * E is O(h^2) (O(h^3) relative to the variation of g on the piece), so
 * pieces are bisected until E <= RemainderTolerance x (field scale) or
 * MaxPieces is reached. For affine geometry M = 0: one piece, E at
 * rounding level. The enclosure of a piece is the Bernstein hull of Q on
 * RangeSubdivisions sub-intervals, widened by E and by Q's coefficient
 * rounding bound.
 *
 * What is guaranteed: if the cell is valid (x injective with det J != 0 on
 * the domain, so r(t) is continuous) and the segment lies in it (r(t) in
 * the domain, as for intervals from RayCurvedCellIntervals, up to their
 * ~1e-12 accuracy, which the margin delta covers), then f(r(t)) lies in
 * [Lo, Hi] for every t in [t0, t1], in exact arithmetic. Floating point: the
 * Bernstein coefficients of Q carry their computed rounding bound; the
 * O(1) bound arithmetic (a few dozen operations on positive numbers) is
 * inflated by a relative 1e-12; the derivative bounds by a relative 1e-9
 * (their equispaced-to-Bernstein conversion amplifies rounding by <= ~4e3).
 * A piece whose displacement bound fails at the resolution limit gets the
 * field's hull over B (still rigorous, loose; counted in LoosePieces).
 *
 * Measured (TestEnclosure, GCC 12 Release): dense samples of g (301 per
 * segment, 144 segments through curved and affine cells of every type,
 * orders 1..6) always inside, and inside every piece's Q +- E (largest
 * actual/E 0.79: the remainder bound is within a factor ~1.3 of the truth);
 * overestimate of the range width 0.28% at RemainderTolerance 1e-8 and
 * RangeSubdivisions 16 (~120 pieces per curved segment at that tolerance);
 * affine cells: 1 piece; remainder ratio E(h)/E(h/2) 6.8, 5.9, 5.1, 4.5,
 * 4.3, 4.1 for h = 1 .. 1/32 of a chord (second order).
 *
 * Thread safety: re-entrant; the optional pieces vector is the only allocation.
 * @sa hovBernstein.h, hovLagrangeRestriction.h, hovCurvedSegment.h
 */
#ifndef hovEnclosure_h
#define hovEnclosure_h

#include "hovBernstein.h"
#include "hovConfig.h"
#include "hovLagrangeCell.h"

#include <vector> // pieces output

namespace hov
{
/// Rigorous bounds of second derivatives over the parametric domain widened by Margin.
struct CellDerivativeBounds
{
  double Margin = 0.05;
  double Geometry[3][3][3] = {}; ///< >= sup |d2 x_a / dr_b dr_c|
  double Field[3][3] = {};       ///< >= sup |d2 f / dr_b dr_c| (0 if no scalars)
  double FieldMin = 0.0, FieldMax = 0.0; ///< hull of f over the box
  double FieldScale = 0.0;       ///< range of the node scalars (or max |f_i| if 0)
  bool Valid = false;
};

/**
 * Bounds of @p cell (geometry, and the field if cell.Scalars is set) over
 * the parametric domain widened by @p margin (max norm), from the tensor
 * Bernstein nets of x and f over sub-boxes of [-margin, 1+margin]^3 (one
 * for hexahedra; 2 x 2 (x 2) for wedges (tetrahedra), skipping those that
 * miss the widened domain, since the polynomials grow fast outside a
 * simplex); each net from samples at the equispaced grid of the cell's
 * degrees per direction (exact for these polynomials). Cost ~ (number of
 * boxes) (p+1)^3 node sums; once per cell.
 */
HOV_EXPORT bool ComputeCellDerivativeBounds(
  const LagrangeCellView& cell, CellDerivativeBounds& out, double margin = 0.05);

/// One Taylor model: g(t) in Q((t - T0) / (T1 - T0)) +- Remainder on [T0, T1].
struct EnclosurePiece
{
  double T0 = 0.0, T1 = 0.0;
  BernsteinPolynomial Q;
  double Remainder = 0.0;
  bool Loose = false; ///< no bound: Q meaningless, enclosure = the field's hull over B
};

struct EnclosureSettings
{
  /// Target of each piece's remainder, relative to the field scale.
  double RemainderTolerance = 1e-6;
  int MaxPieces = 256;
  /// Bernstein sub-intervals per piece for its hull (tightness ~1/n^2).
  int RangeSubdivisions = 4;
};

struct FieldEnclosure
{
  double Lo = 0.0, Hi = 0.0;
  double MaxRemainder = 0.0;
  int Pieces = 0;
  int LoosePieces = 0;
  int NewtonFailures = 0;
  bool Valid = false; ///< false for invalid input (no scalars, bad bounds, t1 < t0)
};

/**
 * Enclosure of the field on the ray segment o + t d, t in [@p t0, @p t1],
 * inside @p cell (see file doc). @p pcGuess (may be null) is a parametric
 * point near the segment (e.g. the interval's entry coordinates). If
 * @p pieces is given it receives the Taylor models, ordered in t.
 */
HOV_EXPORT FieldEnclosure EncloseFieldOnSegment(const LagrangeCellView& cell,
  const CellDerivativeBounds& bounds, const double origin[3], const double direction[3],
  double t0, double t1, const double* pcGuess,
  const EnclosureSettings& settings = EnclosureSettings(),
  std::vector<EnclosurePiece>* pieces = nullptr);
}

#endif
